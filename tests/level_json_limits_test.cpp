// Hostile JSON (docs/ROBUSTNESS.md): every reader refuses nesting past kMaxJsonNesting before
// it builds a tree, with a message naming file, line and column, and shapes that used to cost
// quadratic time or memory (many keys in one object, long keys over deep nesting) read in
// linear time. No timings here: a regression shows as a test that runs for minutes.
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "game/gltf_mesh.hpp"
#include "game/json_document.hpp"
#include "game/level_format/level_reader.hpp"
#include "game/level_loader.hpp"
#include "game/progress.hpp"
#include "game/replay.hpp"
#include "game/settings.hpp"
#include "temp_dir_fixture.hpp"

namespace {

namespace fs = std::filesystem;

using JsonLimits = test::TempDirTest;

// `depth` arrays, one inside the next.
std::string nestedArrays(std::size_t depth) {
  return std::string(depth, '[') + std::string(depth, ']');
}

const std::string kTooDeepMessage = "arrays and objects nest more than 64 deep here, the limit";

std::optional<std::size_t> offsetOfProblem(const std::string& text, std::size_t maxNesting = 64,
                                           std::size_t maxValues = 4'000'000) {
  const auto problem = game::jsonShapeProblem(text, maxNesting, maxValues);
  return problem ? std::optional<std::size_t>(problem->offset) : std::nullopt;
}

TEST(JsonNesting, the_first_bracket_past_the_limit_is_found_outside_strings) {
  EXPECT_EQ(offsetOfProblem(nestedArrays(64)), std::nullopt);
  EXPECT_EQ(offsetOfProblem(nestedArrays(65)), 64u);
  // Brackets in strings, escaped quotes included, do not count.
  EXPECT_EQ(offsetOfProblem("[\"" + std::string(100, '[') + "\\\"[\"]"), std::nullopt);
  EXPECT_EQ(offsetOfProblem("{\"a\": " + nestedArrays(200) + "}", 64), 69u);
}

// 16 MiB of "0," would be 8 million numbers, several hundred megabytes once read (a glTF's
// more): past 4 000 000 values (arrays, objects and commas) a file is refused at the one too
// many.
TEST(JsonNesting, values_past_the_count_limit_are_refused) {
  std::string many = "[0";
  for (int i = 1; i < 4'000'001; ++i) many += ",0";
  many += "]";
  const auto problem = game::jsonShapeProblem(many);
  ASSERT_TRUE(problem.has_value());
  // The root array is value 1, the k-th comma value k + 1, at offset 2k.
  EXPECT_EQ(problem->offset, 2u * 4'000'000u);
  EXPECT_EQ(problem->message,
            "more than 4000000 values (arrays, objects and commas) in the file, the limit");
  EXPECT_EQ(offsetOfProblem("[1,2,3]", 64, 3), std::nullopt);
  EXPECT_EQ(offsetOfProblem("[{},[],{\"a\":[]}]", 64, 5), 7u);      // [ { , [ , then this {
  EXPECT_EQ(offsetOfProblem("[\",,,,\",1]", 64, 2), std::nullopt);  // commas in strings
}

TEST(JsonNesting, a_level_names_the_place_where_nesting_passes_the_limit) {
  const std::string text = "{\n  \"format\": 1,\n  \"name\": " + nestedArrays(100000) + "\n}\n";
  try {
    game::parseLevel(text, "levels/deep.json");
    ADD_FAILURE() << "a 100 000-deep level loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()), "levels/deep.json:3:74: " + kTooDeepMessage);
  }
}

TEST(JsonNesting, a_replay_names_the_place_where_nesting_passes_the_limit) {
  try {
    game::parseReplay("{\"replay\": 1, \"input\": " + nestedArrays(30000) + "}", "r.json");
    ADD_FAILURE() << "a 30 000-deep replay parsed";
  } catch (const game::ReplayError& error) {
    EXPECT_EQ(std::string(error.what()), "r.json:1:87: " + kTooDeepMessage);
  }
}

TEST_F(JsonLimits, settings_and_progress_too_deep_are_set_aside_with_one_message) {
  test::writeFile(root_ / "settings.json", "{\"settings\": 1, \"keys\": " + nestedArrays(70) + "}");
  const game::SettingsLoad settings = game::loadSettings(root_ / "settings.json");
  EXPECT_EQ(settings.settings, game::Settings{});
  ASSERT_EQ(settings.messages.size(), 1u);
  EXPECT_EQ(settings.messages[0].rfind(
                (root_ / "settings.json").string() + ":1:88: " + kTooDeepMessage + "; ", 0),
            0u)
      << settings.messages[0];

  test::writeFile(root_ / "progress.json", nestedArrays(100));
  const game::ProgressLoad progress = game::loadProgress(root_ / "progress.json");
  ASSERT_EQ(progress.messages.size(), 1u);
  EXPECT_EQ(progress.messages[0].rfind(
                (root_ / "progress.json").string() + ":1:65: " + kTooDeepMessage + "; ", 0),
            0u)
      << progress.messages[0];
}

TEST_F(JsonLimits, gltf_json_too_deep_is_refused_before_tinygltf_reads_it) {
  const std::string json =
      "{\"asset\": {\"version\": \"2.0\", \"extras\": " + nestedArrays(5000) + "}}";
  test::writeFile(root_ / "deep.gltf", json);
  const std::string expected = ": invalid glTF JSON at line 1, column 102: " + kTooDeepMessage;
  try {
    game::loadGltfModel(root_ / "deep.gltf", root_);
    ADD_FAILURE() << "a 5 000-deep glTF loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()), (root_ / "deep.gltf").string() + expected);
  }
  // The same JSON as a .glb's JSON chunk.
  const auto u32 = [](std::size_t value) {
    const uint32_t v = static_cast<uint32_t>(value);
    return std::string(reinterpret_cast<const char*>(&v), sizeof v);
  };
  test::writeFile(root_ / "deep.glb",
                  "glTF" + u32(2) + u32(20 + json.size()) + u32(json.size()) + "JSON" + json);
  try {
    game::loadGltfModel(root_ / "deep.glb", root_);
    ADD_FAILURE() << "a 5 000-deep .glb loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()), (root_ / "deep.glb").string() + expected);
  }
}

// An object of 200 000 members took nlohmann's ordered parse minutes (each key looked up among
// the members before it); and 60 levels of 1 000-byte keys over 100 000 values took the
// position index gigabytes (a full JSON pointer per value). Both now read in a moment and get
// the reader's usual message.
TEST(JsonShapes, many_keys_and_long_keys_over_deep_nesting_read_in_linear_time) {
  std::string manyKeys = "{\"format\": 1";
  for (int i = 0; i < 200000; ++i) manyKeys += ",\"k" + std::to_string(i) + "\":0";
  manyKeys += "}";
  try {
    game::parseLevel(manyKeys, "levels/keys.json");
    ADD_FAILURE() << "loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(
        std::string(error.what()).rfind("levels/keys.json:1:14: unknown key \"k0\"; allowed", 0),
        0u)
        << error.what();
  }

