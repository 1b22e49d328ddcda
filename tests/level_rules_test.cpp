// Goals, lose conditions and the level outcome, tick by tick.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "game/level.hpp"
#include "game/primitives.hpp"
#include "game/probes.hpp"
#include "game/rules.hpp"
#include "game/world.hpp"

namespace {

using game::Goal;
using game::LoseCondition;
using game::Outcome;

// A floor, an orb, a sensor and a lamp; the player stands at the origin.
game::Level baseLevel(bool withFloor = true) {
  game::Level level;
  level.camera.position = {0.0f, 1.65f, 0.0f};
  level.meshes.push_back(game::primitives::box({40.0f, 0.1f, 40.0f}));
  for (const char* id : {"floor", "orb", "sensor"}) {
    game::Entity entity;
    entity.id = id;
    entity.position = {0.0f, -0.05f, id[0] == 'f' ? 0.0f : -30.0f};
    level.entities.push_back(entity);
  }
  if (!withFloor) level.entities[0].position.y = -1000.0f;
  level.lights.push_back({});
  level.lightIds.push_back("lamp");
  return level;
}

Goal focus(float rise = 0.5f, float fall = 0.25f) {
  Goal goal{Goal::Type::Focus};
  goal.entity = 1;
  goal.coverage = 0.5f;
  goal.risePerSecond = rise;
  goal.fallPerSecond = fall;
  return goal;
}

Goal lit(float holdSeconds) {
  Goal goal{Goal::Type::Lit};
  goal.entity = 2;
  goal.threshold = 0.5f;
  goal.holdSeconds = holdSeconds;
  return goal;
}

Goal reach(const glm::vec3& min, const glm::vec3& max) {
  Goal goal{Goal::Type::Reach};
  goal.min = min;
  goal.max = max;
  return goal;
}

Goal combine(Goal::Type type, std::vector<Goal> children) {
  Goal goal{type};
  goal.children = std::move(children);
  return goal;
}

// Runs world and rules together; readings(tick) gives the probe values for each tick (fed every
// tick, as if probes were instant).
struct Session {
  game::Level level;
  game::ProbeLayout layout;
  game::World world;
  game::Rules rules;
  explicit Session(game::Level lvl)
      : level(std::move(lvl)),
        layout(game::probeLayout(level)),
        world(level),
        rules(level, layout) {}

