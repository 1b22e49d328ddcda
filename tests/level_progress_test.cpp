// Settings, progress, the level order file and where the player's files live.
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "game/level_order.hpp"
#include "game/progress.hpp"
#include "game/settings.hpp"
#include "game/user_paths.hpp"
#include "tests/temp_dir_fixture.hpp"

namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream), {});
}

// Sets (or, with std::nullopt, unsets) an environment variable and restores it afterwards, so
// tests cannot leak their XDG settings into each other.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) previous_ = old;
    if (value) {
      setenv(name, value->c_str(), 1);
    } else {
      unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    if (previous_) {
      setenv(name_, previous_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> previous_;
};

using SettingsFile = test::TempDirTest;
using ProgressFile = test::TempDirTest;
using AtomicSave = test::TempDirTest;

// ----- settings -----

TEST(Settings, defaults_are_the_documented_ones) {
  const game::Settings settings;
  EXPECT_FLOAT_EQ(settings.mouseSensitivity, 0.1f);
  EXPECT_FALSE(settings.invertY);
  EXPECT_FALSE(settings.fieldOfViewDegrees.has_value());  // each level's own
  EXPECT_FLOAT_EQ(settings.renderScale, 0.25f);
  EXPECT_TRUE(settings.vsync);
  EXPECT_TRUE(settings.dynamicRenderScale);
  const std::map<std::string, std::string> expected = {
      {"forward", "W"},    {"back", "S"},     {"left", "A"},        {"right", "D"},
      {"jump", "SPACE"},   {"interact", "E"}, {"adjust_down", "Q"}, {"adjust_up", "R"},
      {"pause", "ESCAPE"}, {"restart", "F5"}, {"fullscreen", "F11"}};
  EXPECT_EQ(settings.keyBindings, expected);
  for (const auto& [action, key] : expected) EXPECT_TRUE(game::isKeyName(key)) << action;
}

TEST(Settings, key_names_follow_glfw) {
  for (const char* name : {"A", "Z", "0", "9", "F1", "F25", "SPACE", "KP_ENTER", "LEFT_SHIFT"})
    EXPECT_TRUE(game::isKeyName(name)) << name;
  for (const char* name : {"", "a", "F0", "F26", "F01", "SPACEBAR", "GLFW_KEY_W", "shift"})
    EXPECT_FALSE(game::isKeyName(name)) << name;
}

TEST_F(SettingsFile, round_trips_every_field) {
  game::Settings settings;
  settings.mouseSensitivity = 0.35f;
  settings.invertY = true;
  settings.fieldOfViewDegrees = 95.5f;
  settings.renderScale = 0.6f;
  settings.vsync = false;
  settings.dynamicRenderScale = false;
  settings.keyBindings["jump"] = "LEFT_CONTROL";
  settings.keyBindings["forward"] = "UP";
  const fs::path file = root_ / "settings.json";
  game::saveSettings(settings, file);

  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_TRUE(load.messages.empty()) << load.messages.front();
  EXPECT_EQ(load.settings, settings);
  // Floats are written in their shortest form, so the file stays readable by hand.
  EXPECT_NE(readFile(file).find("\"render_scale\": 0.6,"), std::string::npos) << readFile(file);
  EXPECT_NE(readFile(file).find("\"settings\": 1,"), std::string::npos) << readFile(file);
}

TEST_F(SettingsFile, unset_field_of_view_is_written_as_null_and_keeps_each_levels_own) {
  const fs::path file = root_ / "settings.json";
  game::saveSettings(game::Settings{}, file);
  EXPECT_NE(readFile(file).find("\"field_of_view_degrees\": null,"), std::string::npos)
      << readFile(file);
  EXPECT_FALSE(game::loadSettings(file).settings.fieldOfViewDegrees.has_value());

  test::writeFile(file, "{\n  \"settings\": 1,\n  \"field_of_view_degrees\": 200\n}\n");
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_FALSE(load.settings.fieldOfViewDegrees.has_value());
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0], file.string() +
                                  ":3:28: /field_of_view_degrees: expected a number in [30, 120], "
                                  "got 200; using the default null (the level's)");
}

