// Level logic without Vulkan: rules read from JSON, run against the World tick by tick with
// probe readings supplied by the test (docs/LEVELS.md, "Logic").
#include <gtest/gtest.h>

#include <string>

#include "game/level_loader.hpp"
#include "game/logic.hpp"
#include "game/probes.hpp"
#include "game/rules.hpp"
#include "game/world.hpp"

namespace {

// A floor, a door that waits, a lever (switch for "lamp") and a shade (slide), and the rules.
game::Level levelWithRules(const std::string& logic, const std::string& lose = "[]") {
  const std::string text = R"({
    "format": 1, "name": "Logic",
    "camera": { "position": [0, 1.65, 8] },
    "materials": { "paint": {} },
    "meshes": { "floor": { "box": { "size": [40, 1, 40] } }, "cube": { "box": { "size": [1, 1, 1] } } },
    "entities": {
      "floor": { "mesh": "floor", "material": "paint", "position": [0, -0.5, 0] },
      "door": { "mesh": "cube", "material": "paint", "position": [0, 0.5, -5],
                "mover": { "duration_seconds": 1, "repeat": "once", "starts_playing": false,
                           "keyframes": [ { "position": [0, 0.5, -5] }, { "position": [0, 2.5, -5] },
                                          { "position": [0, 4.5, -5] } ] } },
      "lever": { "mesh": "cube", "material": "paint", "position": [0, 1.5, 6.5],
                 "interactable": { "type": "switch", "light": "lamp", "starts_on": false } },
      "shade": { "mesh": "cube", "material": "paint", "position": [5, 0.5, 0],
                 "interactable": { "type": "slide", "axis": [1, 0, 0], "min": 0, "max": 2 } }
    },
    "lights": { "lamp": { "type": "point", "position": [0, 3, 0], "intensity": 5 } },
    "lose": )" + lose + R"(,
    "logic": )" + logic + "}";
  return game::parseLevel(text, "logic_test.json");
}

// The world, its rules and its logic, stepped the way the simulation steps them.
struct LogicRun {
  explicit LogicRun(const game::Level& level)
      : world(level),
        layout(game::probeLayout(level)),
        rules(level, layout),
        logic(level, layout) {}

  void step(const game::PlayerInput& input = {}, const game::ProbeReadings* readings = nullptr) {
    world.step(input);
    logic.update(world.tick(), world, readings);
    rules.update(world.tick(), world, readings);
    if (const auto decided = logic.outcome())
      rules.decide(*decided, logic.outcomeTick(), logic.reason());
  }
  void steps(int count) {
    for (int i = 0; i < count; ++i) step();
  }
  float doorHeight() const { return world.entityTransform(1)[3].y; }

  game::World world;
  game::ProbeLayout layout;
  game::Rules rules;
  game::Logic logic;
};

const std::string kInsideStart = R"({ "type": "inside", "min": [-1, -1, 7], "max": [1, 1, 9] })";

TEST(LevelLogic, a_waiting_door_stays_shut_until_a_rule_plays_it) {
  const game::Level level = levelWithRules(R"({
    "open": { "when": { "type": "timer", "seconds": 0.5 }, "then": [{ "do": "play", "mover": "door" }] } })");
  LogicRun run(level);
  run.steps(29);
  EXPECT_EQ(run.doorHeight(), 0.5f);  // still at its first keyframe
  EXPECT_TRUE(run.logic.firings(0).empty());
  run.step();  // tick 30 = 0.5 s: fires; the door moves from the next step
  EXPECT_EQ(run.logic.firings(0), std::vector<uint64_t>{30});
  run.steps(60 + 2);
  EXPECT_EQ(run.doorHeight(), 4.5f);  // at the end of its path, and it stays there
}

TEST(LevelLogic, goto_runs_a_mover_to_its_keyframe_and_stops_there) {
  const game::Level level = levelWithRules(R"({
    "half": { "when": { "type": "timer", "seconds": 0 }, "then": [{ "do": "goto", "mover": "door", "keyframe": 1 }] } })");
  LogicRun run(level);
  run.steps(200);
  EXPECT_NEAR(run.doorHeight(), 2.5f, 1e-6f);
  EXPECT_EQ(run.world.moverDirection(1), 0);
}

