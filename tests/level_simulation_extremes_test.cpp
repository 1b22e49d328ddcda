// Simulation extremes (docs/ROBUSTNESS.md, "Simulation extremes"): long frames, very fast
// players and platforms, determinism. Game-only: no Vulkan. Each test prints its measured values
// next to the limit it asserts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "game/player_controller.hpp"
#include "game/primitives.hpp"
#include "game/replay.hpp"
#include "game/tick_clock.hpp"
#include "game/world.hpp"

namespace {

using game::PlayerController;
using game::TickClock;
using game::World;

const std::filesystem::path kSource = SIGHTLINE_SOURCE_DIR;
constexpr double kTick = TickClock::TICK_SECONDS;

// Everything a tick can change, compared bit for bit.
struct WorldState {
  uint64_t tick = 0;
  glm::vec3 feet{0.0f}, velocity{0.0f};
  float yaw = 0.0f, pitch = 0.0f;
  bool grounded = false;
  std::vector<glm::mat4> transforms;
  bool operator==(const WorldState&) const = default;
};

WorldState stateOf(const World& world) {
  WorldState state{world.tick(),
                   world.feetPosition(),
                   world.player().velocity(),
                   world.yawDegrees(),
                   world.pitchDegrees(),
                   world.grounded(),
                   {}};
  for (uint32_t e = 0; e < world.entityCount(); ++e)
    state.transforms.push_back(world.entityTransform(e));
  return state;
}

// A level of boxes and platforms built in code; the eye starts 1.65 m above `feet`.
struct LevelBuilder {
  game::Level level;
  explicit LevelBuilder(const glm::vec3& feet = glm::vec3(0.0f)) {
    level.camera.position = feet + glm::vec3(0.0f, 1.65f, 0.0f);
  }
  uint32_t box(const glm::vec3& size, const glm::vec3& centre) {
    level.meshes.push_back(game::primitives::box(size));
    game::Entity entity;
    entity.id = "box" + std::to_string(level.entities.size());
    entity.mesh = uint32_t(level.meshes.size() - 1);
    entity.position = centre;
    level.entities.push_back(entity);
    return uint32_t(level.entities.size() - 1);
  }
  void floor() { box({200.0f, 0.1f, 200.0f}, {0.0f, -0.05f, 0.0f}); }
};

// ----- Long frames -----

TEST(TickClock, a_5_second_frame_runs_5_ticks_and_drops_the_rest) {
  TickClock clock;
  EXPECT_EQ(clock.advance(5.0), TickClock::MAX_TICKS_PER_FRAME);
  EXPECT_EQ(clock.droppedTicks(), 295u);  // 300 due, 5 run
  EXPECT_EQ(clock.backlogSeconds(), 0.0);
  EXPECT_EQ(clock.advance(kTick), 1);  // and the next frame is a normal one
  EXPECT_EQ(clock.advance(3600.0), TickClock::MAX_TICKS_PER_FRAME);  // an hour in a debugger
  std::printf("5 s frame: %d ticks run, 295 dropped (limit %d)\n", TickClock::MAX_TICKS_PER_FRAME,
              TickClock::MAX_TICKS_PER_FRAME);
}

TEST(TickClock, frame_rates_from_30_to_144_hz_run_60_ticks_a_second) {
  for (const double hertz : {30.0, 60.0, 75.0, 144.0}) {
    TickClock clock;
    int ticks = 0;
    for (int frame = 0; frame < int(hertz) * 10; ++frame) ticks += clock.advance(1.0 / hertz);
    EXPECT_NEAR(ticks, 600, 1) << hertz << " Hz";
    EXPECT_EQ(clock.droppedTicks(), 0u);
  }
}

TEST(TickClock, a_clock_that_jumps_back_or_is_not_a_number_runs_nothing) {
  TickClock clock;
  EXPECT_EQ(clock.advance(0.5 * kTick), 0);
  for (const double bad :
       {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(clock.advance(bad), 0) << bad;
    EXPECT_EQ(clock.backlogSeconds(), 0.5 * kTick) << bad;
  }
  EXPECT_EQ(clock.advance(0.5 * kTick), 1);
}

// The 07_crossing winning replay's inputs (moving platforms, jumps), played by the play loop's
// clock under 60 Hz frames and under random frame times from 1 to 100 ms with 5-second hitches:
// the world sees only ticks, so after every tick the states agree bit for bit; a hitch runs 5
// ticks, the same 5 ticks, so nothing tunnels or explodes.
TEST(SimulationExtremes, hitches_and_uneven_frames_give_the_states_of_steady_60_hz_play) {
  const game::Replay replay = game::loadReplay(kSource / "replays" / "07_crossing_win.json");
  const game::Level level = game::loadLevel(replay.level);
  const uint64_t ticks = 739;
  std::vector<WorldState> steady;
  {
    World world(level);
    TickClock clock;
    while (world.tick() < ticks) {
      const int due = clock.advance(kTick);
      for (int i = 0; i < due && world.tick() < ticks; ++i) {
        world.step(replay.inputAt(world.tick()));
        steady.push_back(stateOf(world));
      }
    }
  }
  World world(level);
  TickClock clock;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> frameSeconds(0.001, 0.1);
  size_t mismatches = 0, hitches = 0, frames = 0;
  float fastestDuringHitch = 0.0f;
  while (world.tick() < ticks) {
    const bool hitch = frames++ % 50 == 49;  // every 50th frame takes 5 s
    const int due = clock.advance(hitch ? 5.0 : frameSeconds(random));
    ASSERT_LE(due, TickClock::MAX_TICKS_PER_FRAME);
    if (hitch) {
      ASSERT_EQ(due, TickClock::MAX_TICKS_PER_FRAME);
      ++hitches;
    }
    for (int i = 0; i < due && world.tick() < ticks; ++i) {
      world.step(replay.inputAt(world.tick()));
      mismatches += !(stateOf(world) == steady[world.tick() - 1]);
      if (hitch)
        fastestDuringHitch = std::max(fastestDuringHitch, glm::length(world.player().velocity()));
    }
  }
  std::printf(
      "07_crossing's 739 ticks over %zu uneven frames with %zu 5-second hitches: %zu ticks "
      "differ from steady play (limit 0); fastest player during a hitch %.2f m/s\n",
      frames, hitches, mismatches, fastestDuringHitch);
  EXPECT_GE(hitches, 5u);
  EXPECT_EQ(mismatches, 0u);
  EXPECT_LT(fastestDuringHitch, 20.0f);
}

// ----- Fast players -----

// 100 m/s is 1.67 m a tick, 17 times a 0.1 m wall and 1667 times a 1 mm one; the controller
// moves in sub-steps of half its radius, so its centre never passes a wall's plane. Head-on and
// at 10 degrees to the wall, for a second.
TEST(SimulationExtremes, player_at_100_metres_per_second_stops_at_walls_down_to_1mm) {
  float deepest = 0.0f;
  for (const float thickness : {0.1f, 0.01f, 0.001f}) {
    for (const float yaw : {0.0f, 80.0f}) {  // yaw 80: walking at 10 degrees to the wall
      LevelBuilder b;
      b.floor();
      b.box({200.0f, 3.0f, thickness}, {0.0f, 1.5f, -3.0f - 0.5f * thickness});  // front z = -3
      const game::CollisionWorld world(b.level);
      game::PlayerSettings fast;
      fast.walkSpeed = 100.0f;
      PlayerController player(b.level.camera, fast);
      game::TickInput input;
      input.move = {0.0f, 1.0f};
      input.yawDeltaDegrees = yaw;
      for (int tick = 0; tick < 60; ++tick) {
        player.tick(input, world);
        input.yawDeltaDegrees = 0.0f;
        // The capsule's surface may touch the wall, never cross it.
        deepest = std::max(deepest, -3.0f - (player.feet().z - fast.radius));
        ASSERT_GT(player.feet().z, -3.0f) << thickness << " m wall, tick " << tick;
      }
      EXPECT_NEAR(player.feet().z, -3.0f + fast.radius, 1e-3f) << thickness << ", yaw " << yaw;
    }
  }
  // Falling at 100 m/s onto a 1 mm floor.
  LevelBuilder b({0.0f, 2.0f, 0.0f});
  b.box({20.0f, 0.001f, 20.0f}, {0.0f, -0.0005f, 0.0f});
  const game::CollisionWorld world(b.level);
  PlayerController player(b.level.camera);
  player.setVelocity({0.0f, -100.0f, 0.0f});
  for (int tick = 0; tick < 30; ++tick) player.tick({}, world);
  std::printf(
      "100 m/s into walls of 0.1, 0.01, 0.001 m: deepest capsule penetration %.2g m "
      "(limit 1e-3); onto a 1 mm floor: feet at %.2g m (limit +-1e-4)\n",
      deepest, player.feet().y);
  EXPECT_LE(deepest, 1e-3f);
  EXPECT_NEAR(player.feet().y, 0.0f, 1e-4f);
  EXPECT_TRUE(player.grounded());
}

// ----- Fast platforms -----

// A 2 m platform the player stands on starts moving at up to 20 m/s (a third of a metre a
// tick): across, up, down (faster than the player would fall for its first second), and back
// and forth with smooth easing. Riding keeps the feet where they
// stood on it: the deviation of their offset from the platform's top, tick to tick, is the
// jitter.
TEST(SimulationExtremes, platforms_at_up_to_20_metres_per_second_carry_the_player_without_jitter) {
  struct Motion {
    const char* name;
    glm::vec3 to;
    game::Mover::Repeat repeat;
    game::Mover::Easing easing;
  };
  const Motion motions[] = {
      {"across at 20 m/s",
       {40.0f, 0.0f, 0.0f},
       game::Mover::Repeat::Once,
       game::Mover::Easing::Linear},
      {"up at 10 m/s", {0.0f, 20.0f, 0.0f}, game::Mover::Repeat::Once, game::Mover::Easing::Linear},
      {"down at 10 m/s",
       {0.0f, -20.0f, 0.0f},
       game::Mover::Repeat::Once,
       game::Mover::Easing::Linear},
      {"back and forth, smooth",
       {20.0f, 0.0f, 10.0f},
       game::Mover::Repeat::PingPong,
       game::Mover::Easing::Smooth},
  };
  for (const Motion& motion : motions) {
    LevelBuilder b({0.0f, 0.0f, 0.0f});
    const glm::vec3 start(0.0f, -0.1f, 0.0f);  // top at y = 0, under the feet
    const uint32_t platform = b.box({2.0f, 0.2f, 2.0f}, start);
    // Still for 2 s with the player standing on it, then 2 s of motion (keyframes are evenly
    // spaced): it starts at full speed under the player's feet.
    game::Mover mover;
    mover.durationSeconds = 4.0f;
    mover.repeat = motion.repeat;
    mover.easing = motion.easing;
    mover.keyframes = {{start}, {start}, {start + motion.to}};
    b.level.entities[platform].mover = mover;
    World world(b.level);
    const auto top = [&] {
      return glm::vec3(world.entityTransform(platform)[3]) + glm::vec3(0.0f, 0.1f, 0.0f);
    };
    world.step({});  // lands
    const glm::vec3 offset = world.feetPosition() - top();
    float jitter = 0.0f, fastest = 0.0f;
    size_t airborne = 0;
    glm::vec3 previousTop = top();
    for (int tick = 2; tick <= 360; ++tick) {
      world.step({});
      fastest = std::max(fastest, glm::length(top() - previousTop) * 60.0f);
      previousTop = top();
      jitter = std::max(jitter, glm::length(world.feetPosition() - top() - offset));
      airborne += !world.grounded();
    }
    std::printf(
        "platform %s (fastest %.1f m/s): jitter %.2g m (limit 1e-3), %zu ticks not "
        "grounded (limit 0)\n",
        motion.name, fastest, jitter, airborne);
    EXPECT_LE(jitter, 1e-3f) << motion.name;
    EXPECT_EQ(airborne, 0u) << motion.name;
  }
}

// ----- Determinism -----

// Two worlds given the same long run of random inputs (walking, turning, jumping, interacting)
// on a shipped level with movers end bit for bit alike, tick by tick.
TEST(SimulationExtremes, random_inputs_for_3000_ticks_give_bit_identical_worlds) {
  const game::Level level = game::loadLevel(kSource / "levels" / "07_crossing.json");
  World first(level), second(level);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> axis(-1.0f, 1.0f);
  size_t mismatches = 0;
  for (int tick = 0; tick < 3000; ++tick) {
    game::TickInput input;
    input.move = {axis(random), axis(random)};
    input.yawDeltaDegrees = 5.0f * axis(random);
    input.pitchDeltaDegrees = 2.0f * axis(random);
    input.jump = axis(random) > 0.9f;
    input.interact = axis(random) > 0.8f;
    input.adjust = axis(random);
    first.step(input);
    second.step(input);
    mismatches += !(stateOf(first) == stateOf(second));
  }
  std::printf("3000 random-input ticks: %zu ticks where the worlds differ (limit 0)\n", mismatches);
  EXPECT_EQ(mismatches, 0u);
}

}  // namespace
