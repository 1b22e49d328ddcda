#pragma once
// A CPU reference for the ray tracer: Embree 3 shoots the rays the ray-gen shader shoots, at the
// same geometry, with single-ray calls on a fixed number of threads. The benchmark divides
// lavapipe's ray rate by this one; a test compares what each pixel's path reached.
//
// Rays, per pixel, as in shaders/raygen.rgen for the pipeline variant given:
// - surface rays: the camera ray, and one more per mirror bounce (up to the variant's cap);
// - glass rays (variants with glass): one along every surface ray and one after every shadow
//   ray that no opaque caster blocks, each passing through every glass surface on the way;
// - shadow rays at the surface the path ends on (not at mirrors): one per light that reaches
//   the point (the same facing tests as the shader), aimed at the light's centre or along a
//   directional light. Soft-shadow variants trace the point lights that way and one ray for all
//   soft lights, aimed at the centre of the first one that reaches the point; the shader picks
//   that light at random (weighted by its light) and a random point on it, and skips the ray
//   when that point is below the surface. So the counts differ by a few rays in 10^4 there.
// Secondary rays start off the surface as ray_offset.glsl moves them.
// Normal maps are not applied to the reflection normal (no shipped mirror has one).
#include <cstdint>
#include <memory>
#include <vector>

#include "render/pipeline_variant.hpp"
#include "scene/probes.hpp"
#include "scene/scene_desc.hpp"

namespace reference {

// What a pixel's path ended on, as render::gpu::PixelPath::finalInstance.
constexpr uint32_t kReachedNothing = 0xFFFFFFFFu;

struct ReferenceFrame {
  uint32_t width = 0, height = 0;
  uint64_t surfaceRays = 0;              // camera rays and mirror bounces (FrameStats::surfaceRays)
  uint64_t secondaryRays = 0;            // shadow and glass rays (FrameStats::secondaryRays)
  double milliseconds = 0.0;             // wall time of the trace, all threads (no BVH build)
  std::vector<uint32_t> finalInstances;  // per pixel, rows top to bottom

  uint64_t rays() const { return surfaceRays + secondaryRays; }
};

class EmbreeTracer {
 public:
  // Builds the BVHs (one per mesh and use, instanced like the renderer's BLAS and TLAS).
  // `features` is the pipeline variant whose rays to shoot (render::featuresOf(scene) for the
  // level's own).
  EmbreeTracer(const scene::SceneDesc& scene, const render::PipelineFeatures& features,
               uint32_t threads = 2);
  ~EmbreeTracer();
  EmbreeTracer(const EmbreeTracer&) = delete;
  EmbreeTracer& operator=(const EmbreeTracer&) = delete;

  // Traces one frame from `camera` at width x height; rows are dealt to the threads one at a
  // time. Coordinates are camera-relative (world minus camera, like the renderer's render
  // space); a camera that moved re-places the instances first, outside the timed trace.
  ReferenceFrame traceFrame(const scene::CameraDesc& camera, uint32_t width, uint32_t height);

  double buildMilliseconds() const { return buildMilliseconds_; }
  uint32_t threads() const { return threads_; }

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
  uint32_t threads_ = 2;
  double buildMilliseconds_ = 0.0;
};

// Pixels of `box` whose path ended on `instance`, as the ray-gen shader counts a focus probe.
uint32_t countFocusPixels(const ReferenceFrame& frame, uint32_t instance,
                          const scene::PixelBox& box);

}  // namespace reference