TEST(LevelLogic, a_while_rule_holds_the_door_open_only_while_the_player_stands_on_the_plate) {
  const game::Level level =
      levelWithRules(R"({
    "plate": { "fires": "while", "when": )" +
                     kInsideStart + R"(, "then": [{ "do": "play", "mover": "door" }] } })");
  LogicRun run(level);
  run.steps(90);  // the player spawns on the plate
  EXPECT_EQ(run.doorHeight(), 4.5f);
  EXPECT_EQ(run.logic.firings(0).size(), 1u);
  run.world.respawnPlayer({10, 0, 0}, 0);  // off the plate: the door closes again
  run.steps(90);
  EXPECT_EQ(run.doorHeight(), 0.5f);
  EXPECT_FALSE(run.logic.holding(0));
}

TEST(LevelLogic, once_fires_on_the_first_entry_and_repeat_on_every_entry) {
  const game::Level level =
      levelWithRules(R"({
    "first": { "when": )" +
                     kInsideStart +
                     R"(, "then": [{ "do": "light_toggle", "light": "lamp" }] },
    "every": { "fires": "repeat", "when": )" +
                     kInsideStart + R"(, "then": [{ "do": "message", "text": "again" }] } })");
  LogicRun run(level);
  for (int entry = 0; entry < 3; ++entry) {
    run.world.respawnPlayer({0, 0, 8}, 0);
    run.steps(5);
    run.world.respawnPlayer({10, 0, 0}, 0);
    run.steps(5);
  }
  EXPECT_EQ(run.logic.firings(0), std::vector<uint64_t>{1});
  EXPECT_EQ(run.logic.firings(1), (std::vector<uint64_t>{1, 11, 21}));
}

TEST(LevelLogic, hold_seconds_counts_whole_ticks_and_fired_and_timer_since_chain_rules) {
  const game::Level level = levelWithRules(R"({
    "stood": { "when": { "type": "inside", "min": [-1, -1, 7], "max": [1, 1, 9], "hold_seconds": 0.5 },
               "then": [{ "do": "message", "text": "stood" }] },
    "after": { "when": { "type": "timer", "seconds": 1, "since": "stood" }, "then": [{ "do": "lock", "entity": "lever" }] },
    "chain": { "when": { "type": "all", "of": [{ "type": "fired", "rule": "after" },
                                              { "type": "not", "of": { "type": "fired", "rule": "nothing" } }] },
               "then": [{ "do": "hide", "entity": "door" }] },
    "nothing": { "when": { "type": "timer", "seconds": 1000 }, "then": [{ "do": "win" }] } })");
  LogicRun run(level);
  run.steps(200);
  EXPECT_EQ(run.logic.firings(0), std::vector<uint64_t>{30});  // 30 ticks on the plate: 1..30
  EXPECT_EQ(run.logic.firings(1), std::vector<uint64_t>{90});  // 60 ticks after
  EXPECT_EQ(run.logic.firings(2), std::vector<uint64_t>{90});  // "after" comes first in the file
  EXPECT_TRUE(run.world.locked(2));
  EXPECT_FALSE(run.world.visible(1));
  EXPECT_EQ(run.logic.message(40), std::optional<std::string>("stood"));
  EXPECT_EQ(run.logic.message(30 + 180), std::nullopt);  // shown for the default 3 s
}

TEST(LevelLogic, a_hidden_entity_is_not_collided_with) {
  const game::Level level = levelWithRules(R"({
    "drop": { "when": { "type": "timer", "seconds": 1 }, "then": [{ "do": "hide", "entity": "floor" }] } })");
  LogicRun run(level);
  run.steps(59);
  EXPECT_NEAR(run.world.feetPosition().y, 0.0f, 1e-6f);
  run.steps(30);
  EXPECT_LT(run.world.feetPosition().y, -0.5f);  // falling through where the floor was
}

TEST(LevelLogic, a_locked_switch_cannot_be_used) {
  const std::string rule = R"({
    "lock": { "when": { "type": "timer", "seconds": 0 }, "then": [{ "do": "lock", "entity": "lever" }] } })";
  for (const bool locked : {false, true}) {
    const game::Level level = levelWithRules(locked ? rule : "{}");
    LogicRun run(level);
    run.steps(2);
    game::PlayerInput press;
    press.interact = true;  // the lever is straight ahead, 1.5 m away at eye height
    run.step(press);
    EXPECT_EQ(run.world.lightEnabled(0), !locked) << "locked " << locked;
    EXPECT_EQ(run.world.switchOn(2), !locked);
  }
}

