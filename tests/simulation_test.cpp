// The simulation's probe cadence: a probe frame after every k-th tick, its readings reaching
// the rules exactly L probe frames later, identical from run to run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "game/level_loader.hpp"
#include "sim/simulation.hpp"
#include "vulkan_fixture.hpp"

namespace {

class SimulationTest : public test::VulkanTest {
 protected:
  static game::Level firstLevel() {
    return game::loadLevel(test::sourceDir() / "levels" / "01_first_light.json");
  }
};

TEST_F(SimulationTest, readings_arrive_exactly_latency_probe_frames_after_they_were_rendered) {
  const game::Level level = firstLevel();
  for (const auto& [every, latency] : {std::pair{4u, 2u}, std::pair{3u, 0u}, std::pair{1u, 5u}}) {
    sim::Simulation simulation(context(), compiler(), level, {32, 18, every, latency});
    uint32_t arrivals = 0;
    for (int step = 0; step < 40; ++step) {
      game::TickInput input;
      input.move = {0.0f, 1.0f};
      simulation.step(input);
      const uint64_t now = simulation.tick();
      const uint64_t due = uint64_t(latency) * every;
      if (now < std::max<uint64_t>(due, 1)) {
        EXPECT_FALSE(simulation.readingsArrivedThisTick()) << "tick " << now;
        continue;
      }
      // A frame rendered after tick t (t % k == 0) arrives at t + L k; nothing in between.
      const bool expected = (now - due) % every == 0;
      ASSERT_EQ(simulation.readingsArrivedThisTick(), expected)
          << "k " << every << ", L " << latency << ", tick " << now;
      if (expected) {
        EXPECT_EQ(simulation.latestReadings()->tick, now - due);
        ++arrivals;
      }
    }
    EXPECT_GT(arrivals, 5u);
  }
}

TEST_F(SimulationTest, the_same_inputs_give_the_same_readings_and_states) {
  const game::Level level = firstLevel();
  auto run = [&] {
    sim::Simulation simulation(context(), compiler(), level, {32, 18, 2, 1});
    std::vector<float> trace;
    for (int step = 0; step < 60; ++step) {
      game::TickInput input;
      input.move = {0.2f, 1.0f};
      input.yawDeltaDegrees = step < 30 ? 0.3f : -0.2f;
      input.pitchDeltaDegrees = 0.15f;
      simulation.step(input);
      trace.push_back(simulation.world().feetPosition().z);
      if (simulation.latestReadings())
        trace.push_back(simulation.latestReadings()->focusCoverage[0]);
      trace.push_back(simulation.rules().progress()[0].progress);
    }
    return trace;
  };
  EXPECT_EQ(run(), run());
}

}  // namespace

// A hidden entity is seen by no ray: the orb drops out of the focus probe, and the slab that
// shaded the sensor stops casting its shadow (docs/LEVELS.md, "Logic").
TEST_F(SimulationTest, a_hidden_entity_leaves_camera_rays_and_shadow_rays) {
  const game::Level level = game::parseLevel(R"({
    "format": 1, "name": "Hide",
    "camera": { "position": [0, 1.65, 8] },
    "materials": { "paint": {} },
    "meshes": { "floor": { "box": { "size": [40, 1, 40] } }, "ball": { "sphere": { "radius": 0.5 } },
                "plate": { "box": { "size": [1, 0.05, 1] } }, "slab": { "box": { "size": [2, 0.1, 2] } } },
    "entities": {
      "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
      "orb": { "mesh": "ball", "material": "paint", "position": [0, 1.65, 6] },
      "plate": { "mesh": "plate", "material": "paint", "position": [6, 0.03, 0] },
      "slab": { "mesh": "slab", "material": "paint", "position": [6, 1.5, 0] }
    },
    "lights": { "lamp": { "type": "point", "position": [6, 3, 0], "intensity": 5 } },
    "logic": {
      "watch": { "when": { "type": "focus", "orb": "orb" }, "then": [{ "do": "message", "text": "seen" }] },
      "lit": { "when": { "type": "lit", "sensor": "plate", "light": "lamp" }, "then": [{ "do": "message", "text": "lit" }] },
      "hide": { "when": { "type": "timer", "seconds": 0.5 },
                "then": [{ "do": "hide", "entity": "orb" }, { "do": "hide", "entity": "slab" }] }
    } })",
                                             "hide.json");
  sim::Simulation simulation(context(), compiler(), level, {64, 36, 4, 2});
  ASSERT_EQ(simulation.layout().focus.size(), 1u);
  ASSERT_EQ(simulation.layout().exposure.size(), 1u);
  auto runUntil = [&](uint64_t tick) {
    while (simulation.tick() < tick) simulation.step({});
  };
  runUntil(24);  // readings of the world before the rule fired on tick 30
  EXPECT_EQ(simulation.latestReadings()->focusCoverage[0], 1.0f);
  EXPECT_EQ(simulation.latestReadings()->exposure[0], 0.0f);
  EXPECT_EQ(simulation.logic().firings(0), std::vector<uint64_t>{8});  // the first readings
  runUntil(100);
  EXPECT_EQ(simulation.latestReadings()->focusCoverage[0], 0.0f);
  EXPECT_GT(simulation.latestReadings()->exposure[0], 0.99f);
  EXPECT_EQ(simulation.logic().firings(1).size(), 1u);
}

