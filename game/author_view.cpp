#include "game/author_view.hpp"

#include <cstdio>

namespace game {

namespace {

std::string number(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", double(value));
  std::string result = text;
  return result == "-0.00" ? "0.00" : result;
}

std::string vector3(const glm::vec3& v) {
  return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

std::string interactableState(const Interactable& it, const World& world, uint32_t entity) {
  char text[96];
  switch (it.type) {
    case Interactable::Type::Rotate:
      std::snprintf(text, sizeof text, "rotate %.1f degrees of %g..%g",
                    double(world.interactableValue(entity)), double(it.min), double(it.max));
      break;
    case Interactable::Type::Slide:
      std::snprintf(text, sizeof text, "slide %.2f m of %g..%g",
                    double(world.interactableValue(entity)), double(it.min), double(it.max));
      break;
    case Interactable::Type::Switch:
      std::snprintf(text, sizeof text, "switch %s", world.switchOn(entity) ? "on" : "off");
      break;
  }
  return std::string(text) + (world.locked(entity) ? ", locked" : "");
}

}  // namespace

std::optional<CrosshairTarget> crosshairTarget(const World& world) {
  const std::optional<RayHit> hit = world.collision().rayCast(
      world.eyePosition(), world.player().viewDirection(), kAuthorViewMetres);
  if (!hit) return std::nullopt;
  return CrosshairTarget{hit->entity, hit->point, hit->distance};
}

std::vector<std::string> describeCrosshair(const Level& level, const World& world,
                                           const CrosshairTarget& target) {
  std::vector<std::string> lines;
  if (target.entity >= level.entities.size()) return lines;
  const Entity& entity = level.entities[target.entity];
  std::string materials;
  if (entity.meshMaterials.empty()) {
    materials = "material " + level.materialIds[entity.material];
  } else {
    materials = "materials";
    for (uint32_t material : entity.meshMaterials) materials += " " + level.materialIds[material];
  }
  lines.push_back("entity " + entity.id + ", " + materials);
  lines.push_back("at " + vector3(target.point) + ", " + number(target.distance) + " m");
  if (entity.interactable)
    lines.push_back(interactableState(*entity.interactable, world, target.entity));
  return lines;
}

std::string cameraJson(const World& world) {
  return "\"camera\": { \"position\": " + vector3(world.eyePosition()) +
         ", \"yaw_degrees\": " + number(world.yawDegrees()) +
         ", \"pitch_degrees\": " + number(world.pitchDegrees()) +
         ", \"fov_degrees\": " + number(world.camera().verticalFovDegrees) + " }";
}

std::string positionJson(const glm::vec3& point) {
  return "\"position\": " + vector3(point);
}

}  // namespace game
