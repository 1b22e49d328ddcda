#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "game/level_watcher.hpp"

namespace {
namespace fs = std::filesystem;
using Event = game::LevelWatcher::Event;

std::string levelText(const std::string& color) {
  return R"({
  "format": 1, "name": "Watched",
  "camera": {"position": [0, 1, 3]},
  "materials": {"paint": {"color": )" +
         color + R"(}},
  "meshes": {"cube": {"box": {"size": [1, 1, 1]}}},
  "entities": {"cube": {"mesh": "cube", "material": "paint"}},
  "lights": {}
})";
}

class LevelWatcherTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("sightline-watch-" +
                  std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
    file_ = directory_ / "level.json";
  }
  void TearDown() override { fs::remove_all(directory_); }

  // Writes the file and moves its modification time forward, as a later save would.
  void save(const std::string& text) {
    std::ofstream(file_) << text;
    fs::last_write_time(file_, fs::file_time_type::clock::now() + std::chrono::seconds(++saves_));
  }

  fs::path directory_;
  fs::path file_;
  int saves_ = 0;
};

TEST_F(LevelWatcherTest, first_poll_loads_and_an_untouched_file_is_unchanged) {
  save(levelText("[1, 1, 1]"));
  game::LevelWatcher watcher(file_);
  EXPECT_EQ(watcher.poll(), Event::Reloaded);
  ASSERT_NE(watcher.level(), nullptr);
  EXPECT_EQ(watcher.level()->name, "Watched");
  EXPECT_EQ(watcher.poll(), Event::Unchanged);
  EXPECT_EQ(watcher.poll(), Event::Unchanged);
}

TEST_F(LevelWatcherTest, saving_the_level_reloads_it_with_the_new_values) {
  save(levelText("[1, 1, 1]"));
  game::LevelWatcher watcher(file_);
  ASSERT_EQ(watcher.poll(), Event::Reloaded);
  EXPECT_FLOAT_EQ(watcher.level()->materials[0].baseColor.r, 1.0f);
  save(levelText("[0, 1, 1]"));
  EXPECT_EQ(watcher.poll(), Event::Reloaded);
  EXPECT_FLOAT_EQ(watcher.level()->materials[0].baseColor.r, 0.0f);
}

TEST_F(LevelWatcherTest, invalid_edit_reports_the_error_and_keeps_the_last_good_level) {
  save(levelText("[1, 1, 1]"));
  game::LevelWatcher watcher(file_);
  ASSERT_EQ(watcher.poll(), Event::Reloaded);
  save(levelText("[1, 1, 2]"));  // 2 is out of range
  EXPECT_EQ(watcher.poll(), Event::Failed);
  EXPECT_NE(watcher.error().find("level.json:4:"), std::string::npos) << watcher.error();
  ASSERT_NE(watcher.level(), nullptr);
  EXPECT_FLOAT_EQ(watcher.level()->materials[0].baseColor.b, 1.0f);
  EXPECT_EQ(watcher.poll(), Event::Unchanged);  // reported once, not on every poll
  save(levelText("[0.5, 0.5, 0.5]"));
  EXPECT_EQ(watcher.poll(), Event::Reloaded);
  EXPECT_TRUE(watcher.error().empty());
}

TEST_F(LevelWatcherTest, a_level_that_never_loaded_has_no_level_and_an_error) {
  save("{ not json");
  game::LevelWatcher watcher(file_);
  EXPECT_EQ(watcher.poll(), Event::Failed);
  EXPECT_EQ(watcher.level(), nullptr);
  EXPECT_NE(watcher.error().find("invalid JSON"), std::string::npos) << watcher.error();
}

}  // namespace
