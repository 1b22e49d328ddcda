#include "game/level.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "game/world.hpp"

namespace game {

glm::mat4 entityTransform(const Entity& entity) {
  const glm::vec3 radians = glm::radians(entity.rotationDegrees);
  glm::mat4 transform = glm::translate(glm::mat4(1.0f), entity.position);
  transform = glm::rotate(transform, radians.y, glm::vec3(0, 1, 0));  // yaw
  transform = glm::rotate(transform, radians.x, glm::vec3(1, 0, 0));  // pitch
  transform = glm::rotate(transform, radians.z, glm::vec3(0, 0, 1));  // roll
  return glm::scale(transform, entity.scale);
}

namespace {

std::string quotedId(const std::string& id, uint32_t index) {
  return "\"" + (id.empty() ? "#" + std::to_string(index) : id) + "\"";
}

}  // namespace

std::string quotedEntityId(const Level& level, uint32_t entity) {
  return quotedId(entity < level.entities.size() ? level.entities[entity].id : "", entity);
}

std::string quotedLightId(const Level& level, uint32_t light) {
  return quotedId(light < level.lightIds.size() ? level.lightIds[light] : "", light);
}

scene::SceneDesc buildSceneDesc(const Level& level, const World& world) {
  scene::SceneDesc scene;
  scene.meshes = level.meshes;
  scene.materials = level.materials;
  scene.textures = level.textures;
  scene.lights = world.lights();  // with enabled, radius, size and angular diameter
  scene.environment = level.environment;
  scene.maxMirrorBounces = level.maxMirrorBounces;
  scene.lightViaMirrors = level.lightViaMirrors;
  scene.instances.reserve(level.entities.size());
  for (uint32_t e = 0; e < level.entities.size(); ++e) {
    const Entity& entity = level.entities[e];
    scene::InstanceDesc instance;
    instance.mesh = entity.mesh;
    instance.material = entity.material;
    instance.meshMaterials = entity.meshMaterials;
    instance.objectToWorld = world.entityTransform(e);
    instance.castsShadow = entity.castsShadow;
    instance.shadowsDirectionalOnly = entity.shadowsDirectionalOnly;
    scene.instances.push_back(std::move(instance));
  }
  return scene;
}

scene::SceneDesc buildSceneDesc(const Level& level) {
  return buildSceneDesc(level, World(level));
}

}  // namespace game