TEST_F(SettingsFile, missing_file_gives_the_defaults_silently) {
  const game::SettingsLoad load = game::loadSettings(root_ / "nowhere" / "settings.json");
  EXPECT_EQ(load.settings, game::Settings{});
  EXPECT_TRUE(load.messages.empty());
}

TEST_F(SettingsFile, corrupt_file_gives_the_defaults_and_one_message_naming_it) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, "{\n  \"settings\": 1,\n  \"vsync\": fals\n}\n");
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_EQ(load.settings, game::Settings{});
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0], file.string() +
                                  ":3:16: invalid JSON: syntax error while parsing value - "
                                  "invalid literal; last read: '\"vsync\": fals<U+000A>'; "
                                  "using the default settings");
}

TEST_F(SettingsFile, a_file_that_is_not_an_object_gives_the_defaults) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, "[1, 2]\n");
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_EQ(load.settings, game::Settings{});
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0],
            file.string() + ":1:1: expected an object, got [1,2]; using the default settings");
}

TEST_F(SettingsFile, out_of_range_field_takes_its_default_and_keeps_the_others) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, R"({
  "settings": 1,
  "mouse_sensitivity": 0.5,
  "render_scale": 2,
  "invert_y": true,
  "key_bindings": { "jump": "J" }
}
)");
  const game::SettingsLoad load = game::loadSettings(file);
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0], file.string() +
                                  ":4:19: /render_scale: expected a number in (0.1, 1], got 2; "
                                  "using the default 0.25");
  EXPECT_FLOAT_EQ(load.settings.renderScale, 0.25f);
  EXPECT_FLOAT_EQ(load.settings.mouseSensitivity, 0.5f);
  EXPECT_TRUE(load.settings.invertY);
  EXPECT_EQ(load.settings.keyBindings.at("jump"), "J");
  EXPECT_EQ(load.settings.keyBindings.at("forward"), "W");  // not in the file: the default
}

TEST_F(SettingsFile, every_kind_of_bad_field_is_reported_where_it_is) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, R"({
  "settings": 1,
  "render_scale": 0.1,
  "field_of_view_degrees": 29,
  "mouse_sensitivity": 0,
  "vsync": "yes",
  "colour": "blue",
  "key_bindings": { "fly": "F", "jump": "spacebar", "back": 7, "pause": "P" }
}
)");
  const game::SettingsLoad load = game::loadSettings(file);
  const std::string at = file.string() + ":";
  const std::vector<std::string> expected = {
      at + "7:3: /colour: unknown key; ignored",
      at + "5:24: /mouse_sensitivity: expected a number in (0, 10], got 0; using the default 0.1",
      at + "4:28: /field_of_view_degrees: expected a number in [30, 120], got 29; using the "
           "default null (the level's)",
      at + "3:19: /render_scale: expected a number in (0.1, 1], got 0.1; using the default 0.25",
      at + "6:12: /vsync: expected true or false, got \"yes\"; using the default true",
      at + "8:21: /key_bindings/fly: unknown action; ignored",
      at + "8:41: /key_bindings/jump: expected a GLFW key name such as \"W\" or \"SPACE\", got "
           "\"spacebar\"; using the default \"SPACE\"",
      at + "8:61: /key_bindings/back: expected a GLFW key name such as \"W\" or \"SPACE\", got 7; "
           "using the default \"S\"",
  };
  EXPECT_EQ(load.messages, expected);
  game::Settings settings;
  settings.keyBindings["pause"] = "P";  // the one good field
  EXPECT_EQ(load.settings, settings);
}

TEST_F(SettingsFile, a_newer_version_gives_the_defaults) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, "{\n  \"settings\": 2,\n  \"vsync\": false\n}\n");
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_EQ(load.settings, game::Settings{});
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(
      load.messages[0],
      file.string() + ":2:15: /settings: expected version 1, got 2; using the default settings");
}

TEST_F(SettingsFile, a_missing_version_is_reported_and_the_fields_still_read) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file, "{ \"vsync\": false }");
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_FALSE(load.settings.vsync);
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0],
            file.string() + ":1:1: missing \"settings\": 1; reading the file as version 1");
}

