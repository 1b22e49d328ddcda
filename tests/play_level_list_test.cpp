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
  const auto entries = play::levelListEntries(progress, levels, names, "levels/03_c.json");
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].label, "1. A");
  EXPECT_TRUE(entries[0].selectable);
  EXPECT_EQ(entries[1].label, "2. B   (locked)");
  EXPECT_FALSE(entries[1].selectable);
  EXPECT_EQ(entries[2].label, "3. C   (playing)");
  EXPECT_TRUE(entries[2].selectable);
  EXPECT_TRUE(entries[2].current);
  progress.completed.insert("01_a.json");
  EXPECT_EQ(play::levelListEntries(progress, levels, names, "levels/01_a.json")[0].label,
            "1. A   [won]");
}

}  // namespace
