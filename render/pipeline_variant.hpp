#pragma once
// Which ray tracing pipeline a scene needs: features in, shader groups and defines out.
// A level without glass gets no any-hit shader and only opaque rays; one without mirrors gets
// no bounce loop.
#include <cstdint>
#include <string>
#include <vector>

#include "render/shader_compiler.hpp"
#include "scene/scene_desc.hpp"

namespace render {

struct PipelineFeatures {
  bool glass = false;    // some visible instance has a glass material
  bool mirrors = false;  // some visible instance has a mirror material
  uint32_t maxMirrorBounces = 0;
  bool softShadows = false;        // some light has extent: sampled visibility + denoiser
  uint32_t softShadowSamples = 1;  // shadow rays per pixel and frame for the soft lights
  // A visible mirror has flat faces, the level has a light and mirror bounces: light is routed
  // by the mirrors onto surfaces and sensors.
  bool lightRoutes = false;
  // Some material is alpha-masked (glTF alphaMode MASK): the surface hit group gets the alpha
  // test as its any-hit shader and rays stop forcing opaque hits.
  bool alphaMask = false;
  bool operator==(const PipelineFeatures&) const = default;
};

PipelineFeatures featuresOf(const scene::SceneDesc& scene);
// Everything on, for measuring what a level's own variant saves.
PipelineFeatures allFeatures(uint32_t maxMirrorBounces);

// What a variant consists of; the renderer builds exactly this.
struct PipelineDescription {
  std::vector<std::string> misses;     // shader files, in miss-index order
  std::vector<std::string> hitGroups;  // "closest.rchit" or "any.rahit", in SBT order
  ShaderDefines defines;               // passed to every ray tracing stage
  // Every traceRayEXT is issued by the ray-gen shader (bounces iterate there), so 1 is
  // enough for every variant; hit and miss shaders never trace.
  uint32_t recursionDepth = 1;
};

PipelineDescription describePipeline(const PipelineFeatures& features);

}  // namespace render
