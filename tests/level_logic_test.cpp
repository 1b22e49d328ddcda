// Level logic without Vulkan: rules read from JSON, run against the World tick by tick with
// probe readings supplied by the test (docs/LEVELS.md, "Logic").
#include <gtest/gtest.h>

#include <string>

#include "game/author_view.hpp"
#include "game/level_loader.hpp"
#include "game/logic.hpp"
#include "game/probes.hpp"
#include "game/rules.hpp"
#include "game/solution_steps.hpp"
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

// A rule's lit and seen meters on the HUD read the author's words where the condition has a
// label, the ids otherwise.
TEST(LevelLogic, lit_and_seen_conditions_name_their_meters_with_the_label) {
  const game::Level level = levelWithRules(R"({
    "lit": { "when": { "type": "lit", "label": "The door sees the lamp", "sensor": "door",
                       "light": "lamp" },
             "then": [{ "do": "message", "text": "lit" }] },
    "seen": { "when": { "type": "seen", "label": "Seen by the lamp", "watcher": "lamp" },
              "then": [{ "do": "message", "text": "seen" }] },
    "plain": { "when": { "type": "seen", "watcher": "lamp" },
               "then": [{ "do": "message", "text": "plain" }] } })");
  const game::ProbeLayout layout = game::probeLayout(level);
  ASSERT_EQ(layout.exposure.size(), 3u);
  EXPECT_EQ(layout.exposure[0].label, "The door sees the lamp");
  EXPECT_EQ(layout.exposure[1].label, "Seen by the lamp");
  EXPECT_EQ(layout.exposure[2].label, "Seen by \"lamp\"");
  EXPECT_THROW(levelWithRules(R"({ "empty": { "when": { "type": "seen", "label": "",
      "watcher": "lamp" }, "then": [{ "do": "message", "text": "x" }] } })"),
               game::LevelError);
}

// With more meters than rows the HUD shows a watcher's first, then those reading something,
// then the rest, each measurement once, in the layout's order.
TEST(LevelLogic, the_hud_shows_watchers_then_meters_that_read_something_each_once) {
  using Probe = game::ExposureProbe;
  auto lit = [](const char* label) { return Probe{Probe::Target::Entity, 0, 0, label}; };
  const std::vector<Probe> meters = {
      lit("A"), lit("B"), lit("A"), lit("C"), Probe{Probe::Target::Player, 0, 0, "Seen"}, lit("D")};
  const std::vector<float> readings = {0.0f, 0.0f, 0.0f, 0.5f, 0.0f, 0.2f};
  EXPECT_EQ(game::hudMeters(meters, readings, 3), (std::vector<size_t>{3, 4, 5}));
  EXPECT_EQ(game::hudMeters(meters, {}, 3), (std::vector<size_t>{0, 1, 4}));
  EXPECT_EQ(game::hudMeters(meters, readings, 10), (std::vector<size_t>{0, 1, 3, 4, 5}));
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

// ----- what a run's steps are (game/solution_steps.hpp) -----

TEST(SolutionSteps, interactables_changed_and_rules_that_change_the_world_count_once_each) {
  const game::Level level = levelWithRules(R"({
    "greet": { "when": { "type": "timer", "seconds": 0 },
               "then": [{ "do": "hide", "entity": "door" }, { "do": "show", "entity": "door" }] },
    "lamp_on": { "when": { "type": "switch", "entity": "lever" },
                 "then": [{ "do": "play", "mover": "door" }] },
    "pulled": { "when": { "type": "slide", "entity": "shade", "min": 0.5, "max": 2 },
                "then": [{ "do": "message", "text": "pulled" }] },
    "won": { "when": { "type": "slide", "entity": "shade", "min": 0.6, "max": 2 },
             "then": [{ "do": "lock", "entity": "shade" }, { "do": "win" }] } })");
  LogicRun run(level);
  game::SolutionSteps steps(level, run.world);
  auto step = [&](const game::PlayerInput& input) {
    run.step(input);
    steps.observe(run.world, run.logic);
  };
  game::PlayerInput press;
  press.interact = true;  // the lever is 1 m ahead of the eye
  step(press);
  step({});
  step(press);  // switched back off: still the one step
  step({});
  run.world.respawnPlayer({5, 0, 2.5}, 0);
  game::PlayerInput look;
  look.pitchDeltaDegrees = -25.0f;
  step(look);
  game::PlayerInput pull;
  pull.interact = true;
  pull.adjust = 1.0f;
  for (int tick = 0; tick < 40; ++tick) step(pull);
  ASSERT_FALSE(run.logic.firings(0).empty());  // the timer rule fired, on tick 1
  ASSERT_FALSE(run.logic.firings(2).empty());  // the message-only rule fired
  ASSERT_FALSE(run.logic.firings(3).empty());  // the winning rule fired
  std::vector<std::string> what;
  for (const game::SolutionStep& s : steps.steps()) what.push_back(s.what);
  EXPECT_EQ(what, (std::vector<std::string>{"switch lever", "rule lamp_on", "slide shade"}));
  EXPECT_EQ(steps.steps()[0].tick, 1u);
  EXPECT_EQ(steps.steps()[1].tick, 1u);
  EXPECT_EQ(steps.steps()[2].tick, 6u);  // the first tick of pulling
}

