#include "game/player_body.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "game/primitives.hpp"

namespace game {

scene::MeshData playerBodyMesh() {
  scene::MeshData body = primitives::cylinder(PlayerBody::trunkRadius, PlayerBody::trunkHeight, 16);
  for (scene::Vertex& vertex : body.vertices) vertex.position.y += 0.5f * PlayerBody::trunkHeight;
  const scene::MeshData head = primitives::sphere(PlayerBody::headRadius, 16, 8);
  const auto firstHeadVertex = static_cast<uint32_t>(body.vertices.size());
  for (scene::Vertex vertex : head.vertices) {
    vertex.position.y += PlayerBody::headCentre;
    body.vertices.push_back(vertex);
  }
  for (uint32_t index : head.indices) body.indices.push_back(firstHeadVertex + index);
  body.name = "player body";
  return body;
}

scene::MaterialDesc playerBodyMaterial() {
  scene::MaterialDesc material;
  material.baseColor = glm::vec3(0.12f, 0.14f, 0.2f);
  material.roughness = 0.8f;
  return material;
}

glm::mat4 playerBodyTransform(const glm::vec3& feet) {
  return glm::translate(glm::mat4(1.0f), feet);
}

}  // namespace game
