// The first-person controller against boxes, steps, slopes, ceilings and a moving platform.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "game/collision.hpp"
#include "game/level.hpp"
#include "game/player_controller.hpp"
#include "game/primitives.hpp"
#include "game/world.hpp"

namespace {

using game::PlayerController;
using game::PlayerInput;

struct LevelBuilder {
  game::Level level;
  LevelBuilder(const glm::vec3& eye = {0.0f, 1.65f, 0.0f}) { level.camera.position = eye; }
  uint32_t add(scene::MeshData mesh, const glm::vec3& position,
               const glm::vec3& rotationDegrees = glm::vec3(0.0f)) {
    level.meshes.push_back(std::move(mesh));
    game::Entity entity;
    entity.id = "e" + std::to_string(level.entities.size());
    entity.mesh = uint32_t(level.meshes.size() - 1);
    entity.position = position;
    entity.rotationDegrees = rotationDegrees;
    level.entities.push_back(entity);
    return uint32_t(level.entities.size() - 1);
  }
  // A box whose top face is at `topY`, centred on (x, z).
  uint32_t box(const glm::vec3& size, float x, float topY, float z) {
    return add(game::primitives::box(size), {x, topY - 0.5f * size.y, z});
  }
  uint32_t floor(float thickness = 0.1f) { return box({40.0f, thickness, 40.0f}, 0, 0, 0); }
};

// A ramp rising towards −Z from the line z = z0 at y = 0: a two-sided quad of `length`.
scene::MeshData ramp(float degrees, float z0, float length) {
  const float h = length * std::sin(glm::radians(degrees));
  const float z1 = z0 - length * std::cos(glm::radians(degrees));
  scene::MeshData mesh;
  for (const glm::vec3& p :
       {glm::vec3(-3, 0, z0), glm::vec3(3, 0, z0), glm::vec3(3, h, z1), glm::vec3(-3, h, z1)})
    mesh.vertices.push_back({p});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

PlayerInput forward(float amount = 1.0f) {
  PlayerInput input;
  input.move = {0.0f, amount};
  return input;
}

void run(PlayerController& player, const game::CollisionWorld& world, int ticks,
         const PlayerInput& input = {}) {
  for (int i = 0; i < ticks; ++i) player.tick(input, world);
}

TEST(Controller, StandsOnAFloorWithoutDrifting) {
  LevelBuilder b;
  b.floor();
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  for (int i = 0; i < 600; ++i) {
    player.tick({}, world);
    ASSERT_NEAR(player.feet().y, 0.0f, 1e-4f) << "tick " << i;
    ASSERT_TRUE(player.grounded()) << "tick " << i;
  }
  EXPECT_EQ(player.feet().x, 0.0f);
  EXPECT_EQ(player.feet().z, 0.0f);
  EXPECT_NEAR(player.eye().y, 1.65f, 1e-4f);
}

TEST(Controller, FallingAt40MetresPerSecondStopsOnAThinFloor) {
  LevelBuilder b({0.0f, 1.65f + 1.0f, 0.0f});
  b.floor(0.1f);
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  player.setVelocity({0.0f, -40.0f, 0.0f});  // 0.67 m per tick, well past the 0.1 m floor
  run(player, world, 30);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
  EXPECT_TRUE(player.grounded());
}

TEST(Controller, FallingFrom100MetresStopsOnAThinFloor) {
  LevelBuilder b({0.0f, 100.0f, 0.0f});
  b.floor(0.1f);
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  float fastest = 0.0f;
  for (int i = 0; i < 400; ++i) {
    player.tick({}, world);
    fastest = std::max(fastest, -player.velocity().y);
  }
  EXPECT_GT(fastest, 40.0f);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
}

TEST(Controller, WalkingAt40MetresPerSecondStopsAtAThinWall) {
  LevelBuilder b;
  b.floor();
  b.box({10.0f, 3.0f, 0.1f}, 0.0f, 3.0f, -3.0f);  // faces at z = -2.95 and -3.05
  const game::CollisionWorld world(b.level);
  game::PlayerSettings fast;
  fast.walkSpeed = 40.0f;
  PlayerController player(b.level.camera, fast);
  run(player, world, 60, forward());
  EXPECT_NEAR(player.feet().z, -2.95f + 0.3f, 1e-3f);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
}

TEST(Controller, WalkingDirectionFollowsYaw) {
  LevelBuilder b;
  b.floor();
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  PlayerInput turn;
  turn.yawDeltaDegrees = 90.0f;  // now facing −X
  player.tick(turn, world);
  run(player, world, 60, forward());  // 4 m in 60 ticks
  EXPECT_NEAR(player.feet().x, -4.0f, 1e-3f);
  EXPECT_NEAR(player.feet().z, 0.0f, 1e-4f);
  PlayerInput strafe;
  strafe.move = {1.0f, 0.0f};  // right of −X is −Z
  run(player, world, 30, strafe);
  EXPECT_NEAR(player.feet().z, -2.0f, 1e-3f);
}

TEST(Controller, ClimbsA30CentimetreStepButNotA50CentimetreOne) {
  for (const float height : {0.3f, 0.5f}) {
    LevelBuilder b;
    b.floor();
    b.box({10.0f, height, 10.0f}, 0.0f, height, -7.0f);  // front face at z = -2
    const game::CollisionWorld world(b.level);
    PlayerController player(b.level.camera);
    run(player, world, 90, forward());  // 6 m of walking
    if (height < 0.35f) {
      EXPECT_NEAR(player.feet().y, height, 1e-4f);
      EXPECT_NEAR(player.feet().z, -6.0f, 1e-3f);
    } else {
      EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
      EXPECT_NEAR(player.feet().z, -2.0f + 0.3f, 1e-3f);
    }
    EXPECT_TRUE(player.grounded());
  }
}

TEST(Controller, WalkingOffALedgeHigherThanAStepFalls) {
  LevelBuilder b;
  b.box({10.0f, 0.1f, 10.0f}, 0.0f, 0.0f, 3.0f);  // the player's floor ends at z = -2
  b.box({10.0f, 0.1f, 10.0f}, 0.0f, -1.0f, -7.0f);
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  bool fell = false;
  for (int i = 0; i < 60; ++i) {
    player.tick(forward(), world);
    fell = fell || (!player.grounded() && player.feet().y < -0.5f);
  }
  EXPECT_TRUE(fell);
  EXPECT_NEAR(player.feet().y, -1.0f, 1e-4f);
  EXPECT_TRUE(player.grounded());
}

TEST(Controller, WalksDownStepsWithoutLeavingTheGround) {
  LevelBuilder b;
  b.box({10.0f, 0.1f, 10.0f}, 0.0f, 0.0f, 3.0f);  // ends at z = -2
  b.box({10.0f, 0.1f, 10.0f}, 0.0f, -0.3f, -7.0f);
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  for (int i = 0; i < 60; ++i) {
    player.tick(forward(), world);
    ASSERT_TRUE(player.grounded()) << "tick " << i;
  }
  EXPECT_NEAR(player.feet().y, -0.3f, 1e-4f);
  EXPECT_NEAR(player.feet().z, -4.0f, 1e-3f);
}

// Settles on the ground, jumps once, and returns the feet's highest point over the next
// two seconds (by then the player has landed again).
float highestFeetInAJump(PlayerController& player, const game::CollisionWorld& world) {
  player.tick({}, world);
  PlayerInput jump;
  jump.jump = true;
  float highest = 0.0f;
  player.tick(jump, world);
  for (int i = 0; i < 120; ++i) {
    highest = std::max(highest, player.feet().y);
    player.tick({}, world);
  }
  return highest;
}

TEST(Controller, JumpsAboutTheAnalyticHeight) {
  LevelBuilder b;
  b.floor();
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  const float highest = highestFeetInAJump(player, world);
  EXPECT_NEAR(highest, 5.0f * 5.0f / (2.0f * 9.81f), 0.05f);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
  EXPECT_TRUE(player.grounded());
}

TEST(Controller, CeilingStopsTheHead) {
  LevelBuilder b;
  b.floor();
  b.box({40.0f, 0.2f, 40.0f}, 0.0f, 2.4f, 0.0f);  // underside at 2.2 m
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  const float highest = highestFeetInAJump(player, world);
  EXPECT_LT(highest, 2.2f - 1.8f + 1e-3f);
  EXPECT_GT(highest, 2.2f - 1.8f - 0.05f);  // it did jump up to the ceiling
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
}

TEST(Controller, WalksUpA30DegreeSlope) {
  LevelBuilder b;
  b.floor();
  b.add(ramp(30.0f, -1.0f, 8.0f), glm::vec3(0.0f));
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  run(player, world, 60, forward());
  // The sphere rests on the plane: its lowest point is r / cos(30°) − r above the surface.
  const float surface = (-1.0f - player.feet().z) * std::tan(glm::radians(30.0f));
  EXPECT_LT(player.feet().z, -3.0f);
  EXPECT_NEAR(player.feet().y, surface + 0.3f / std::cos(glm::radians(30.0f)) - 0.3f, 1e-3f);
  EXPECT_TRUE(player.grounded());
  // Standing on it does not slide.
  const glm::vec3 resting = player.feet();
  run(player, world, 120);
  EXPECT_NEAR(glm::length(player.feet() - resting), 0.0f, 1e-4f);
}

TEST(Controller, CannotWalkUpA60DegreeSlopeAndSlidesOffIt) {
  LevelBuilder b;
  b.floor();
  b.add(ramp(60.0f, -1.0f, 8.0f), glm::vec3(0.0f));
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  run(player, world, 120, forward());
  EXPECT_LT(player.feet().y, 0.01f);
  EXPECT_GT(player.feet().z, -1.0f);

  // Dropped onto the slope, the player slides down to the floor.
  player.teleport({0.0f, 3.0f, -1.0f - 3.0f / std::tan(glm::radians(60.0f)) + 0.2f});
  run(player, world, 180);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
  EXPECT_GT(player.feet().z, -1.0f);
}

TEST(Controller, MovingPlatformCarriesThePlayer) {
  LevelBuilder b;
  const uint32_t platform = b.box({2.0f, 0.2f, 2.0f}, 0.0f, 0.0f, 0.0f);
  game::Mover mover;
  mover.durationSeconds = 4.0f;
  mover.repeat = game::Mover::Repeat::Once;
  mover.keyframes = {{{0.0f, -0.1f, 0.0f}}, {{4.0f, 0.9f, 0.0f}}};  // top from y 0 to 1
  b.level.entities[platform].mover = mover;
  game::World world(b.level);
  const auto top = [&] {
    return glm::vec3(world.entityTransform(platform)[3]) + glm::vec3(0.0f, 0.1f, 0.0f);
  };
  // The first tick lands the player (it starts in the air), so the platform's first 1/60 s of
  // sideways motion is not carried; from then on the offset stays put.
  world.step({});
  const float offsetX = world.feetPosition().x - top().x;
  EXPECT_NEAR(offsetX, -4.0f / 240.0f, 1e-4f);
  for (int tick = 2; tick <= 180; ++tick) {
    world.step({});
    ASSERT_NEAR(world.feetPosition().x - top().x, offsetX, 1e-3f) << "tick " << tick;
    ASSERT_NEAR(world.feetPosition().y, top().y, 1e-3f) << "tick " << tick;
  }
  EXPECT_NEAR(top().x, 3.0f, 1e-5f);
  EXPECT_TRUE(world.grounded());
}

TEST(Controller, PitchIsClampedAndYawTurnsLeft) {
  LevelBuilder b;
  b.floor();
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  PlayerInput look;
  look.pitchDeltaDegrees = 200.0f;
  look.yawDeltaDegrees = 90.0f;
  player.tick(look, world);
  EXPECT_EQ(player.pitchDegrees(), 89.0f);
  look.pitchDeltaDegrees = -400.0f;
  look.yawDeltaDegrees = 0.0f;
  player.tick(look, world);
  EXPECT_EQ(player.pitchDegrees(), -89.0f);
  look.pitchDeltaDegrees = 89.0f;
  player.tick(look, world);
  const glm::vec3 view = player.viewDirection();
  EXPECT_NEAR(view.x, -1.0f, 1e-5f);  // yaw 90: looking along −X
  EXPECT_NEAR(view.y, 0.0f, 1e-5f);
}

}  // namespace
