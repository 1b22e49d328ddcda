#include <algorithm>

#include "game/level.hpp"
#include "scene/flat_faces.hpp"

namespace game {

LevelFeatures levelFeatures(const Level& level) {
  LevelFeatures features;
  features.instances = level.entities.size();
  features.lights = level.lights.size();
  features.textures = !level.textures.empty();
  for (const Entity& entity : level.entities) {
    features.triangles += level.meshes[entity.mesh].indices.size() / 3;
    const scene::MaterialKind kind = level.materials[entity.material].kind;
    features.glass = features.glass || kind == scene::MaterialKind::Glass;
    features.mirrors = features.mirrors || kind == scene::MaterialKind::Mirror;
    if (kind == scene::MaterialKind::Mirror && !features.lightViaMirrors)
      features.lightViaMirrors = !scene::flatFaces(level.meshes[entity.mesh]).empty();
    features.movers = features.movers || entity.mover.has_value();
    features.interactables = features.interactables || entity.interactable.has_value();
  }
  features.mirrorBounces = features.mirrors ? std::min(level.maxMirrorBounces, 31u) : 0;
  features.lightViaMirrors = features.lightViaMirrors && level.lightViaMirrors &&
                             !level.lights.empty() && features.mirrorBounces > 0;
  for (const scene::LightDesc& light : level.lights) {
    const bool hasExtent = light.type == scene::LightType::Directional
                               ? light.angularDiameterRadians > 0.0f
                               : light.type != scene::LightType::Point;
    features.areaLights = features.areaLights || hasExtent;
  }
  return features;
}

}  // namespace game