TEST_F(SettingsFile, a_directory_in_its_place_gives_the_defaults_and_a_message) {
  const fs::path file = root_ / "settings.json";
  fs::create_directories(file);
  const game::SettingsLoad load = game::loadSettings(file);
  EXPECT_EQ(load.settings, game::Settings{});
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0],
            file.string() + ": cannot read: not a regular file; using the default settings");
}

// ----- progress -----

TEST_F(ProgressFile, round_trips) {
  game::Progress progress;
  EXPECT_EQ(game::markWon(progress, "02_penumbra.json", 300), std::nullopt);
  EXPECT_EQ(game::markWon(progress, "01_first_light.json", 200), std::nullopt);
  // Winning again keeps the level completed and the fewer ticks as its best.
  EXPECT_EQ(game::markWon(progress, "01_first_light.json", 250), std::optional<uint64_t>(200));
  EXPECT_EQ(game::markWon(progress, "02_penumbra.json", 280), std::optional<uint64_t>(300));
  EXPECT_EQ(progress.completed.size(), 2u);
  EXPECT_EQ(progress.bestTicks, (std::map<std::string, uint64_t>{{"01_first_light.json", 200},
                                                                 {"02_penumbra.json", 280}}));
  const fs::path file = root_ / "data" / "progress.json";
  game::saveProgress(progress, file);
  EXPECT_EQ(readFile(file), R"({
  "progress": 1,
  "completed": [
    "01_first_light.json",
    "02_penumbra.json"
  ],
  "best_ticks": {
    "01_first_light.json": 200,
    "02_penumbra.json": 280
  }
}
)");
  const game::ProgressLoad load = game::loadProgress(file);
  EXPECT_TRUE(load.messages.empty());
  EXPECT_EQ(load.progress, progress);
}

TEST_F(ProgressFile, corrupt_file_gives_no_progress_and_one_message) {
  const fs::path file = root_ / "progress.json";
  test::writeFile(file, "{\"progress\": 1, \"completed\": [\"01_first_light.json\"");
  const game::ProgressLoad load = game::loadProgress(file);
  EXPECT_TRUE(load.progress.completed.empty());
  ASSERT_EQ(load.messages.size(), 1u);
  EXPECT_EQ(load.messages[0].rfind(file.string() + ":1:52: invalid JSON: ", 0), 0u)
      << load.messages[0];
  EXPECT_TRUE(load.messages[0].ends_with("; starting with no levels completed"))
      << load.messages[0];
}

TEST_F(ProgressFile, bad_entries_are_skipped_and_the_others_kept) {
  const fs::path file = root_ / "progress.json";
  test::writeFile(file, R"({ "progress": 1,
  "completed": ["01_first_light.json", "../../etc/passwd", 3, "02_penumbra.json"] })");
  const game::ProgressLoad load = game::loadProgress(file);
  EXPECT_EQ(load.progress.completed,
            (std::set<std::string>{"01_first_light.json", "02_penumbra.json"}));
  const std::string bad = ": expected a level file name such as \"01_first_light.json\", got ";
  EXPECT_EQ(load.messages,
            (std::vector<std::string>{
                file.string() + ":2:40: /completed/1" + bad + "\"../../etc/passwd\"; ignored",
                file.string() + ":2:60: /completed/2" + bad + "3; ignored"}));
}

TEST_F(ProgressFile, bad_best_times_are_skipped_and_the_others_kept) {
  const fs::path file = root_ / "progress.json";
  test::writeFile(file, R"({ "progress": 1, "completed": ["a.json"],
  "best_ticks": { "a.json": 120, "b/c.json": 5, "d.json": -3, "e.json": 0, "f.json": 61 } })");
  const game::ProgressLoad load = game::loadProgress(file);
  EXPECT_EQ(load.progress.bestTicks,
            (std::map<std::string, uint64_t>{{"a.json", 120}, {"f.json", 61}}));
  const std::string bad = ": expected a level file name with a tick count above 0, got ";
  EXPECT_EQ(load.messages, (std::vector<std::string>{
                               file.string() + ":2:46: /best_ticks/b~1c.json" + bad + "5; ignored",
                               file.string() + ":2:59: /best_ticks/d.json" + bad + "-3; ignored",
                               file.string() + ":2:73: /best_ticks/e.json" + bad + "0; ignored"}));
  test::writeFile(file, R"({ "progress": 1, "best_ticks": [1] })");
  EXPECT_EQ(game::loadProgress(file).messages,
            (std::vector<std::string>{
                file.string() +
                ":1:32: /best_ticks: expected an object of level file names and tick counts, got "
                "[1]; no best times kept"}));
}

