#pragma once
// First-person walking: a vertical capsule moved in fixed ticks against the collision world.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "game/collision.hpp"
#include "game/replay.hpp"
#include "scene/scene_desc.hpp"

namespace game {

// One tick of input: move (x strafe right, y forward, each in [-1, 1]), yawDeltaDegrees,
// pitchDeltaDegrees, jump, interact, adjust. The same struct replays record.
using PlayerInput = TickInput;

struct PlayerSettings {
  float walkSpeed = 4.0f;     // m/s
  float gravity = 9.81f;      // m/s², downwards
  float jumpVelocity = 5.0f;  // m/s
  float stepHeight = 0.35f;   // climbed while walking
  float maxSlopeDegrees = 45.0f;
  float radius = 0.3f;
  float height = 1.8f;
  float eyeHeight = 1.65f;  // above the feet
};

class PlayerController {
 public:
  static constexpr float TICK_SECONDS = 1.0f / 60.0f;

  // `spawn.position` is the eye; the feet are eyeHeight below it.
  explicit PlayerController(const scene::CameraDesc& spawn, const PlayerSettings& settings = {});

  // One tick: look, ride the platform stood on, walk (with steps), then fall or stick to the
  // ground. `world` already holds this tick's transforms.
  void tick(const PlayerInput& input, const CollisionWorld& world);

  // One tick of the authors' fly camera: look, then move along the view (jump rises) at
  // FLY_SPEED_FACTOR times the walking speed, through everything, without gravity.
  void fly(const PlayerInput& input);
  static constexpr float FLY_SPEED_FACTOR = 2.0f;

  glm::vec3 feet() const { return feet_; }
  glm::vec3 eye() const { return feet_ + glm::vec3(0.0f, settings_.eyeHeight, 0.0f); }
  float yawDegrees() const { return yawDegrees_; }
  float pitchDegrees() const { return pitchDegrees_; }
  glm::vec3 viewDirection() const;  // unit; yaw 0, pitch 0 is −Z
  glm::vec3 velocity() const { return velocity_; }
  bool grounded() const { return grounded_; }
  std::optional<uint32_t> groundEntity() const { return groundEntity_; }
  const PlayerSettings& settings() const { return settings_; }

  // Places the feet (a respawn); the player starts falling from there.
  void teleport(const glm::vec3& feet);
  void setYawDegrees(float degrees) { yawDegrees_ = std::remainder(degrees, 360.0f); }
  void setPitchDegrees(float degrees) { pitchDegrees_ = std::clamp(degrees, -89.0f, 89.0f); }
  // Only the vertical part lasts: walking sets the horizontal velocity every tick.
  void setVelocity(const glm::vec3& velocity) {
    velocity_ = velocity;
    if (velocity.y > 0.0f) grounded_ = false;
  }

 private:
  struct Contacts {
    bool ground = false;  // a walkable surface pushed the capsule up
    std::optional<uint32_t> groundEntity;
    float highestGroundPoint = -1e30f;  // y of the highest ground contact
    bool ceiling = false;               // something above pushed it down
    bool wall = false;                  // a wall or a too-steep slope pushed it sideways
  };
  void resolve(glm::vec3& feet, const CollisionWorld& world, Contacts& contacts) const;
  // Moves in sub-steps of at most radius / 2 so nothing thinner than that is tunnelled through.
  void moveBy(glm::vec3& feet, const glm::vec3& displacement, const CollisionWorld& world,
              Contacts& contacts) const;
  void walk(const glm::vec3& displacement, const CollisionWorld& world);

  PlayerSettings settings_;
  CapsuleShape capsule_;
  float walkableNormalY_;  // cos(max slope)
  glm::vec3 feet_{0.0f};
  glm::vec3 velocity_{0.0f};
  float yawDegrees_ = 0.0f;
  float pitchDegrees_ = 0.0f;
  bool grounded_ = false;
  std::optional<uint32_t> groundEntity_;
  glm::mat4 groundTransform_{1.0f};  // the ground entity's transform at the end of last tick
};

}  // namespace game