// Feedback in the world: the orb of a focus goal glows as its score rises, so the picture says
// how close the player is without the HUD; the probes do not see the glow.
TEST_F(SimulationTest, an_orb_glows_as_its_focus_score_rises) {
  const game::Level level = game::parseLevel(R"({
    "format": 1, "name": "Glow",
    "camera": { "position": [0, 1.65, 8] },
    "environment": { "ambient": [0.3, 0.3, 0.3] },
    "materials": { "paint": { "color": [0.2, 0.5, 0.9] } },
    "meshes": { "ball": { "sphere": { "radius": 0.6 } }, "floor": { "box": { "size": [20, 1, 20] } } },
    "entities": { "orb": { "mesh": "ball", "material": "paint", "position": [0, 1.65, 6] },
                  "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] } },
    "goal": { "type": "focus", "orb": "orb", "rise_per_second": 0.5 } })",
                                             "glow.json");
  sim::Simulation simulation(context(), compiler(), level, {64, 36, 4, 2});
  auto centreGreen = [&] {
    const std::vector<uint8_t>& pixels = simulation.renderPicture();
    return int(pixels[(18 * 64 + 32) * 4 + 1]);
  };
  const int before = centreGreen();
  while (simulation.tick() < 67) simulation.step({});  // readings from tick 8: 60 ticks of focus
  EXPECT_NEAR(simulation.rules().progress()[0].progress, 0.5f, 1e-6f);
  const int during = centreGreen();
  EXPECT_GT(during, before + 40) << "before " << before << ", at half the score " << during;
  EXPECT_EQ(simulation.latestReadings()->focusCoverage[0], 1.0f);  // the glow counts for nothing
}

namespace {

// A lamp 3 m up over a plate, half shaded by a slab 1 m up; the lamp rides a bulb that crosses
// from x = -3 to 3 in one second (or stands where the bulb is at `tick`).
std::string sweepingLampLevel(std::optional<int> standingAtTick) {
  const bool moving = !standingAtTick;
  const float x = moving ? -3.0f : -3.0f + 6.0f * float(std::min(*standingAtTick, 60)) / 60.0f;
  const std::string position = "[" + std::to_string(x) + ", 3, 0]";
  const std::string mover =
      moving ? R"(, "mover": { "duration_seconds": 1, "repeat": "once", "easing": "linear",
                              "keyframes": [ { "position": [-3, 3, 0] }, { "position": [3, 3, 0] } ] })"
             : "";
  return R"({
    "format": 1, "name": "Sweep",
    "camera": { "position": [0, 1.65, 8] },
    "materials": { "paint": {} },
    "meshes": { "floor": { "box": { "size": [40, 1, 40] } }, "plate": { "box": { "size": [2, 0.05, 2] } },
                "slab": { "box": { "size": [1, 0.1, 3] } }, "bulb": { "sphere": { "radius": 0.1 } } },
    "entities": {
      "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
      "plate": { "mesh": "plate", "material": "paint", "position": [0, 0.025, 0] },
      "slab": { "mesh": "slab", "material": "paint", "position": [0, 1, 0] },
      "bulb": { "mesh": "bulb", "material": "paint", "position": )" +
         position + R"(, "casts_shadow": false)" + mover + R"( } },
    "lights": { "lamp": { "type": "point", "position": )" +
         position + R"(, "intensity": 5, "rides": "bulb" } },
    "goal": { "type": "lit", "sensor": "plate", "light": "lamp", "threshold": 1 }
  })";
}

}  // namespace

// A light that rides a mover is where the mover is on every tick: with a probe frame after
// each tick, the reading each frame adds to the filter over probe frames is what the lamp
// standing at that tick's place reads, and the readings change as the shadow sweeps.
TEST_F(SimulationTest, probe_values_follow_a_moving_light_tick_for_tick) {
  auto fixed = [](float reading) { return int64_t(std::llround(double(reading) * 65536.0)); };
  const game::Level moving = game::parseLevel(sweepingLampLevel(std::nullopt), "sweep.json");
  sim::Simulation simulation(context(), compiler(), moving, {32, 18, 1, 0});
  std::vector<int64_t> filtered;  // 16.16, as the simulation keeps it
  for (int tick = 0; tick <= 60; ++tick) {
    if (tick > 0) simulation.step({});
    ASSERT_EQ(simulation.latestReadings()->tick, uint64_t(tick));
    filtered.push_back(fixed(simulation.latestReadings()->exposure[0]));
    if (tick % 6 != 0) continue;  // every tenth of a second against a standing lamp
    const game::Level standing = game::parseLevel(sweepingLampLevel(tick), "sweep.json");
    sim::Simulation still(context(), compiler(), standing, {32, 18, 1, 0});
    const int64_t raw = fixed(still.latestReadings()->exposure[0]);  // the first: unfiltered
    if (tick == 0) {
      EXPECT_EQ(filtered[0], raw);
      continue;
    }
    // filtered = floor((previous + raw) / 2): the raw reading this frame added.
    const int64_t added = 2 * filtered[size_t(tick)] - filtered[size_t(tick) - 1];
    EXPECT_TRUE(raw == added || raw == added + 1) << "tick " << tick << ": the standing lamp reads "
                                                  << raw << ", the moving one added " << added;
  }
  // The shadow sweeps across the plate: most of it is shaded with the lamp overhead.
  const auto [least, most] = std::minmax_element(filtered.begin(), filtered.end());
  EXPECT_GT(*most - *least, 65536 / 10);
}

