#include "game/world.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "game/mover_path.hpp"

namespace game {

World::World(const Level& level, const PlayerSettings& player)
    : entities_(level.entities),
      lights_(level.lights),
      lightCarriers_(level.lightCarriers),
      verticalFovDegrees_(level.camera.verticalFovDegrees),
      collision_(level),
      player_(level.camera, player),
      values_(level.entities.size(), 0.0f),
      movers_(level.entities.size()),
      visible_(level.entities.size(), 1),
      locked_(level.entities.size(), 0) {
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
    if (entity.mover && !entity.mover->startsPlaying) movers_[e].direction = 0;
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
  if (e.mover) return moverTransform(e, double(movers_[entity].ticks) * TICK_SECONDS);
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
  if (!hit || !entities_[hit->entity].interactable || locked_[hit->entity]) return std::nullopt;
  return hit->entity;
}

void World::step(const PlayerInput& input) {
  ++tick_;
  changed_.clear();
  for (uint32_t e = 0; e < entities_.size(); ++e) {
    if (!entities_[e].mover) continue;
    advanceMover(e);
    place(e);
  }

  if (flying_)
    player_.fly(input);
  else
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

namespace {

int64_t ticksOf(double seconds) {
  return int64_t(std::ceil(seconds / World::TICK_SECONDS - 1e-6));
}

}  // namespace

void World::advanceMover(uint32_t entity) {
  MoverClock& clock = movers_[entity];
  if (clock.direction == 0) return;
  const Mover& mover = *entities_[entity].mover;
  clock.ticks += clock.direction;
  if (clock.targetTicks && (clock.direction > 0 ? clock.ticks >= *clock.targetTicks
                                                : clock.ticks <= *clock.targetTicks)) {
    clock.ticks = *clock.targetTicks;
    clock.direction = 0;
    clock.targetTicks.reset();
    return;
  }
  if (mover.repeat == Mover::Repeat::Once) {
    // Past either end the pose no longer changes; the clock stays there so that a reverse
    // starts back at once.
    clock.ticks = std::clamp<int64_t>(clock.ticks, 0, ticksOf(mover.durationSeconds) + 1);
  } else if (clock.ticks < 0) {
    const double period =
        mover.durationSeconds * (mover.repeat == Mover::Repeat::PingPong ? 2.0 : 1.0);
    clock.ticks += std::max<int64_t>(1, ticksOf(period));
  }
}

void World::playMover(uint32_t entity, int direction) {
  movers_[entity].direction = std::clamp(direction, -1, 1);
  movers_[entity].targetTicks.reset();
}

void World::sendMoverToKeyframe(uint32_t entity, uint32_t keyframe) {
  const Mover& mover = *entities_[entity].mover;
  MoverClock& clock = movers_[entity];
  const int64_t end = ticksOf(mover.durationSeconds);
  if (mover.repeat != Mover::Repeat::Once) {
    // The same pose on the once-through timeline [0, end].
    const int64_t period = mover.repeat == Mover::Repeat::PingPong ? 2 * end : end;
    if (period > 0) {
      clock.ticks = ((clock.ticks % period) + period) % period;
      if (clock.ticks > end) clock.ticks = period - clock.ticks;
    }
  }
  const double keyframeSeconds =
      mover.keyframes.size() > 1
          ? mover.durationSeconds * double(keyframe) / double(mover.keyframes.size() - 1)
          : 0.0;
  const int64_t target = std::min(end, int64_t(std::llround(keyframeSeconds / TICK_SECONDS)));
  clock.targetTicks = target;
  clock.direction = target > clock.ticks ? 1 : target < clock.ticks ? -1 : 0;
  if (clock.direction == 0) clock.targetTicks.reset();
}

bool World::switchOn(uint32_t entity) const {
  const Interactable& it = *entities_[entity].interactable;
  return it.light < lightsEnabled_.size() && lightsEnabled_[it.light] != 0;
}

void World::setVisible(uint32_t entity, bool visible) {
  visible_[entity] = visible ? 1 : 0;
  collision_.setSolid(entity, visible);
  if (!visible && held_ == entity) held_.reset();
  if (!visible && picked_ == entity) picked_.reset();
}

void World::setLocked(uint32_t entity, bool locked) {
  locked_[entity] = locked ? 1 : 0;
  if (locked && held_ == entity) held_.reset();
  if (locked && picked_ == entity) picked_.reset();
}

void World::respawnPlayer(const glm::vec3& feet, float yawDegrees) {
  player_.teleport(feet);
  player_.setYawDegrees(yawDegrees);
}

void World::placePlayer(const glm::vec3& feet, float yawDegrees, float pitchDegrees) {
  respawnPlayer(feet, yawDegrees);
  player_.setPitchDegrees(pitchDegrees);
}

std::vector<scene::LightDesc> World::lights() const {
  std::vector<scene::LightDesc> lights = lights_;
  for (size_t i = 0; i < lights.size(); ++i) {
    lights[i].enabled = lightsEnabled_[i] != 0;
    if (i >= lightCarriers_.size() || !lightCarriers_[i]) continue;
    // Where the carrier is now, relative to where the level put it.
    const uint32_t carrier = *lightCarriers_[i];
    const glm::mat4 moved =
        entityTransform(carrier) * glm::inverse(game::entityTransform(entities_[carrier]));
    lights[i].position = glm::vec3(moved * glm::vec4(lights[i].position, 1.0f));
    const glm::vec3 direction = glm::mat3(moved) * lights[i].direction;
    if (glm::length(direction) > 0.0f) lights[i].direction = glm::normalize(direction);
  }
  return lights;
}

scene::CameraDesc World::camera() const {
  return {player_.eye(), player_.yawDegrees(), player_.pitchDegrees(), verticalFovDegrees_};
}

}  // namespace game