// ----- the authors' tools (game/author_view.hpp, the fly camera) -----

const std::string kQuietLogic = R"({
    "later": { "when": { "type": "timer", "seconds": 100 }, "then": [{ "do": "message", "text": "x" }] } })";

TEST(AuthorView, the_crosshair_names_the_entity_its_material_the_point_and_its_state) {
  const game::Level level = levelWithRules(kQuietLogic);
  game::World world(level);
  // The lever's near face is 1 m in front of the eye (0, 1.65, 8).
  const auto lever = game::crosshairTarget(world);
  ASSERT_TRUE(lever);
  EXPECT_EQ(game::describeCrosshair(level, world, *lever),
            (std::vector<std::string>{"entity lever, material paint",
                                      "at [0.00, 1.65, 7.00], 1.00 m", "switch off"}));
  // Past the lever, 4 degrees down meets the door's face (its top is 1 m high) at z = -4.5.
  world.placePlayer({0, 0, 5}, 0, -4);
  const auto door = game::crosshairTarget(world);
  ASSERT_TRUE(door);
  EXPECT_EQ(level.entities[door->entity].id, "door");
  EXPECT_NEAR(door->distance, 9.5f / std::cos(glm::radians(4.0f)), 1e-3f);
  EXPECT_NEAR(door->point.y, 1.65f - 9.5f * std::tan(glm::radians(4.0f)), 1e-3f);
  EXPECT_EQ(game::describeCrosshair(level, world, *door).size(), 2u);  // not an interactable
  world.placePlayer({5, 0, 2.5}, 0, -25);
  const auto shade = game::crosshairTarget(world);
  ASSERT_TRUE(shade);
  EXPECT_EQ(game::describeCrosshair(level, world, *shade).back(), "slide 0.00 m of 0..2");
  world.placePlayer({0, 0, 8}, 0, 30);  // the sky
  EXPECT_FALSE(game::crosshairTarget(world));
}

TEST(AuthorView, the_view_and_the_point_copy_as_level_json) {
  const game::Level level = levelWithRules(kQuietLogic);
  game::World world(level);
  world.placePlayer({1.25f, 0, -3}, 90, -12.5f);
  EXPECT_EQ(game::cameraJson(world),
            "\"camera\": { \"position\": [1.25, 1.65, -3.00], \"yaw_degrees\": 90.00, "
            "\"pitch_degrees\": -12.50, \"fov_degrees\": 60.00 }");
  EXPECT_EQ(game::positionJson({0.004f, -0.001f, 2.5f}), "\"position\": [0.00, 0.00, 2.50]");
}

TEST(AuthorView, the_fly_camera_goes_through_walls_without_gravity_and_jump_rises) {
  const game::Level level = levelWithRules(kQuietLogic);
  game::World world(level);
  world.setFlying(true);
  game::PlayerInput forward;
  forward.move = {0, 1};
  for (int tick = 0; tick < 60; ++tick) world.step(forward);  // through the lever at z 6..7
  EXPECT_NEAR(world.feetPosition().z, 8.0f - 4.0f * game::PlayerController::FLY_SPEED_FACTOR,
              1e-4f);
  EXPECT_EQ(world.feetPosition().y, 0.0f);
  game::PlayerInput rise;
  rise.jump = true;
  for (int tick = 0; tick < 30; ++tick) world.step(rise);
  EXPECT_NEAR(world.feetPosition().y, 4.0f, 1e-4f);
  for (int tick = 0; tick < 30; ++tick) world.step({});  // no gravity
  EXPECT_NEAR(world.feetPosition().y, 4.0f, 1e-4f);
  world.setFlying(false);
  for (int tick = 0; tick < 120; ++tick) world.step({});  // walking again: falls to the floor
  EXPECT_NEAR(world.feetPosition().y, 0.0f, 1e-3f);
}

}  // namespace
