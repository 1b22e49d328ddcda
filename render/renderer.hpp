#pragma once
// Draws a SceneDesc with the ray tracing pipeline: trace -> tonemap -> (optional) readback.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include <array>
#include <optional>
#include "render/acceleration_structure.hpp"

#include "render/buffer.hpp"
#include "render/denoiser.hpp"
#include "render/gpu_types.hpp"
#include "render/light_routes.hpp"
#include "render/pipeline_variant.hpp"
#include "render/temporal_upscaler.hpp"
#include "scene/flat_faces.hpp"
#include "scene/probes.hpp"
#include "scene/scene_desc.hpp"

namespace render {

class Context;
class ShaderCompiler;
class StorageImage;
class RayTracingPipeline;
class Texture;

struct RendererOptions {
  uint32_t width = 320;
  uint32_t height = 180;
  // Launch rows are dealt to image rows in this many interleaved groups (1 = off), so a CPU
  // driver's contiguous per-thread blocks each get a share of every part of the image.
  // 0: 8 on CPU drivers, 1 on GPUs.
  uint32_t rowGroups = 0;
  // Build the all-features pipeline instead of the scene's own variant (for measuring it).
  bool allFeatures = false;
  // Sum the ray and focus-pixel counters per subgroup before the atomics where the device can
  // (false: one atomic per pixel everywhere, for measuring the difference).
  bool subgroupCounters = true;
  uint32_t denoiserIterations = 3;  // a-trous iterations after the temporal pass (0..5)
  // How the denoiser's temporal pass reads each pixel's 5x5 neighbourhood of samples: from a
  // work-group tile in shared memory (Tile) or from the image (PerPixel). The results are the
  // same; Auto takes the tile on GPUs and the image reads on CPU drivers (faster there).
  NeighbourhoodReads neighbourhoodReads = NeighbourhoodReads::Auto;
  // Which channels of visibility the temporal pass's statistics keep: Auto one in a level
  // without glass (its visibility is grey), where the results are the same as with Rgb's three.
  VisibilityChannels visibilityChannels = VisibilityChannels::Auto;
  // The denoiser's temporal pass compiled for a still view (the camera, picture size and
  // instances as in the last full frame), which reads each pixel's own history. The results are
  // the same as the general pass's; false runs the general pass on every frame (to compare).
  bool stillViewDenoiser = true;
  // In a still view of a steady scene (Renderer::steadyFrames() counting; after a change of an
  // instance or a light, from the 64th steady frame on), a pixel in a penumbra
  // traces DENOISER_PENUMBRA_FRAMES frames' worth of soft shadow samples until its history holds
  // DENOISER_PENUMBRA_HISTORY frames' worth, and a history grows to DENOISER_STEADY_MAX_HISTORY
  // (shared_types.h); false: one frame's worth into a history of DENOISER_MAX_HISTORY, as in
  // any other view. Needs stillViewDenoiser.
  bool steadyPenumbraSamples = true;
  // Under a camera held still, the upscaler's resolve takes a pixel whose four samples show
  // nothing that moved as held where it was, without reading their motions (on levels whose
  // movers never rest, most of the picture). The pictures are the same as the general path's;
  // false takes the general path everywhere (to compare).
  bool heldPointResolve = true;
  // Shadow rays per pixel and frame towards the soft lights (1..16; CPU drivers: 1).
  uint32_t softShadowSamples = 1;
  // Route light by flat mirrors onto surfaces and sensors where the scene can (false: direct
  // light only, as the Embree reference traces it).
  bool lightRoutes = true;
  // Temporal upscaling to this size (0: none, the picture is the render size): jittered camera
  // rays accumulated into a history at the output size, which outputImage() then holds. The
  // render size again gives plain temporal anti-aliasing. Probe frames are never jittered.
  uint32_t outputWidth = 0;
  uint32_t outputHeight = 0;
  // How the upscaler's resolve writes its results (the same either way; Auto: colour
  // attachments on CPU drivers, image stores on GPUs).
  ResolveWrites resolveWrites = ResolveWrites::Auto;
  // Called after each `waitSlice` that the host waits for a frame, probe frames and those of
  // runEachPicturePipelineOnce included (on a CPU driver, a level's first frames compile their
  // pipelines for seconds): a window answers its events there (waitForFence).
  std::function<void()> whileWaiting;
  std::chrono::milliseconds waitSlice{100};
};

// GPU time of each pass from timestamp queries (0 where the device has no timestamps).
struct PassTimes {
  double traceMs = 0.0;    // TLAS update and ray tracing
  double denoiseMs = 0.0;  // temporal and a-trous passes (0 without soft shadows)
  double tonemapMs = 0.0;  // composite, tonemap, sRGB encode, temporal upscale
  double readbackMs = 0.0;
  double totalMs() const { return traceMs + denoiseMs + tonemapMs + readbackMs; }
};

struct FrameStats {
  PassTimes gpu;
  double milliseconds = 0.0;   // host time from submit to completion
  uint64_t surfaceRays = 0;    // camera rays and mirror bounces, counted by the ray-gen shader
  uint64_t secondaryRays = 0;  // shadow and glass rays
  uint64_t rays() const { return surfaceRays + secondaryRays; }
};

class Renderer {
 public:
  Renderer(const Context& context, ShaderCompiler& compiler, const scene::SceneDesc& scene,
           const RendererOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders one frame and waits for it. With `readback`, pixels() holds the result.
  FrameStats renderFrame(const scene::FrameDesc& frame, bool readback = true);
  // Renders only what the probes read and waits for it: the focus regions' pixels (what each
  // path reaches, unshaded) and the exposure probes, with the same counts a full frame gives.
  // No image changes, and the denoiser's history and motion stay those of the last full frame.
  FrameStats renderProbeFrame(const scene::FrameDesc& frame);

  // Runs each pipeline a full frame may take once, on a picture of a few pixels, and leaves the
  // renderer as it was: the next full frame renders what it would have. A CPU driver compiles
  // a pipeline's machine code the first time a command buffer runs it, unless Mesa's shader
  // cache holds it: lavapipe froze the first and third frames of a level played for the first
  // time for 0.8-1.4 s each (docs/PERFORMANCE.md, session 40). Play calls this while the level
  // loads. Only before the first full frame (throws RenderError otherwise). `afterEachFrame`
  // (optional) is called after each of its frames with how many are done and how many there are
  // (a loading screen's progress).
  void runEachPicturePipelineOnce(
      const scene::FrameDesc& frame,
      const std::function<void(uint32_t done, uint32_t frames)>& afterEachFrame = {});

  // New object-to-world transforms, one per scene instance; the next frame updates the TLAS,
  // unless every element is within 1e-5 (10 µm) of what it holds: so small a change is not drawn.
  void setInstanceTransforms(std::span<const glm::mat4> objectToWorld);

  // What the probes measure from the next frame on (replaces the previous request). Exposure
  // probes need a scene made with exposureProbes.
  void setProbes(const scene::ProbeRequest& request);
  // The probes' results of the last frame rendered.
  const scene::ProbeCounts& probeCounts() const { return probeCounts_; }

  // Turns a light on or off from the next frame (switches).
  void setLightEnabled(uint32_t light, bool enabled);
  // A hidden instance is seen by no ray (camera, shadow, glass, mirror or probe).
  void setInstanceVisible(uint32_t instance, bool visible);
  // Extra emitted light, `glow` times the surface's albedo (0: none), for feedback in the world.
  void setInstanceGlow(uint32_t instance, float glow);
  // Moves a light (one that rides a moving entity): world position and, for directional,
  // rectangle and disk lights, direction.
  void setLightPose(uint32_t light, const glm::vec3& position, const glm::vec3& direction);
  // The light's colour times `tint` (white: as the level made it).
  void setLightTint(uint32_t light, const glm::vec3& tint);

  // RGBA8, sRGB-encoded, rows top to bottom, of the last frame rendered with readback, at the
  // shown size (shownWidth() x shownHeight()).
  const std::vector<uint8_t>& pixels() const { return pixels_; }
  // The last frame's display image at the output size (R8G8B8A8_UNORM holding sRGB-encoded
  // bytes, usable as a transfer source and sampled, as the presenter does, in
  // VK_IMAGE_LAYOUT_GENERAL). After renderFrame it is in GENERAL; a user that changes the layout
  // must put it back to GENERAL before the next frame.
  VkImage outputImage() const;
  VkImageView outputView() const;  // of outputImage(), which can also be sampled
  // The last frame's linear radiance before exposure and tonemap, without the soft lights'
  // share, in rgb; alpha 0 where temporal upscaling's sample shows something that moved, else 1
  // (test and debugging hook; waits).
  std::vector<glm::vec4> readRadiance() const;
  // Soft-shadow denoiser images of the last frame (test and debugging hook; waits).
  std::vector<glm::vec4> readDenoiser(DenoiserImage which) const;
  // Replaces the history the next frame reprojects (test hook: long histories, NaN).
  void fillDenoiserHistory(const glm::vec4& history, const glm::vec4& moments);
  // The same for the one pixel (x, y) (test hook: a NaN or infinity in one place).
  void writeDenoiserHistoryTexel(uint32_t x, uint32_t y, const glm::vec4& history,
                                 const glm::vec4& moments);
  bool softShadows() const { return denoiser_ != nullptr; }

  // The light routes via mirrors the last frame used (empty without the LIGHT_ROUTES variant).
  const std::vector<gpu::GpuLightRoute>& lightRoutes() const { return routes_; }

  // What each pixel's path reached in the last frame (rows top to bottom).
  std::vector<gpu::PixelPath> pixelPaths() const;
  const PipelineDescription& pipelineDescription() const { return pipelineDescription_; }
  uint32_t width() const { return options_.width; }  // the render size: rays, probes
  uint32_t height() const { return options_.height; }
  // Full frames from the next one trace only the top-left width x height of the render size
  // (a render scale that changes while playing): the camera keeps its field of view and aspect,
  // with fewer pixels. Probe frames keep the whole render size, so what the probes read does not
  // depend on it. The denoiser's and the upscaler's histories carry across a change.
  void setPictureSize(uint32_t width, uint32_t height);
  uint32_t pictureWidth() const { return pictureWidth_; }
  uint32_t pictureHeight() const { return pictureHeight_; }
  // Full frames in a row, the last one included, that showed the same scene as the one before:
  // the same camera, picture size and exposure, no reset, and no instance or light changed (0:
  // the last full frame changed something). From UPSCALE_STEADY_FRAMES_UNCLAMPED on, the
  // upscaler resolves with its steady view's pipeline.
  uint32_t steadyFrames() const { return steadyFrames_; }
  // How many frames updated the TLAS (new transforms, render origin or visibility) since the
  // renderer was made.
  uint64_t tlasUpdates() const { return tlasUpdates_; }
  // The size of outputImage(): the output size with temporal upscaling, else the render size.
  uint32_t outputWidth() const { return upscaler_ ? upscaler_->outputWidth() : width(); }
  uint32_t outputHeight() const { return upscaler_ ? upscaler_->outputHeight() : height(); }
  // How much of outputImage() the last full frame wrote, from its top-left corner (and the size
  // of pixels() after a readback): the output size with temporal upscaling, else that frame's
  // picture size.
  uint32_t shownWidth() const { return upscaler_ ? upscaler_->outputWidth() : shownPicture_.x; }
  uint32_t shownHeight() const { return upscaler_ ? upscaler_->outputHeight() : shownPicture_.y; }
  size_t triangleCount() const { return triangleCount_; }

 private:
  void destroyHandles();  // what the destructor does, also for a constructor that throws
  void createDescriptors();
  void createPipelines(ShaderCompiler& compiler, const PipelineFeatures& features,
                       bool exposureProbes);
  void moveRenderOrigin(const glm::dvec3& origin);
  void writeFrameUniforms(const scene::FrameDesc& frame, bool probeOnly);
  void writeInstanceMotion(bool fullFrame);
  void writeLightMotion(bool fullFrame);
  void writeProbePoints();
  void writeLightRoutes();
  uint32_t denoiserIterations(const scene::FrameDesc& frame) const;
  void recordFrame(VkCommandBuffer commands, bool readback, bool probeOnly);
  FrameStats submitFrame(const scene::FrameDesc& frame, bool readback, bool probeOnly);
  // A frame's commands into commands_.
  void recordCommands(bool readback, bool probeOnly);
  // Submits commands_ and waits for frameDone_ (waitForFence with options_.whileWaiting), then
  // resets it.
  void submitAndWaitForFrame() const;

  const Context& context_;
  RendererOptions options_;
  uint32_t pictureWidth_ = 0;  // setPictureSize's; the render size until it is called
  uint32_t pictureHeight_ = 0;
  glm::uvec2 shownPicture_{0u};  // the picture size of the last full frame recorded
  uint32_t lightCount_ = 0;
  size_t triangleCount_ = 0;
  scene::EnvironmentDesc environment_;

  Buffer vertices_;
  Buffer indices_;
  Buffer instances_;
  Buffer materials_;
  Buffer lights_;
  Buffer frameUniforms_;
  Buffer counters_;
  Buffer countersReadback_;
  Buffer paths_;
  Buffer probeSetup_;
  Buffer lightRoutes_;
  Buffer sampleNoise_;          // blue_noise.hpp's softShadowSampleNoise()
  Buffer triangleMaterials_;    // scene material per triangle of instances of several materials
  bool routeLight_ = false;     // the variant routes light by mirrors
  uint32_t mirrorBounces_ = 0;  // the most a camera path or a light route takes (the cap)
  std::vector<std::vector<scene::FlatFace>> mirrorFaces_;  // per instance, object space
  std::vector<glm::vec3> mirrorTints_;                     // per instance
  std::vector<bool> instanceVisible_;
  std::vector<float> instanceGlow_;
  std::vector<gpu::GpuLightRoute> routes_;
  scene::ProbeRequest probeRequest_;
  std::optional<scene::PixelBox> focusBox_;  // all focus regions' pixels, if there are any
  scene::ProbeCounts probeCounts_;
  PipelineDescription pipelineDescription_;
  Buffer readback_;
  std::vector<AccelerationStructure> bottomLevels_;
  std::unique_ptr<TopLevel> topLevel_;
  // The glass instances alone, which the glass rays traverse (none: they use topLevel_).
  std::unique_ptr<TopLevelSubset> glassLevel_;
  // Every instance but the player's body, which the camera rays traverse (none: the scene has no
  // body, or nothing else, and they use topLevel_). From the eye the body is never seen, but the
  // eye is inside its box, so in topLevel_ every camera ray visited the nodes over the body and
  // what lies next to it, whose mask lavapipe tests only on reaching the instance (01 First
  // Light's trace at 320x180 on lavapipe: 0.7-1.3 ms a frame; docs/PERFORMANCE.md, session 35).
  std::unique_ptr<TopLevelSubset> eyeLevel_;
  std::vector<glm::mat4> pendingTransforms_;  // world space, for the next frame
  bool tlasStale_ = false;  // the TLAS needs render-space transforms of currentTransforms_
  uint64_t tlasUpdates_ = 0;
  std::vector<gpu::GpuLight> gpuLights_;   // render space (positions relative to the origin)
  std::vector<glm::vec3> lightPositions_;  // world space
  // World space: where the lights were at the last full frame, and what the GPU's lights hold
  // as their previous positions.
  std::vector<glm::vec3> lightHistoryPositions_;
  std::vector<glm::vec3> lightPreviousPositions_;
  bool lightsMovedSinceHistory_ = false;   // a light moved since the last full frame
  bool lightsMoved_ = false;               // the last full frame's light motion was not identity
  std::vector<glm::vec3> lightRadiances_;  // as the level made them, before any tint
  std::vector<std::unique_ptr<Texture>> textures_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  Buffer radiance_;  // ray-gen's linear radiance, a vec4 a render pixel (readRadiance)
  std::unique_ptr<StorageImage> outputImage_;

  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  std::array<VkDescriptorSet, 2> descriptorSets_{};  // by frame parity (denoiser ping-pong)
  uint32_t parity_ = 0;
  uint32_t lastIterations_ = 0;
  std::unique_ptr<Denoiser> denoiser_;
  std::unique_ptr<TemporalUpscaler> upscaler_;
  uint32_t jitterIndex_ = 0;  // full frames rendered with temporal upscaling
  std::optional<gpu::FrameUniforms> previousUniforms_;  // for reprojection; none: reset
  // The world position render space is centred on: the camera of the last frame (none before
  // the first), and that of the last full frame (for reprojection and cut detection).
  std::optional<glm::dvec3> renderOrigin_;
  std::optional<glm::dvec3> historyOrigin_;
  std::vector<glm::mat4> currentTransforms_;  // world space
  std::vector<glm::mat4> historyTransforms_;  // world space, at the last full frame
  bool movedSinceHistory_ = false;            // transforms arrived since the last full frame
  bool instancesMoved_ = false;               // the last full frame's motion was not identity
  // An instance or a light changed since the last full frame (set only by a different value, or
  // a transform that strayed from currentTransforms_ by more than a tolerance).
  bool sceneChanged_ = true;
  uint32_t steadyFrames_ = 0;  // steadyFrames() of the last full frame
  // Whether no instance or light changed since the denoiser's history last started afresh: then
  // it holds nothing that a change made stale.
  bool unchangedSinceReset_ = false;
  // The last full frame's camera, picture size and instances were the full frame's before it
  // (and it was neither a reset nor a reference accumulation): the denoiser's still view.
  bool stillView_ = false;
  // The last full frame's camera and picture size were the full frame's before it, and it was no
  // reset: the upscaler's resolve takes its pipeline for a camera held still.
  bool viewHeld_ = false;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
  std::unique_ptr<RayTracingPipeline> rayTracingPipeline_;
  VkPipeline tonemapPipeline_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence frameDone_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;  // null when the queue has no timestamps
  std::vector<uint8_t> pixels_;
};

}  // namespace render