namespace {

// A low lamp, a board behind the player (the lamp, the player and the board on a line when the
// player stands at the origin), and a stealth rule that only reads the player's exposure.
game::Level bodyLevel(const std::string& camera) {
  return game::parseLevel(R"({
    "format": 1, "name": "Body",
    "camera": )" + camera + R"(,
    "materials": { "paint": {} },
    "meshes": { "floor": { "box": { "size": [40, 1, 40] } }, "board": { "box": { "size": [1.2, 1.6, 0.05] } } },
    "entities": {
      "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
      "board": { "mesh": "board", "material": "paint", "position": [0, 0.9, 2.5] }
    },
    "lights": { "lamp": { "type": "point", "position": [0, 1, -4], "intensity": 40 } },
    "goal": { "type": "lit", "sensor": "board", "light": "lamp" },
    "lose": [ { "type": "stealth", "watcher": "lamp", "exposure_limit": 1, "seconds": 100 } ]
  })",
                          "body.json");
}

}  // namespace

// The player's body casts the shadow the rules measure: standing between the lamp and the board
// it shades the board's probe and the board on screen alike (a 33 x 19 picture: the board's
// row through its centre spans columns 13 to 19, the body's shadow 14 to 18), while the player's
// own exposure (sample points on the body) is not shaded by the body itself.
TEST_F(SimulationTest, the_player_body_shades_the_board_on_screen_and_in_its_probe) {
  struct Seen {
    float board, player;
    int centre, edge;  // green bytes on screen: the board's centre, and its left edge
  };
  auto look = [&](const std::string& camera) {
    const game::Level level = bodyLevel(camera);
    sim::Simulation simulation(context(), compiler(), level, {33, 19, 1, 0});
    const std::vector<uint8_t>& pixels = simulation.renderPicture();
    return Seen{simulation.latestReadings()->exposure[0], simulation.latestReadings()->exposure[1],
                pixels[(9 * 33 + 16) * 4 + 1], pixels[(9 * 33 + 13) * 4 + 1]};
  };
  // Both cameras look at the board's centre (0, 0.9, 2.5).
  const Seen between =
      look(R"({ "position": [0, 1.65, 0], "yaw_degrees": 180, "pitch_degrees": -16.7 })");
  const Seen aside =
      look(R"({ "position": [3, 1.65, 0], "yaw_degrees": 129.8, "pitch_degrees": -10.9 })");
  EXPECT_EQ(aside.board, 1.0f);
  EXPECT_LT(between.board, 0.8f);  // the body's shadow covers part of the board
  EXPECT_GT(between.board, 0.2f);
  EXPECT_EQ(between.player, 1.0f);  // its own probe rays pass through the body
  EXPECT_EQ(aside.player, 1.0f);
  // On screen the body's shadow darkens the board's centre; its edge stays lit. (A sensor glows
  // with its reading, evenly, so the shadow is not black.)
  EXPECT_GT(between.edge - between.centre, 20);
  EXPECT_LT(between.centre, aside.centre - 20);
}

// Camera rays from the eye pass through the body (looking down, the floor is seen); rays that
// come back from a mirror meet it.
TEST_F(SimulationTest, the_player_body_shows_in_a_mirror_but_not_from_the_eye) {
  auto centreInstance = [&](const std::string& camera) {
    const game::Level level = game::parseLevel(R"({
      "format": 1, "name": "Mirror",
      "camera": )" + camera + R"(,
      "materials": { "paint": {}, "silver": { "mirror": { "reflectance": 1 } } },
      "meshes": { "floor": { "box": { "size": [40, 1, 40] } }, "mirror": { "box": { "size": [2, 2.5, 0.05] } } },
      "entities": {
        "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
        "mirror": { "mesh": "mirror", "material": "silver", "position": [0, 1.25, -2] }
      },
      "lights": { "lamp": { "type": "point", "position": [0, 3, 0], "intensity": 5 } }
    })",
                                               "mirror.json");
    sim::Simulation simulation(context(), compiler(), level, {33, 19, 1, 0});
    simulation.renderPicture();
    return simulation.renderer().pixelPaths()[9 * 33 + 16].finalInstance;
  };
  const uint32_t floor = 0, body = 2;  // the body comes after the level's entities
  EXPECT_EQ(centreInstance(R"({ "position": [0, 1.65, 0] })"), body);
  EXPECT_EQ(centreInstance(R"({ "position": [0, 1.65, 0], "pitch_degrees": -89 })"), floor);
}