  const std::string key = "\"" + std::string(1000, 'k') + "\":";
  std::string longKeys = "{\"format\": 1, \"name\": \"x\", \"extras\": ";
  for (int i = 0; i < 60; ++i) longKeys += "{" + key;
  longKeys += "[";
  for (int i = 0; i < 100000; ++i) longKeys += i ? ",0" : "0";
  longKeys += "]" + std::string(60, '}') + "}";
  try {
    game::parseLevel(longKeys, "levels/long.json");
    ADD_FAILURE() << "loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("levels/long.json:1:28: unknown key \"extras\"; allowed", 0),
              0u)
        << error.what();
  }
}

// A file at the level size limit made of the worst shape the reader takes apart: valid
// materials with 1 000-byte ids, many more than the limit of 256. It is refused with the
// material limit's message, not half-loaded and not after minutes.
TEST(JsonShapes, a_level_at_the_size_limit_of_long_keyed_deep_materials_is_refused) {
  const std::string material = "{\"color\": [0.5, 0.5, 0.5]}";
  const std::string id = std::string(1000, 'm');
  std::string text =
      "{\"format\": 1, \"name\": \"Big\", \"camera\": {\"position\": [0, 1, 5]}, "
      "\"meshes\": {\"cube\": {\"box\": {\"size\": [1, 1, 1]}}}, \"lights\": {}, "
      "\"entities\": {\"crate\": {\"mesh\": \"cube\", \"material\": \"0" +
      id + "\"}}, \"materials\": {";
  for (std::size_t i = 0; text.size() + 1200 < game::level_format::kMaxLevelFileBytes; ++i)
    text += (i ? ",\"" : "\"") + std::to_string(i) + id + "\": " + material;
  text += "}}";
  ASSERT_LE(text.size(), game::level_format::kMaxLevelFileBytes);
  try {
    game::parseLevel(text, "levels/big.json");
    ADD_FAILURE() << "loaded";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()),
              "levels/big.json:1:1200: /materials: 16203 materials, more than the limit of 256");
  }
}

}  // namespace
