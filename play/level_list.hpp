#pragma once
// The pause menu's level list as plain data: a line per shipped level, whether it can be
// picked, and which one is being played.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/progress.hpp"

namespace play {

struct LevelListEntry {
  std::string chapter;  // the chapter's name on the first level of each chapter, else ""
  std::string label;    // "3. Glass and Mirrors   [won, best 12.3 s]"
  bool selectable = false;
  bool current = false;  // the level being played
};

// `names` and `chapters` parallel to `levels`. The level being played is always selectable and
// never shown as locked, however it was opened (by path, say, before the one before it was won).
std::vector<LevelListEntry> levelListEntries(const game::Progress& progress,
                                             const std::vector<std::filesystem::path>& levels,
                                             const std::vector<std::string>& names,
                                             const std::vector<std::string>& chapters,
                                             const std::filesystem::path& playedFile);

// The line the won level's panel shows: "Level complete in 42.3 s (best 40.1 s)", "... a new
// best (was 45.0 s)", or without a best before, "Level complete in 42.3 s".
std::string wonText(uint64_t ticks, std::optional<uint64_t> bestBefore);

}  // namespace play