TEST(Progress, game_time_is_ticks_at_sixty_a_second) {
  EXPECT_EQ(game::gameTimeText(0), "0.0 s");
  EXPECT_EQ(game::gameTimeText(2538), "42.3 s");
  EXPECT_EQ(game::gameTimeText(60 * 125), "125.0 s");
}

TEST(Progress, the_first_level_and_those_after_a_completed_one_are_unlocked) {
  const std::vector<std::string> order = {"a.json", "b.json", "c.json"};
  game::Progress progress;
  EXPECT_TRUE(game::unlocked(progress, order, "a.json"));
  EXPECT_FALSE(game::unlocked(progress, order, "b.json"));
  EXPECT_FALSE(game::unlocked(progress, order, "c.json"));
  game::markWon(progress, "a.json", 100);
  EXPECT_TRUE(game::unlocked(progress, order, "b.json"));
  EXPECT_FALSE(game::unlocked(progress, order, "c.json"));
  // Winning a later level (from the command line) unlocks only the one after it.
  game::Progress skipped;
  game::markWon(skipped, "b.json", 100);
  EXPECT_FALSE(game::unlocked(skipped, order, "b.json"));
  EXPECT_TRUE(game::unlocked(skipped, order, "c.json"));
  EXPECT_FALSE(game::unlocked(progress, order, "not_in_the_order.json"));
  progress = game::Progress{};  // reset
  EXPECT_FALSE(game::unlocked(progress, order, "b.json"));
}

// ----- atomic saves -----

TEST_F(AtomicSave, replaces_an_existing_file_and_leaves_no_temporary_file) {
  const fs::path file = root_ / "config" / "sightline" / "settings.json";
  test::writeFile(file,
                  "old contents that are longer than the new ones will be, by far......"
                  "...............................................................");
  game::Settings settings;
  settings.vsync = false;
  game::saveSettings(settings, file);
  EXPECT_EQ(game::loadSettings(file).settings, settings);
  EXPECT_EQ(readFile(file).find("old contents"), std::string::npos);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(file.parent_path()))
    entries.push_back(entry.path());
  EXPECT_EQ(entries, std::vector<fs::path>{file});
}

TEST_F(AtomicSave, creates_missing_directories) {
  const fs::path file = root_ / "a" / "b" / "c" / "progress.json";
  game::saveProgress(game::Progress{{"01_first_light.json"}}, file);
  EXPECT_EQ(game::loadProgress(file).progress.completed,
            std::set<std::string>{"01_first_light.json"});
}

TEST_F(AtomicSave, an_unwritable_place_throws_naming_the_file) {
  test::writeFile(root_ / "blocker", "a file where a directory should be");
  const fs::path file = root_ / "blocker" / "settings.json";
  try {
    game::saveSettings(game::Settings{}, file);
    FAIL() << "expected UserFileError";
  } catch (const game::UserFileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(file.string() + ": cannot create directory ", 0), 0u)
        << error.what();
  }
}

TEST_F(AtomicSave, a_failed_rename_keeps_the_target_and_removes_the_temporary_file) {
  const fs::path file = root_ / "settings.json";
  test::writeFile(file / "keep", "a directory in the file's place cannot be renamed over");
  try {
    game::saveSettings(game::Settings{}, file);
    FAIL() << "expected UserFileError";
  } catch (const game::UserFileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(file.string() + ": cannot replace: ", 0), 0u)
        << error.what();
  }
  EXPECT_TRUE(fs::exists(file / "keep"));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

