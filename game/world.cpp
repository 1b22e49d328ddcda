#include "game/world.hpp"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "game/mover_path.hpp"

namespace game {

World::World(const Level& level, const PlayerSettings& player)
    : entities_(level.entities),
      lights_(level.lights),
      verticalFovDegrees_(level.camera.verticalFovDegrees),
      collision_(level),
      player_(level.camera, player),
      values_(level.entities.size(), 0.0f) {
  for (const scene::LightDesc& light : lights_) lightsEnabled_.push_back(light.enabled ? 1 : 0);
  for (uint32_t e = 0; e < entities_.size(); ++e) {
    const Entity& entity = entities_[e];
    if (entity.interactable) {
      const Interactable& it = *entity.interactable;
      if (it.type == Interactable::Type::Switch) {
        if (it.light < lightsEnabled_.size()) lightsEnabled_[it.light] = it.startsOn ? 1 : 0;
      } else {
        values_[e] = std::clamp(it.start, it.min, it.max);
      }
    }
    if (entity.mover || entity.interactable) {
      collision_.setTransform(e, poseOf(e));
      changed_.push_back(e);
    }
  }
  picked_ = pick();
}

// Rotate turns the authored pose about `axis` through the entity's position by the current
// angle; Slide moves it along `axis` by the current offset. The authored pose is value 0.
glm::mat4 World::poseOf(uint32_t entity) const {
  const Entity& e = entities_[entity];
  if (e.mover) return moverTransform(e, seconds());
  const glm::mat4 authored = game::entityTransform(e);
  if (!e.interactable) return authored;
  const Interactable& it = *e.interactable;
  const float value = values_[entity];
  switch (it.type) {
    case Interactable::Type::Rotate: {
      glm::mat4 about = glm::translate(glm::mat4(1.0f), e.position);
      about = glm::rotate(about, glm::radians(value), it.axis);
      return glm::translate(about, -e.position) * authored;
    }
    case Interactable::Type::Slide:
      return glm::translate(glm::mat4(1.0f), it.axis * value) * authored;
    case Interactable::Type::Switch:
      break;
  }
  return authored;
}

void World::place(uint32_t entity) {
  const glm::mat4 pose = poseOf(entity);
  if (pose == collision_.transform(entity)) return;
  collision_.setTransform(entity, pose);
  changed_.push_back(entity);
}

std::optional<uint32_t> World::pick() const {
  const std::optional<RayHit> hit =
      collision_.rayCast(player_.eye(), player_.viewDirection(), REACH_METRES);
  if (!hit || !entities_[hit->entity].interactable) return std::nullopt;
  return hit->entity;
}

void World::step(const PlayerInput& input) {
  ++tick_;
  changed_.clear();
  for (uint32_t e = 0; e < entities_.size(); ++e)
    if (entities_[e].mover) place(e);

  player_.tick(input, collision_);

  const bool pressed = input.interact && !interactWasDown_;
  interactWasDown_ = input.interact;
  picked_ = pick();
  if (!input.interact) held_.reset();
  if (pressed && picked_) {
    const Interactable& it = *entities_[*picked_].interactable;
    if (it.type == Interactable::Type::Switch) {
      if (it.light < lightsEnabled_.size()) lightsEnabled_[it.light] ^= 1;
    } else {
      held_ = *picked_;
    }
  }
  if (held_) {
    const Interactable& it = *entities_[*held_].interactable;
    const float rate =
        it.type == Interactable::Type::Rotate ? ROTATE_DEGREES_PER_SECOND : SLIDE_METRES_PER_SECOND;
    const float adjust = std::clamp(input.adjust, -1.0f, 1.0f);
    values_[*held_] =
        std::clamp(values_[*held_] + adjust * rate * float(TICK_SECONDS), it.min, it.max);
    place(*held_);
  }
  std::sort(changed_.begin(), changed_.end());
}

std::vector<scene::LightDesc> World::lights() const {
  std::vector<scene::LightDesc> lights = lights_;
  for (size_t i = 0; i < lights.size(); ++i) lights[i].enabled = lightsEnabled_[i] != 0;
  return lights;
}

scene::CameraDesc World::camera() const {
  return {player_.eye(), player_.yawDegrees(), player_.pitchDegrees(), verticalFovDegrees_};
}

}  // namespace game