TEST(LevelLogic, a_respawn_point_turns_a_fall_into_a_return) {
  const std::string logic = R"({
    "drop": { "when": { "type": "timer", "seconds": 0.2 }, "then": [{ "do": "hide", "entity": "floor" }] },
    "save": { "when": { "type": "timer", "seconds": 0 },
              "then": [{ "do": "set_respawn", "position": [20, 5, 0], "yaw_degrees": 90 }] } })";
  const game::Level level = levelWithRules(logic, R"([{ "type": "fall", "below": -2 }])");
  LogicRun run(level);
  run.steps(120);
  EXPECT_EQ(run.rules.outcome(), game::Outcome::Playing);
  EXPECT_GT(run.world.feetPosition().x, 19.0f);
  EXPECT_FLOAT_EQ(run.world.yawDegrees(), 90.0f);
  // Without the respawn point the same fall loses the level.
  const game::Level without = levelWithRules(
      R"({ "drop": { "when": { "type": "timer", "seconds": 0.2 }, "then": [{ "do": "hide", "entity": "floor" }] } })",
      R"([{ "type": "fall", "below": -2 }])");
  LogicRun lost(without);
  lost.steps(120);
  EXPECT_EQ(lost.rules.outcome(), game::Outcome::Lost);
}

TEST(LevelLogic, lose_wins_over_win_on_the_same_tick) {
  const game::Level level = levelWithRules(R"({
    "win": { "when": { "type": "timer", "seconds": 1 }, "then": [{ "do": "win" }] },
    "lose": { "when": { "type": "timer", "seconds": 1 }, "then": [{ "do": "lose", "reason": "too slow" }] } })");
  LogicRun run(level);
  run.steps(61);
  EXPECT_EQ(run.rules.outcome(), game::Outcome::Lost);
  EXPECT_EQ(run.rules.outcomeTick(), 60u);
  EXPECT_EQ(run.rules.reason(), "too slow");
}

TEST(LevelLogic, probe_conditions_read_their_own_probes_after_the_goals) {
  const game::Level level = levelWithRules(R"({
    "lit": { "when": { "type": "lit", "sensor": "door", "light": "lamp", "threshold": 0.5 },
             "then": [{ "do": "message", "text": "lit" }] },
    "seen": { "when": { "type": "seen", "watcher": "lamp", "threshold": 0.25 },
              "then": [{ "do": "message", "text": "seen" }] } })",
                                           R"([{ "type": "stealth", "watcher": "lamp" }])");
  LogicRun run(level);
  ASSERT_EQ(run.layout.exposure.size(), 3u);  // the stealth condition's, then the rules'
  EXPECT_EQ(run.layout.firstLogicExposure, 1u);
  game::ProbeReadings readings;
  readings.exposure = {0.0f, 0.5f, 0.2f};
  run.step({}, &readings);
  EXPECT_EQ(run.logic.firings(0).size(), 1u);
  EXPECT_TRUE(run.logic.firings(1).empty());  // 0.2 is not above 0.25
  readings.exposure = {0.0f, 0.5f, 0.3f};
  run.step({}, &readings);
  EXPECT_EQ(run.logic.firings(1).size(), 1u);
}

TEST(LevelLogic, a_slide_condition_fires_when_the_player_pulls_the_slider_far_enough) {
  const game::Level level = levelWithRules(R"({
    "open": { "when": { "type": "slide", "entity": "shade", "min": 0.5, "max": 2 },
              "then": [{ "do": "play", "mover": "door" }] } })");
  LogicRun run(level);
  run.world.respawnPlayer({5, 0, 2.5}, 0);  // 2.5 m in front of the shade
  game::PlayerInput look;
  look.pitchDeltaDegrees = -25.0f;  // down onto it
  run.step(look);
  game::PlayerInput pull;
  pull.interact = true;
  pull.adjust = 1.0f;  // 1 m/s along the rail
  for (int tick = 0; tick < 40; ++tick) run.step(pull);
  EXPECT_NEAR(run.world.interactableValue(3), 40.0f / 60.0f, 1e-5f);
  ASSERT_EQ(run.logic.firings(0).size(), 1u);
  EXPECT_NEAR(double(run.logic.firings(0)[0]), 1.0 + 30.0, 1.0);  // at 0.5 m, 30 ticks in
}

}  // namespace