// ----- where the files live -----

TEST_F(AtomicSave, screenshots_taken_within_one_millisecond_do_not_overwrite_each_other) {
  const fs::path directory = root_ / "screenshots";
  fs::create_directories(directory);
  const auto now = std::chrono::system_clock::now();
  std::vector<fs::path> files;
  for (int shot = 0; shot < 3; ++shot) {
    files.push_back(game::newScreenshotFile(directory, now));
    test::writeFile(files.back(), "png");
  }
  EXPECT_NE(files[0], files[1]);
  EXPECT_NE(files[1], files[2]);
  EXPECT_EQ(files[1].filename().string(),
            files[0].stem().string() + "-2.png");  // the same moment, numbered
  // A millisecond later is a name of its own.
  EXPECT_NE(game::newScreenshotFile(directory, now + std::chrono::milliseconds(1)).stem(),
            files[0].stem());
}

TEST(UserPaths, xdg_variables_win_when_absolute) {
  const ScopedEnvironment home("HOME", "/home/player");
  const ScopedEnvironment config("XDG_CONFIG_HOME", "/xdg/config");
  const ScopedEnvironment data("XDG_DATA_HOME", "/xdg/data");
  EXPECT_EQ(game::configDirectory(), fs::path("/xdg/config/sightline"));
  EXPECT_EQ(game::dataDirectory(), fs::path("/xdg/data/sightline"));
  EXPECT_EQ(game::settingsFile(), fs::path("/xdg/config/sightline/settings.json"));
  EXPECT_EQ(game::progressFile(), fs::path("/xdg/data/sightline/progress.json"));
}

TEST(UserPaths, home_is_used_when_xdg_variables_are_unset_empty_or_relative) {
  const ScopedEnvironment home("HOME", "/home/player");
  {
    const ScopedEnvironment config("XDG_CONFIG_HOME", std::nullopt);
    const ScopedEnvironment data("XDG_DATA_HOME", std::nullopt);
    EXPECT_EQ(game::configDirectory(), fs::path("/home/player/.config/sightline"));
    EXPECT_EQ(game::dataDirectory(), fs::path("/home/player/.local/share/sightline"));
  }
  {
    const ScopedEnvironment config("XDG_CONFIG_HOME", "");
    const ScopedEnvironment data("XDG_DATA_HOME", "");
    EXPECT_EQ(game::configDirectory(), fs::path("/home/player/.config/sightline"));
    EXPECT_EQ(game::dataDirectory(), fs::path("/home/player/.local/share/sightline"));
  }
  {
    const ScopedEnvironment config("XDG_CONFIG_HOME", "relative/config");
    const ScopedEnvironment data("XDG_DATA_HOME", "./data");
    EXPECT_EQ(game::configDirectory(), fs::path("/home/player/.config/sightline"));
    EXPECT_EQ(game::dataDirectory(), fs::path("/home/player/.local/share/sightline"));
  }
}

TEST(UserPaths, environment_is_restored_after_a_scope) {
  const char* before = std::getenv("XDG_CONFIG_HOME");
  const std::optional<std::string> saved =
      before ? std::optional<std::string>(before) : std::nullopt;
  {
    const ScopedEnvironment config("XDG_CONFIG_HOME", "/elsewhere");
    EXPECT_STREQ(std::getenv("XDG_CONFIG_HOME"), "/elsewhere");
  }
  const char* after = std::getenv("XDG_CONFIG_HOME");
  EXPECT_EQ(after ? std::optional<std::string>(after) : std::nullopt, saved);
}

// ----- level order -----

class LevelOrderFile : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    for (const char* name : {"one.json", "two.json", "three.json", "notes.txt"})
      test::writeFile(root_ / "levels" / name, "{}");
    fs::create_directories(root_ / "levels" / "sub");
  }
  fs::path levels() const { return root_ / "levels"; }
  std::string orderFile() const { return (levels() / "order.txt").string(); }
  // The message loadLevelOrder throws for `text`, "" when it does not throw.
  std::string errorFor(const std::string& text) const {
    test::writeFile(levels() / "order.txt", text);
    try {
      game::loadLevelOrder(levels());
    } catch (const game::LevelError& error) {
      return error.what();
    }
    return "";
  }
};

