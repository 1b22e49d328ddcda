#include "game/player_controller.hpp"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

constexpr int maxResolveIterations = 12;
constexpr float negligibleDepth = 1e-6f;

glm::vec3 horizontal(const glm::vec3& v) {
  return {v.x, 0.0f, v.z};
}

}  // namespace

PlayerController::PlayerController(const scene::CameraDesc& spawn, const PlayerSettings& settings)
    : settings_(settings),
      capsule_{settings.radius, settings.height},
      walkableNormalY_(std::cos(glm::radians(settings.maxSlopeDegrees)) - 1e-4f),
      feet_(spawn.position - glm::vec3(0.0f, settings.eyeHeight, 0.0f)),
      yawDegrees_(spawn.yawDegrees),
      pitchDegrees_(std::clamp(spawn.pitchDegrees, -89.0f, 89.0f)) {}

glm::vec3 PlayerController::viewDirection() const {
  const float yaw = glm::radians(yawDegrees_), pitch = glm::radians(pitchDegrees_);
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

void PlayerController::teleport(const glm::vec3& feet) {
  feet_ = feet;
  velocity_ = glm::vec3(0.0f);
  grounded_ = false;
  groundEntity_.reset();
}

// Ground (a walkable face touched by the bottom hemisphere, or any contact from below within the
// slope limit) pushes straight up, so standing on a gentle slope does not slide and a rounded
// bottom can stand on an edge. Walls and steep slopes push straight sideways: walking into them
// never lifts the player, so steep slopes cannot be climbed and gravity slides the player down
// them. Surfaces facing down push along their normal.
void PlayerController::resolve(glm::vec3& feet, const CollisionWorld& world,
                               Contacts& contacts) const {
  const float r = settings_.radius;
  for (int iteration = 0; iteration < maxResolveIterations; ++iteration) {
    const std::optional<CapsuleContact> contact = world.deepestContact(feet, capsule_);
    if (!contact || contact->depth <= negligibleDepth) return;
    const glm::vec3 n = contact->normal;
    const glm::vec3 sphereCentre = feet + glm::vec3(0.0f, r, 0.0f);
    const bool belowCentre = contact->point.y < sphereCentre.y - 1e-4f;
    const bool walkableFace = contact->faceNormal.y >= walkableNormalY_;
    const float sideways = glm::length(horizontal(n));
    if ((belowCentre && walkableFace) || n.y >= walkableNormalY_) {
      // Up until the sphere clears the contact point, and at least the plane's own clearance.
      const glm::vec3 offset = horizontal(contact->point - sphereCentre);
      const float h2 = std::min(glm::dot(offset, offset), r * r);
      const float clearPoint = contact->point.y + std::sqrt(r * r - h2) - sphereCentre.y;
      const float up = walkableFace ? contact->faceNormal.y : n.y;
      feet.y += std::max(clearPoint, contact->depth / up);
      contacts.ground = true;
      contacts.groundEntity = contact->entity;
      contacts.highestGroundPoint = std::max(contacts.highestGroundPoint, contact->point.y);
    } else if (n.y < -0.01f || sideways < 1e-4f) {
      feet += n * contact->depth;
      contacts.ceiling = contacts.ceiling || n.y < 0.0f;
    } else {
      feet += horizontal(n) / sideways * (contact->depth / sideways);
      contacts.wall = true;
    }
  }
}

void PlayerController::moveBy(glm::vec3& feet, const glm::vec3& displacement,
                              const CollisionWorld& world, Contacts& contacts) const {
  const float maxSubStep = 0.5f * settings_.radius;
  const int steps = std::max(1, int(std::ceil(glm::length(displacement) / maxSubStep)));
  for (int i = 0; i < steps; ++i) {
    feet += displacement / float(steps);
    resolve(feet, world, contacts);
  }
}

// Walks; when grounded and blocked, also tries the classic step: up by the step height, across,
// back down, keeping it only if it lands on walkable ground further along.
void PlayerController::walk(const glm::vec3& displacement, const CollisionWorld& world) {
  const glm::vec3 start = feet_;
  Contacts plain;
  moveBy(feet_, displacement, world, plain);
  if (!grounded_ || !plain.wall) return;

  const glm::vec3 direction = glm::normalize(displacement);
  const glm::vec3 up(0.0f, settings_.stepHeight, 0.0f);
  glm::vec3 stepped = start;
  Contacts climb;
  moveBy(stepped, up, world, climb);
  moveBy(stepped, displacement, world, climb);
  Contacts landing;
  moveBy(stepped, -up, world, landing);
  const float plainProgress = glm::dot(feet_ - start, direction);
  const float steppedProgress = glm::dot(stepped - start, direction);
  const float rise = settings_.stepHeight + 1e-4f;
  if (landing.ground && stepped.y <= start.y + rise &&
      landing.highestGroundPoint <= start.y + rise && steppedProgress > plainProgress + 1e-4f)
    feet_ = stepped;
}

void PlayerController::fly(const PlayerInput& input) {
  yawDegrees_ = std::remainder(yawDegrees_ + input.yawDeltaDegrees, 360.0f);
  pitchDegrees_ = std::clamp(pitchDegrees_ + input.pitchDeltaDegrees, -89.0f, 89.0f);
  glm::vec2 move = glm::clamp(input.move, glm::vec2(-1.0f), glm::vec2(1.0f));
  if (glm::length(move) > 1.0f) move = glm::normalize(move);
  const float yaw = glm::radians(yawDegrees_);
  const glm::vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
  const glm::vec3 rise(0.0f, input.jump ? 1.0f : 0.0f, 0.0f);
  const float speed = settings_.walkSpeed * FLY_SPEED_FACTOR;
  feet_ += (right * move.x + viewDirection() * move.y + rise) * speed * TICK_SECONDS;
  velocity_ = glm::vec3(0.0f);
  grounded_ = false;
  groundEntity_.reset();
}

void PlayerController::tick(const PlayerInput& input, const CollisionWorld& world) {
  const float dt = TICK_SECONDS;
  yawDegrees_ = std::remainder(yawDegrees_ + input.yawDeltaDegrees, 360.0f);
  pitchDegrees_ = std::clamp(pitchDegrees_ + input.pitchDeltaDegrees, -89.0f, 89.0f);

  // Ride: the platform's motion since last tick carries the feet before the player's own.
  if (grounded_ && groundEntity_) {
    const glm::mat4& now = world.transform(*groundEntity_);
    if (now != groundTransform_)
      feet_ = glm::vec3(now * glm::inverse(groundTransform_) * glm::vec4(feet_, 1.0f));
  }

  glm::vec2 move = glm::clamp(input.move, glm::vec2(-1.0f), glm::vec2(1.0f));
  if (glm::length(move) > 1.0f) move = glm::normalize(move);
  const float yaw = glm::radians(yawDegrees_);
  const glm::vec3 forward(-std::sin(yaw), 0.0f, -std::cos(yaw));
  const glm::vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
  const glm::vec3 walkVelocity = (right * move.x + forward * move.y) * settings_.walkSpeed;
  velocity_.x = walkVelocity.x;
  velocity_.z = walkVelocity.z;

  const bool jumping = grounded_ && input.jump;
  if (jumping) velocity_.y = settings_.jumpVelocity;
  if (glm::length(walkVelocity) > 0.0f) walk(walkVelocity * dt, world);

  Contacts vertical;
  if (grounded_ && !jumping) {
    // Stick to the ground (down slopes and steps); stepping off a ledge starts a fall instead.
    velocity_.y = 0.0f;
    glm::vec3 snapped = feet_;
    moveBy(snapped, glm::vec3(0.0f, -settings_.stepHeight, 0.0f), world, vertical);
    if (vertical.ground) feet_ = snapped;
  } else {
    velocity_.y -= settings_.gravity * dt;
    moveBy(feet_, glm::vec3(0.0f, velocity_.y * dt, 0.0f), world, vertical);
    if (vertical.ground && velocity_.y < 0.0f) velocity_.y = 0.0f;
    if (vertical.ceiling && velocity_.y > 0.0f) velocity_.y = 0.0f;
  }
  grounded_ = vertical.ground && velocity_.y <= 0.0f;
  groundEntity_ = grounded_ ? vertical.groundEntity : std::nullopt;
  if (groundEntity_) groundTransform_ = world.transform(*groundEntity_);
}

}  // namespace game
