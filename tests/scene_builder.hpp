#pragma once
// Builds scene::SceneDesc in code for image tests: meshes, materials and instances by index.
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_desc.hpp"

namespace test {

struct SceneBuilder {
  scene::SceneDesc scene;

  uint32_t mesh(scene::MeshData data) {
    scene.meshes.push_back(std::move(data));
    return uint32_t(scene.meshes.size() - 1);
  }
  uint32_t material(const scene::MaterialDesc& material) {
    scene.materials.push_back(material);
    return uint32_t(scene.materials.size() - 1);
  }
  uint32_t instance(uint32_t mesh, uint32_t material, const glm::mat4& transform,
                    bool castsShadow = true) {
    scene.instances.push_back({mesh, material, transform, castsShadow});
    return uint32_t(scene.instances.size() - 1);
  }
  void light(const scene::LightDesc& light) { scene.lights.push_back(light); }
};

// Glass of linear transmittance `tint` per front face.
inline scene::MaterialDesc glassMaterial(const glm::vec3& tint) {
  scene::MaterialDesc material;
  material.kind = scene::MaterialKind::Glass;
  material.glassTint = tint;
  return material;
}

// A perfect mirror of reflectance times tint `tint`.
inline scene::MaterialDesc mirrorMaterial(const glm::vec3& tint = glm::vec3(1.0f)) {
  scene::MaterialDesc material;
  material.kind = scene::MaterialKind::Mirror;
  material.mirrorTint = tint;
  return material;
}

inline glm::mat4 at(const glm::vec3& position) {
  return glm::translate(glm::mat4(1.0f), position);
}

}  // namespace test
