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
