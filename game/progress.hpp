#pragma once
// Which levels the player has won (progress.json in dataDirectory()) and what that unlocks.
// Same file rules as the settings: read forgivingly, written atomically.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace game {

struct Progress {
  std::set<std::string> completed;  // level file names, "01_first_light.json"
  // The fewest ticks (1/60 s) each won level took, by file name.
  std::map<std::string, uint64_t> bestTicks;
  bool operator==(const Progress&) const = default;
};

struct ProgressLoad {
  Progress progress;
  // One line each: "<file>:<line>:<column>: <field>: <problem>; ...".
  std::vector<std::string> messages;
};

// Never throws: a missing file is no progress, silently; an unreadable or corrupt one is no
// progress and one message; a bad entry is skipped with a message, keeping the others.
ProgressLoad loadProgress(const std::filesystem::path& file);

// Writes {"progress": 1, "completed": [...], "best_ticks": {...}} through writeFileAtomically;
// throws UserFileError.
void saveProgress(const Progress& progress, const std::filesystem::path& file);

// The first level of `order` is always unlocked, any other once the one before it is completed.
// A level not in `order` is not part of the campaign and is never unlocked by it.
bool unlocked(const Progress& progress, const std::vector<std::string>& order,
              const std::string& level);

// Completes `level`, keeping `ticks` as its best time when it is the first or fewer than before.
// Returns the best before this win (nullopt: none).
std::optional<uint64_t> markWon(Progress& progress, const std::string& level, uint64_t ticks);

// Seconds of game time for a tick count, "42.3 s" (one decimal).
std::string gameTimeText(uint64_t ticks);

}  // namespace game