  template <typename Readings>
  void run(uint64_t ticks, Readings readings) {
    for (uint64_t i = 0; i < ticks && rules.outcome() == Outcome::Playing; ++i) {
      world.step({});
      game::ProbeReadings probe = readings(world.tick());
      probe.tick = world.tick();
      rules.update(world.tick(), world, &probe);
    }
  }
  game::ProbeReadings values(std::vector<float> focus, std::vector<float> exposure) const {
    return {0, std::move(focus), std::move(exposure)};
  }
};

TEST(Rules, FocusRisesToWinOnTheExactTick) {
  game::Level level = baseLevel();
  level.goal = focus(0.5f);
  Session s(level);
  s.run(119, [&](uint64_t) { return s.values({0.6f}, {}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Playing);
  EXPECT_NEAR(s.rules.progress()[0].progress, 119.0f / 120.0f, 1e-6f);
  s.run(1, [&](uint64_t) { return s.values({0.5f}, {}); });  // coverage ≥ goal: still rising
  EXPECT_EQ(s.rules.outcome(), Outcome::Won);
  EXPECT_EQ(s.rules.outcomeTick(), 120u);
  EXPECT_EQ(s.rules.reason(), "Hold \"orb\" in view: met");
}

TEST(Rules, FocusFallsWhileUncoveredAndKeepsTheLastReadings) {
  game::Level level = baseLevel();
  level.goal = focus(1.0f, 0.25f);
  Session s(level);
  s.run(30, [&](uint64_t) { return s.values({1.0f}, {}); });  // score 0.5
  EXPECT_NEAR(s.rules.progress()[0].progress, 0.5f, 1e-6f);
  s.run(60, [&](uint64_t) { return s.values({0.49f}, {}); });  // −0.25
  EXPECT_NEAR(s.rules.progress()[0].progress, 0.25f, 1e-6f);
  // New readings only once; the rules keep using them: 45 more ticks to 1.
  s.world.step({});
  const game::ProbeReadings covered = s.values({0.9f}, {});
  s.rules.update(s.world.tick(), s.world, &covered);
  for (int i = 0; i < 60 && s.rules.outcome() == Outcome::Playing; ++i) {
    s.world.step({});
    s.rules.update(s.world.tick(), s.world, nullptr);
  }
  EXPECT_EQ(s.rules.outcome(), Outcome::Won);
  EXPECT_EQ(s.rules.outcomeTick(), 135u);
}

TEST(Rules, FocusNotMetBeforeAnyReadings) {
  game::Level level = baseLevel();
  level.goal = focus(10.0f);
  Session s(level);
  for (int i = 0; i < 120; ++i) {
    s.world.step({});
    s.rules.update(s.world.tick(), s.world, nullptr);
  }
  EXPECT_EQ(s.rules.outcome(), Outcome::Playing);
  EXPECT_EQ(s.rules.progress()[0].progress, 0.0f);
}

TEST(Rules, LitMustHoldContinuously) {
  game::Level level = baseLevel();
  level.goal = lit(0.5f);  // 30 ticks
  Session s(level);
  s.run(100, [&](uint64_t tick) { return s.values({}, {tick == 21 ? 0.49f : 0.5f}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Won);
  EXPECT_EQ(s.rules.outcomeTick(), 22u + 29u);  // the run restarts at tick 22
  EXPECT_EQ(s.rules.reason(), "Light \"sensor\" with \"lamp\": met");
}

TEST(Rules, LitHoldRoundsUpToWholeTicks) {
  for (const auto& [hold, tick] :
       std::vector<std::pair<float, uint64_t>>{{0.0f, 1}, {0.1f, 6}, {0.11f, 7}, {2.0f, 120}}) {
    game::Level level = baseLevel();
    level.goal = lit(hold);
    Session s(level);
    s.run(200, [&](uint64_t) { return s.values({}, {1.0f}); });
    EXPECT_EQ(s.rules.outcome(), Outcome::Won) << hold;
    EXPECT_EQ(s.rules.outcomeTick(), tick) << hold;
  }
}

TEST(Rules, ReachNeedsTheFeetInsideTheBox) {
  game::Level level = baseLevel();
  level.goal = reach({-1, -1, -1}, {1, 1, 1});
  Session inside(level);
  inside.run(10, [&](uint64_t) { return inside.values({}, {}); });
  EXPECT_EQ(inside.rules.outcome(), Outcome::Won);
  EXPECT_EQ(inside.rules.outcomeTick(), 1u);

  level.goal = reach({2, -1, -1}, {3, 1, 1});
  Session outside(level);
  outside.run(120, [&](uint64_t) { return outside.values({}, {}); });
  EXPECT_EQ(outside.rules.outcome(), Outcome::Playing);
  EXPECT_FALSE(outside.rules.progress()[0].met);
}

TEST(Rules, ReachProgressIsTheShareOfTheWayCovered) {
  game::Level level = baseLevel();
  level.goal = reach({-1, -1, -9}, {1, 1, -8});  // 8 m ahead of the player's feet
  game::World world(level);
  game::Rules rules(level, game::probeLayout(level));
  game::TickInput forward;
  forward.move = {0.0f, 1.0f};
  const game::ProbeReadings none{};
  world.step({});
  rules.update(world.tick(), world, &none);
  EXPECT_FLOAT_EQ(rules.progress()[0].progress, 0.0f);
  for (int tick = 0; tick < 60; ++tick) {  // one second at 4 m/s: half the way
    world.step(forward);
    rules.update(world.tick(), world, &none);
  }
  EXPECT_NEAR(rules.progress()[0].progress, 0.5f, 0.01f);
  EXPECT_EQ(rules.outcome(), Outcome::Playing);
}

TEST(Rules, StealthLosesAfterSecondsAboveTheLimit) {
  game::Level level = baseLevel();
  LoseCondition stealth{LoseCondition::Type::Stealth};
  stealth.exposureLimit = 0.2f;
  stealth.seconds = 1.5f;  // 90 ticks
  level.lose = {stealth};
  Session s(level);
  // At the limit is not above it; a dip restarts the count.
  s.run(300, [&](uint64_t tick) {
    return s.values({}, {tick <= 100 ? 0.2f : (tick == 150 ? 0.1f : 0.21f)});
  });
  EXPECT_EQ(s.rules.outcome(), Outcome::Lost);
  EXPECT_EQ(s.rules.outcomeTick(), 151u + 89u);
  EXPECT_EQ(s.rules.reason(), "Seen by \"lamp\"");
}

TEST(Rules, FallingBelowLoses) {
  game::Level level = baseLevel(false);
  LoseCondition fall{LoseCondition::Type::Fall};
  fall.below = -1.0f;
  level.lose = {fall};
  Session s(level);
  s.run(100, [&](uint64_t) { return s.values({}, {}); });
  // Semi-implicit Euler from rest: y(n) = −g·dt²·n(n+1)/2 first drops below −1 at n = 27.
  EXPECT_EQ(s.rules.outcome(), Outcome::Lost);
  EXPECT_EQ(s.rules.outcomeTick(), 27u);
  EXPECT_EQ(s.rules.reason(), "Fell");
}

TEST(Rules, a_level_label_names_the_goal_and_the_loss_in_the_players_words) {
  game::Level level = baseLevel(false);
  LoseCondition fall{LoseCondition::Type::Fall};
  fall.below = -1.0f;
  fall.label = "Fell off the ledge";
  level.lose = {fall};
  level.goal = focus(1.0f, 0.0f);
  level.goal->label = "Hold the orb in view";
  Session s(level);
  EXPECT_EQ(s.rules.progress()[0].label, "Hold the orb in view");
  s.run(100, [&](uint64_t) { return s.values({}, {}); });
  EXPECT_EQ(s.rules.reason(), "Fell off the ledge");
}

TEST(Rules, AllNeedsEveryChildOnTheSameTick) {
  game::Level level = baseLevel();
  level.goal = combine(Goal::Type::All, {focus(1.0f, 0.0f), lit(1.0f)});
  Session s(level);
  // Focus met from tick 60; lit exposure from tick 31, held 60 ticks: met from tick 90.
  s.run(200, [&](uint64_t tick) { return s.values({1.0f}, {tick > 30 ? 1.0f : 0.0f}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Won);
  EXPECT_EQ(s.rules.outcomeTick(), 90u);
  ASSERT_EQ(s.rules.progress().size(), 3u);
  EXPECT_EQ(s.rules.progress()[0].label, "All 2 of these");
  EXPECT_TRUE(s.rules.progress()[1].met);
  EXPECT_EQ(s.rules.reason(), "All 2 of these: met");
}

TEST(Rules, AllIsNotWonByChildrenMetAtDifferentTimes) {
  game::Level level = baseLevel();
  level.goal = combine(Goal::Type::All, {focus(1.0f, 0.0f), lit(0.0f)});
  Session s(level);
  // Lit only on ticks 1..30; focus met from tick 60.
  s.run(200, [&](uint64_t tick) { return s.values({1.0f}, {tick <= 30 ? 1.0f : 0.0f}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Playing);
  EXPECT_NEAR(s.rules.progress()[0].progress, 0.5f, 1e-6f);  // mean of the children

  level.goal = combine(Goal::Type::Any, {focus(1.0f, 0.0f), lit(0.0f)});
  Session any(level);
  any.run(200, [&](uint64_t tick) { return any.values({1.0f}, {tick <= 30 ? 1.0f : 0.0f}); });
  EXPECT_EQ(any.rules.outcome(), Outcome::Won);
  EXPECT_EQ(any.rules.outcomeTick(), 1u);
}

TEST(Rules, AnyWinsWithTheFirstChild) {
  game::Level level = baseLevel();
  level.goal =
      combine(Goal::Type::Any,
              {focus(1.0f), combine(Goal::Type::All, {lit(0.5f), reach({-1, -1, -1}, {1, 1, 1})})});
  Session s(level);
  s.run(200, [&](uint64_t) { return s.values({0.0f}, {1.0f}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Won);
  EXPECT_EQ(s.rules.outcomeTick(), 30u);
  ASSERT_EQ(s.rules.progress().size(), 5u);  // any, focus, all, lit, reach
  EXPECT_EQ(s.rules.progress()[0].label, "Any one of 2");
  EXPECT_EQ(s.rules.progress()[4].label, "Reach the goal");
  EXPECT_FALSE(s.rules.progress()[1].met);
  EXPECT_TRUE(s.rules.progress()[2].met);
}

TEST(Rules, LostTakesPrecedenceOnTheSameTick) {
  game::Level level = baseLevel();
  level.goal = focus(1.0f);  // met on tick 60
  LoseCondition stealth{LoseCondition::Type::Stealth};
  stealth.exposureLimit = 0.5f;
  stealth.seconds = 1.0f;  // lost on tick 60
  level.lose = {stealth};
  Session s(level);
  s.run(200, [&](uint64_t) { return s.values({1.0f}, {1.0f}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Lost);
  EXPECT_EQ(s.rules.outcomeTick(), 60u);
  // The outcome is final.
  const game::ProbeReadings calm = s.values({1.0f}, {0.0f});
  s.world.step({});
  s.rules.update(s.world.tick(), s.world, &calm);
  EXPECT_EQ(s.rules.outcome(), Outcome::Lost);
  EXPECT_EQ(s.rules.outcomeTick(), 60u);
}

TEST(Rules, SandboxNeverWins) {
  game::Level level = baseLevel();
  Session s(level);
  s.run(600, [&](uint64_t) { return s.values({}, {}); });
  EXPECT_EQ(s.rules.outcome(), Outcome::Playing);
  EXPECT_TRUE(s.rules.sandbox());
  EXPECT_TRUE(s.rules.progress().empty());
}

TEST(Rules, MismatchedLayoutThrows) {
  game::Level level = baseLevel();
  level.goal = focus();
  EXPECT_THROW(game::Rules(level, game::ProbeLayout{}), std::invalid_argument);
}

}  // namespace
