#include "render/pipeline_variant.hpp"

#include <algorithm>

#include "scene/flat_faces.hpp"

namespace render {

PipelineFeatures featuresOf(const scene::SceneDesc& scene) {
  PipelineFeatures features;
  for (const scene::InstanceDesc& instance : scene.instances) {
    if (instance.material >= scene.materials.size()) continue;
    const scene::MaterialKind kind = scene.materials[instance.material].kind;
    features.glass = features.glass || kind == scene::MaterialKind::Glass;
    features.alphaMask =
        features.alphaMask || scene.materials[instance.material].alphaCutoff > 0.0f;
    for (const uint32_t material : instance.meshMaterials)
      features.alphaMask = features.alphaMask || (material < scene.materials.size() &&
                                                  scene.materials[material].alphaCutoff > 0.0f);
    features.mirrors = features.mirrors || kind == scene::MaterialKind::Mirror;
    if (kind == scene::MaterialKind::Mirror && instance.mesh < scene.meshes.size() &&
        !features.lightRoutes)
      features.lightRoutes = !scene::flatFaces(scene.meshes[instance.mesh]).empty();
  }
  features.maxMirrorBounces = features.mirrors ? std::min(scene.maxMirrorBounces, 31u) : 0;
  features.lightRoutes = features.lightRoutes && scene.lightViaMirrors && !scene.lights.empty() &&
                         features.maxMirrorBounces > 0;
  for (const scene::LightDesc& light : scene.lights) {
    const bool hasExtent = light.type == scene::LightType::Directional
                               ? light.angularDiameterRadians > 0.0f
                               : light.type != scene::LightType::Point;
    features.softShadows = features.softShadows || hasExtent;
  }
  return features;
}

PipelineFeatures allFeatures(uint32_t maxMirrorBounces) {
  PipelineFeatures features;
  features.glass = features.mirrors = features.softShadows = features.lightRoutes = true;
  features.maxMirrorBounces = std::min(maxMirrorBounces, 31u);
  return features;
}

PipelineDescription describePipeline(const PipelineFeatures& features) {
  PipelineDescription description;
  description.misses = {"surface.rmiss", "shadow.rmiss"};
  description.hitGroups = {features.alphaMask ? "surface.rchit+alpha.rahit" : "surface.rchit"};
  if (features.glass) {
    description.misses.push_back("glass.rmiss");
    description.hitGroups.push_back("glass.rahit");
  }
  description.defines = {
      {"HAS_GLASS", features.glass ? "1" : "0"},
      {"HAS_MIRRORS", features.mirrors ? "1" : "0"},
      {"SOFT_SHADOWS", features.softShadows ? "1" : "0"},
      {"LIGHT_ROUTES", features.lightRoutes ? "1" : "0"},
  };
  // Only levels with alpha-masked materials get the define (others keep their cache keys).
  if (features.alphaMask) description.defines.push_back({"ALPHA_MASK", "1"});
  // Only soft-shadow variants have more than one sample to choose; others keep one key.
  if (features.softShadows && features.softShadowSamples > 1)
    description.defines.push_back(
        {"SOFT_SHADOW_SAMPLES", std::to_string(std::min(features.softShadowSamples, 16u))});
  return description;
}

}  // namespace render
