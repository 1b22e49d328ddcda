// The simulation's probe cadence: a probe frame after every k-th tick, its readings reaching
// the rules exactly L probe frames later, identical from run to run.
#include <gtest/gtest.h>

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
