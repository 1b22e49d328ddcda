#pragma once
// Builds render::SceneDesc in code for image tests: meshes, materials and instances by index.
#include <glm/gtc/matrix_transform.hpp>

#include "render/scene_desc.hpp"

namespace test {

struct SceneBuilder {
  render::SceneDesc scene;

  uint32_t mesh(render::MeshData data) {
    scene.meshes.push_back(std::move(data));
    return uint32_t(scene.meshes.size() - 1);
  }
  uint32_t material(const render::MaterialDesc& material) {
    scene.materials.push_back(material);
    return uint32_t(scene.materials.size() - 1);
  }
  uint32_t instance(uint32_t mesh, uint32_t material, const glm::mat4& transform,
                    bool castsShadow = true) {
    scene.instances.push_back({mesh, material, transform, castsShadow});
    return uint32_t(scene.instances.size() - 1);
  }
  void light(const render::LightDesc& light) { scene.lights.push_back(light); }
};

inline glm::mat4 at(const glm::vec3& position) {
  return glm::translate(glm::mat4(1.0f), position);
}

}  // namespace test
