#pragma once
// Whole-level transforms for robustness tests: the same level moved far from the origin or
// scaled, with everything that has a place moving with it (camera, entities, mover keyframes,
// lights, reach boxes, fall heights).
#include <glm/glm.hpp>

#include "game/level.hpp"

namespace test {

namespace detail {

inline void translateGoal(game::Goal& goal, const glm::vec3& offset) {
  goal.min += offset;
  goal.max += offset;
  for (game::Goal& child : goal.children) translateGoal(child, offset);
}

inline void scaleGoal(game::Goal& goal, float factor) {
  goal.min *= factor;
  goal.max *= factor;
  for (game::Goal& child : goal.children) scaleGoal(child, factor);
}

}  // namespace detail

inline game::Level translatedLevel(game::Level level, const glm::vec3& offset) {
  level.camera.position += offset;
  for (game::Entity& entity : level.entities) {
    entity.position += offset;
    if (entity.mover) {
      for (game::Keyframe& keyframe : entity.mover->keyframes) keyframe.position += offset;
    }
  }
  for (scene::LightDesc& light : level.lights) light.position += offset;
  if (level.goal) detail::translateGoal(*level.goal, offset);
  for (game::LoseCondition& lose : level.lose) lose.below += offset.y;
  return level;
}

// Lengths times `factor`, light intensities adjusted so every surface gets the same
// irradiance: point lights (W/sr) by factor², area lights (radiance) and suns unchanged.
inline game::Level scaledLevel(game::Level level, float factor) {
  level.camera.position *= factor;
  for (game::Entity& entity : level.entities) {
    entity.position *= factor;
    entity.scale *= factor;
    if (entity.mover) {
      for (game::Keyframe& keyframe : entity.mover->keyframes) keyframe.position *= factor;
    }
    if (entity.interactable && entity.interactable->type == game::Interactable::Type::Slide) {
      entity.interactable->min *= factor;
      entity.interactable->max *= factor;
      entity.interactable->start *= factor;
    }
  }
  for (scene::LightDesc& light : level.lights) {
    light.position *= factor;
    light.radius *= factor;
    light.size *= factor;
    if (light.type == scene::LightType::Point) light.intensity *= factor * factor;
  }
  if (level.goal) detail::scaleGoal(*level.goal, factor);
  for (game::LoseCondition& lose : level.lose) lose.below *= factor;
  return level;
}

}  // namespace test
