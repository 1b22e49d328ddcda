#pragma once
// The simulated level: fixed 60 Hz ticks of movers, the player and interactables. Pure CPU and
// deterministic: the same level and inputs give the same states bit for bit.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "game/collision.hpp"
#include "game/level.hpp"
#include "game/player_controller.hpp"
#include "scene/scene_desc.hpp"

namespace game {

class World {
 public:
  static constexpr double TICK_SECONDS = 1.0 / 60.0;
  static constexpr float REACH_METRES = 3.0f;                // how far interact reaches
  static constexpr float ROTATE_DEGREES_PER_SECOND = 90.0f;  // held Rotate at adjust = 1
  static constexpr float SLIDE_METRES_PER_SECOND = 1.0f;     // held Slide at adjust = 1

  // Copies what it needs; the level need not outlive the world.
  explicit World(const Level& level, const PlayerSettings& player = {});

  // One tick: movers at the new tick's time, then the player against the moved geometry, then
  // interaction (a press picks what the crosshair is on; a held Rotate/Slide follows `adjust`).
  void step(const PlayerInput& input);

  uint64_t tick() const { return tick_; }  // 0 before the first step
  double seconds() const { return double(tick_) * TICK_SECONDS; }

  size_t entityCount() const { return entities_.size(); }
  const glm::mat4& entityTransform(uint32_t entity) const { return collision_.transform(entity); }
  // Entities whose transform changed in the last step, ascending (after construction: every
  // mover and interactable, placed at their start poses).
  const std::vector<uint32_t>& changedEntities() const { return changed_; }
  // A Rotate's angle in degrees or a Slide's offset in metres (0 for other entities).
  float interactableValue(uint32_t entity) const { return values_[entity]; }

  size_t lightCount() const { return lightsEnabled_.size(); }
  bool lightEnabled(uint32_t light) const { return lightsEnabled_[light] != 0; }
  // A switch interactable is on when the light it switches is.
  bool switchOn(uint32_t entity) const;
  // The level's lights with their current enabled states and poses (a light that rides an
  // entity moves and turns with it).
  std::vector<scene::LightDesc> lights() const;

  const PlayerController& player() const { return player_; }
  glm::vec3 eyePosition() const { return player_.eye(); }
  glm::vec3 feetPosition() const { return player_.feet(); }
  float yawDegrees() const { return player_.yawDegrees(); }
  float pitchDegrees() const { return player_.pitchDegrees(); }
  bool grounded() const { return player_.grounded(); }
  scene::CameraDesc camera() const;  // the eye, with the level's field of view
  // The player's own field of view instead of the level's (a play setting; replays keep it).
  void setVerticalFovDegrees(float degrees) { verticalFovDegrees_ = degrees; }

  // The interactable under the crosshair (the nearest surface within reach belongs to it).
  std::optional<uint32_t> pickedEntity() const { return picked_; }
  // The Rotate/Slide being held, if any.
  std::optional<uint32_t> heldEntity() const { return held_; }

  const CollisionWorld& collision() const { return collision_; }

  // ----- what level logic changes (game/logic.hpp); each takes effect from the next step -----

  // A mover's clock runs forwards, backwards, or stands; Goto runs it to a keyframe and stops.
  void playMover(uint32_t entity, int direction);  // +1, -1 or 0
  void sendMoverToKeyframe(uint32_t entity, uint32_t keyframe);
  // -1, 0 or +1; and whether it is heading for a keyframe.
  int moverDirection(uint32_t entity) const { return movers_[entity].direction; }
  void setLightEnabled(uint32_t light, bool enabled) { lightsEnabled_[light] = enabled ? 1 : 0; }
  // A hidden entity is not rendered, traced or collided with (the renderer follows visible()).
  void setVisible(uint32_t entity, bool visible);
  bool visible(uint32_t entity) const { return visible_[entity] != 0; }
  // A locked interactable cannot be picked or held.
  void setLocked(uint32_t entity, bool locked);
  bool locked(uint32_t entity) const { return locked_[entity] != 0; }
  // Puts the player's feet at `feet`, facing `yawDegrees`, at rest.
  void respawnPlayer(const glm::vec3& feet, float yawDegrees);

  // ----- for level authors (play --author, F4; a live reload) -----

  // The fly camera: the player moves through everything, without gravity (PlayerController::fly).
  void setFlying(bool flying) { flying_ = flying; }
  bool flying() const { return flying_; }
  // Puts the player where a reloaded level should keep them: feet, yaw and pitch.
  void placePlayer(const glm::vec3& feet, float yawDegrees, float pitchDegrees);

 private:
  // Counted in ticks so that a mover that plays from the start is exactly where the world's
  // time says (the same bits as before movers could be stopped).
  struct MoverClock {
    int64_t ticks = 0;
    int direction = 1;
    std::optional<int64_t> targetTicks;  // Goto
  };
  void advanceMover(uint32_t entity);

  glm::mat4 poseOf(uint32_t entity) const;  // from the mover time or interactable value
  void place(uint32_t entity);              // updates collision and the changed list
  std::optional<uint32_t> pick() const;

  std::vector<Entity> entities_;
  std::vector<scene::LightDesc> lights_;
  std::vector<std::optional<uint32_t>> lightCarriers_;  // per light
  float verticalFovDegrees_ = 60.0f;
  CollisionWorld collision_;
  PlayerController player_;
  uint64_t tick_ = 0;
  std::vector<float> values_;           // per entity: Rotate angle / Slide offset
  std::vector<uint8_t> lightsEnabled_;  // per light
  std::vector<MoverClock> movers_;      // per entity (used by movers only)
  std::vector<uint8_t> visible_;        // per entity
  std::vector<uint8_t> locked_;         // per entity
  std::vector<uint32_t> changed_;
  std::optional<uint32_t> picked_;
  std::optional<uint32_t> held_;
  bool interactWasDown_ = false;
  bool flying_ = false;
};

}  // namespace game
