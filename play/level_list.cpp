#include "play/level_list.hpp"

#include <system_error>

namespace play {
namespace fs = std::filesystem;

namespace {

bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code error;
  return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
}

}  // namespace

std::vector<LevelListEntry> levelListEntries(const game::Progress& progress,
                                             const std::vector<fs::path>& levels,
                                             const std::vector<std::string>& names,
                                             const fs::path& playedFile) {
  std::vector<std::string> order;
  for (const fs::path& file : levels) order.push_back(file.filename().string());
  std::vector<LevelListEntry> entries;
  for (size_t i = 0; i < levels.size(); ++i) {
    LevelListEntry entry;
    entry.current = sameFile(levels[i], playedFile);
    const bool won = progress.completed.contains(order[i]);
    entry.selectable = entry.current || game::unlocked(progress, order, order[i]);
    entry.label = std::to_string(i + 1) + ". " + names[i] +
                  (won                ? "   [won]"
                   : entry.current    ? "   (playing)"
                   : entry.selectable ? ""
                                      : "   (locked)");
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace play
