// The pause menu's level list: what each line says and which lines can be picked.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "play/level_list.hpp"

namespace {

namespace fs = std::filesystem;

TEST(LevelList, a_level_opened_by_path_is_shown_as_playing_not_locked) {
  const std::vector<fs::path> levels{"levels/01_a.json", "levels/02_b.json", "levels/03_c.json"};
  const std::vector<std::string> names{"A", "B", "C"};
  game::Progress progress;  // nothing won: only the first is unlocked
  const auto entries = play::levelListEntries(progress, levels, names, {}, "levels/03_c.json");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].label, "1. A");
  EXPECT_TRUE(entries[0].selectable);
  EXPECT_EQ(entries[1].label, "2. B   (locked)");
  EXPECT_FALSE(entries[1].selectable);
  EXPECT_EQ(entries[2].label, "3. C   (playing)");
  EXPECT_TRUE(entries[2].selectable);
  EXPECT_TRUE(entries[2].current);
  progress.completed.insert("01_a.json");
  EXPECT_EQ(play::levelListEntries(progress, levels, names, {}, "levels/01_a.json")[0].label,
            "1. A   [won]");
}

TEST(LevelList, chapters_head_their_first_level_and_a_won_level_shows_its_best_time) {
  const std::vector<fs::path> levels{"levels/01_a.json", "levels/02_b.json", "levels/03_c.json"};
  const std::vector<std::string> names{"A", "B", "C"};
  const std::vector<std::string> chapters{"Sight", "Sight", "Glass"};
  game::Progress progress;
  game::markWon(progress, "01_a.json", 2538);
  const auto entries =
      play::levelListEntries(progress, levels, names, chapters, "levels/02_b.json");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].chapter, "Sight");
  EXPECT_EQ(entries[1].chapter, "");
  EXPECT_EQ(entries[2].chapter, "Glass");
  EXPECT_EQ(entries[0].label, "1. A   [won, best 42.3 s]");
  EXPECT_EQ(entries[1].label, "2. B   (playing)");
  EXPECT_EQ(entries[2].label, "3. C   (locked)");
}

TEST(LevelList, the_won_panel_says_the_time_and_the_best) {
  EXPECT_EQ(play::wonText(2538, std::nullopt), "Level complete in 42.3 s");
  EXPECT_EQ(play::wonText(2538, 2400), "Level complete in 42.3 s (best 40.0 s)");
  EXPECT_EQ(play::wonText(2400, 2538), "Level complete in 40.0 s, a new best (was 42.3 s)");
}

}  // namespace
