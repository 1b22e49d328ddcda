// Replay files: parsing, input by tick, and one clear message for each kind of bad input.
#include <gtest/gtest.h>

#include "game/replay.hpp"

namespace {

const char* const kReplay = R"({
  "replay": 1,
  "level": "../levels/01_first_light.json",
  "size": [32, 18],
  "probe_every_ticks": 4,
  "probe_latency": 2,
  "ticks": 300,
  "input": [
    { "tick": 0, "hold": 60, "move": [0, 1] },
    { "tick": 30, "hold": 10, "look": [20, -5] },
    { "tick": 100, "jump": true }
  ],
  "expect": { "outcome": "won", "between": [120, 200],
              "values": [ { "tick": 150, "focus": 0, "range": [0.3, 1] } ],
              "player": [ { "tick": 60, "feet": [0, 0, -4], "tolerance": 0.1 } ] }
})";

std::string errorOf(const std::string& text) {
  try {
    game::parseReplay(text, "replays/test.json");
  } catch (const game::ReplayError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(Replay, parses_every_field) {
  const game::Replay replay = game::parseReplay(kReplay, "replays/test.json");
  EXPECT_EQ(replay.level, std::filesystem::path("levels/01_first_light.json"));
  EXPECT_EQ(replay.width, 32u);
  EXPECT_EQ(replay.height, 18u);
  EXPECT_EQ(replay.probeEveryTicks, 4u);
  EXPECT_EQ(replay.probeLatency, 2u);
  EXPECT_EQ(replay.ticks, 300u);
  ASSERT_EQ(replay.events.size(), 3u);
  EXPECT_EQ(replay.outcome.outcome, game::ReplayOutcome::Won);
  EXPECT_EQ(replay.outcome.firstTick, 120u);
  EXPECT_EQ(replay.outcome.lastTick, 200u);
  ASSERT_EQ(replay.values.size(), 1u);
  EXPECT_EQ(replay.values[0].kind, game::ValueExpectation::Kind::Focus);
  EXPECT_FLOAT_EQ(replay.values[0].min, 0.3f);
  ASSERT_EQ(replay.players.size(), 1u);
  EXPECT_FLOAT_EQ(replay.players[0].feet.z, -4.0f);
}

TEST(Replay, input_holds_for_its_ticks_and_spreads_look_evenly) {
  const game::Replay replay = game::parseReplay(kReplay, "replays/test.json");
  EXPECT_EQ(replay.inputAt(0).move, glm::vec2(0, 1));
  EXPECT_EQ(replay.inputAt(59).move, glm::vec2(0, 1));
  EXPECT_EQ(replay.inputAt(60).move, glm::vec2(0, 0));
  EXPECT_FLOAT_EQ(replay.inputAt(30).yawDeltaDegrees, 2.0f);
  EXPECT_FLOAT_EQ(replay.inputAt(39).pitchDeltaDegrees, -0.5f);
  EXPECT_FLOAT_EQ(replay.inputAt(40).yawDeltaDegrees, 0.0f);
  EXPECT_TRUE(replay.inputAt(100).jump);
  EXPECT_FALSE(replay.inputAt(101).jump);
}

TEST(Replay, round_trips_through_json) {
  const game::Replay replay = game::parseReplay(kReplay, "replays/test.json");
  const game::Replay again = game::parseReplay(game::replayToJson(replay), "replays/test.json");
  EXPECT_EQ(again.level, replay.level);
  for (uint64_t tick = 0; tick < replay.ticks; ++tick)
    EXPECT_EQ(again.inputAt(tick), replay.inputAt(tick)) << "tick " << tick;
  EXPECT_EQ(again.outcome.outcome, game::ReplayOutcome::Won);
  EXPECT_FALSE(again.verticalFovDegrees.has_value());  // the level's own unless recorded
}

TEST(Replay, a_recorded_field_of_view_round_trips_and_is_range_checked) {
  game::Replay replay = game::parseReplay(kReplay, "replays/test.json");
  replay.verticalFovDegrees = 87.5f;
  const game::Replay again = game::parseReplay(game::replayToJson(replay), "replays/test.json");
  ASSERT_TRUE(again.verticalFovDegrees.has_value());
  EXPECT_EQ(*again.verticalFovDegrees, 87.5f);
  try {
    game::parseReplay(
        R"({"replay": 1, "level": "a.json", "ticks": 5, "vertical_fov_degrees": 180})", "bad.json");
    FAIL() << "a field of view of 180 degrees was accepted";
  } catch (const game::ReplayError& error) {
    EXPECT_STREQ(error.what(),
                 "bad.json:1:70: /vertical_fov_degrees: expected a number in [1, 179], got 180");
  }
}

TEST(Replay, recorded_input_comes_back_exactly_tick_for_tick) {
  game::Replay recording;
  recording.file = "replays/recorded.json";
  recording.level = "levels/01_first_light.json";
  recording.ticks = 0;
  std::vector<game::TickInput> played;
  for (int tick = 0; tick < 300; ++tick) {
    game::TickInput input;
    if (tick < 100) input.move = {0.0f, 1.0f};  // held: one event
    if (tick >= 120 && tick < 160) input.yawDeltaDegrees = 0.1f * float(tick % 7);  // mouse
    if (tick == 200) input.jump = true;
    if (tick >= 220 && tick < 260) input.interact = true, input.adjust = -1.0f;
    played.push_back(input);
    game::appendTickInput(recording, input);
  }
  EXPECT_EQ(recording.ticks, 300u);
  EXPECT_LT(recording.events.size(), 50u);
  const game::Replay loaded =
      game::parseReplay(game::replayToJson(recording), "replays/recorded.json");
  for (uint64_t tick = 0; tick < played.size(); ++tick)
    EXPECT_EQ(loaded.inputAt(tick), played[tick]) << "tick " << tick;
}

TEST(Replay, bad_input_gets_one_message_with_file_line_and_column) {
  EXPECT_EQ(errorOf(replaced(kReplay, R"("tick": 100, "jump")", R"("tick": 10, "jump")")),
            "replays/test.json:11:15: /input/2/tick: events must be in tick order; tick 10 comes "
            "after tick 30");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("tick": 100, "jump")", R"("tick": 300, "jump")")),
            "replays/test.json:11:15: /input/2/tick: tick 300 is past the end of the replay "
            "(ticks: 300)");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("jump": true)", R"("jmp": true)")),
            "replays/test.json:11:20: /input/2: unknown key \"jmp\"; allowed keys: \"tick\", "
            "\"hold\", \"move\", \"look\", \"jump\", \"interact\", \"adjust\"");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("replay": 1)", R"("replay": 2)")),
            "replays/test.json:2:13: /replay: unsupported replay format 2; this version reads "
            "replay format 1");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("move": [0, 1])", R"("move": [0, 2])")),
            "replays/test.json:9:42: /input/0/move/1: expected a number in [-1, 1], got 2");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("outcome": "won")", R"("outcome": "win")")),
            "replays/test.json:13:26: /expect/outcome: expected one of \"won\", \"lost\", "
            "\"none\", got \"win\"");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("ticks": 300,)", R"("ticks": 300)")),
            "replays/test.json:8:9: invalid JSON");
  EXPECT_EQ(errorOf(replaced(kReplay, R"("level": "../levels/01_first_light.json",)", "")),
            "replays/test.json:1:1: missing required key \"level\"");
}

}  // namespace