TEST_F(LevelOrderFile, lists_names_in_order_skipping_comments_and_blank_lines) {
  test::writeFile(levels() / "order.txt",
                  "# the campaign\n\ntwo.json\n  one.json   # indented, with a comment\r\n"
                  "\t\n#three.json\nthree.json");
  EXPECT_EQ(game::loadLevelOrder(levels()),
            (std::vector<std::string>{"two.json", "one.json", "three.json"}));
}

TEST_F(LevelOrderFile, each_error_names_the_line) {
  EXPECT_EQ(errorFor("one.json\nmissing.json\n"),
            orderFile() + ":2: \"missing.json\" does not exist in " + levels().string());
  EXPECT_EQ(errorFor("one.json\ntwo.json\n\none.json\n"),
            orderFile() + ":4: \"one.json\" is listed twice (first on line 1)");
  EXPECT_EQ(errorFor("sub/one.json\n"),
            orderFile() + ":1: \"sub/one.json\" is a path; list level file names only");
  EXPECT_EQ(errorFor("one.json\n../levels/two.json\n"),
            orderFile() + ":2: \"../levels/two.json\" is a path; list level file names only");
  EXPECT_EQ(errorFor("..\n"), orderFile() + ":1: \"..\" is a path; list level file names only");
  EXPECT_EQ(errorFor("notes.txt\n"), orderFile() + ":1: \"notes.txt\" is not a .json level file");
  EXPECT_EQ(errorFor("# nothing yet\n\n"), orderFile() + ": lists no levels");
}

TEST_F(LevelOrderFile, chapters_hold_the_levels_below_them) {
  test::writeFile(
      levels() / "order.txt",
      "one.json\nchapter: Glass  # the second\ntwo.json\n\nchapter:Mirrors\nthree.json\n");
  EXPECT_EQ(game::loadCampaign(levels()),
            (std::vector<game::OrderedLevel>{
                {"one.json", ""}, {"two.json", "Glass"}, {"three.json", "Mirrors"}}));
  EXPECT_EQ(errorFor("chapter:\none.json\n"),
            orderFile() + ":1: a chapter needs a name, as in \"chapter: Mirrors\"");
  EXPECT_EQ(errorFor("chapter: A\none.json\nchapter: A\ntwo.json\n"),
            orderFile() + ":3: chapter \"A\" is named twice (first on line 1)");
  EXPECT_EQ(errorFor("chapter: A\nchapter: B\none.json\n"),
            orderFile() + ":1: chapter \"A\" lists no levels");
  EXPECT_EQ(errorFor("chapter: A\none.json\nchapter: B\n# nothing\n"),
            orderFile() + ":3: chapter \"B\" lists no levels");
}

TEST_F(LevelOrderFile, a_missing_file_is_an_error) {
  try {
    game::loadLevelOrder(levels());
    FAIL() << "expected LevelError";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()), orderFile() + ": cannot open level order file");
  }
}

TEST(LevelOrder, shipped_order_lists_every_shipped_level_once_in_chapters) {
  const fs::path levels = fs::path(SIGHTLINE_SOURCE_DIR) / "levels";
  const std::vector<game::OrderedLevel> order = game::loadCampaign(levels);
  std::set<std::string> listed;
  std::set<std::string> chapters;
  for (const game::OrderedLevel& level : order) {
    listed.insert(level.file);
    EXPECT_FALSE(level.chapter.empty()) << level.file << " is in no chapter";
    chapters.insert(level.chapter);
  }
  std::set<std::string> shipped;
  for (const auto& entry : fs::directory_iterator(levels)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".json" && name.find(".schema.") == std::string::npos)
      shipped.insert(name);
  }
  EXPECT_EQ(listed, shipped);
  EXPECT_GE(order.size(), 16u);
  EXPECT_GE(chapters.size(), 5u);
  EXPECT_EQ(order.front().file, "01_first_light.json");  // the first lesson stays first
}

}  // namespace
