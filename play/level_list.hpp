#pragma once
// The pause menu's level list as plain data: a line per shipped level, whether it can be
// picked, and which one is being played.
#include <filesystem>
#include <string>
#include <vector>

#include "game/progress.hpp"

namespace play {

struct LevelListEntry {
  std::string label;  // "3. Glass and Mirrors   [won]"
  bool selectable = false;
  bool current = false;  // the level being played
};

// `names` parallel to `levels`. The level being played is always selectable and never shown as
// locked, however it was opened (by path, say, before the one before it was won).
std::vector<LevelListEntry> levelListEntries(const game::Progress& progress,
                                             const std::vector<std::filesystem::path>& levels,
                                             const std::vector<std::string>& names,
                                             const std::filesystem::path& playedFile);

}  // namespace play
