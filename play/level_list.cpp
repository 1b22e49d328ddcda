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
                                             const std::vector<std::string>& chapters,
                                             const fs::path& playedFile) {
  std::vector<std::string> order;
  for (const fs::path& file : levels) order.push_back(file.filename().string());
  std::vector<LevelListEntry> entries;
  for (size_t i = 0; i < levels.size(); ++i) {
    LevelListEntry entry;
    entry.current = sameFile(levels[i], playedFile);
    const bool won = progress.completed.contains(order[i]);
    entry.selectable = entry.current || game::unlocked(progress, order, order[i]);
    const std::string chapter = i < chapters.size() ? chapters[i] : "";
    if (i == 0 || chapter != (i - 1 < chapters.size() ? chapters[i - 1] : ""))
      entry.chapter = chapter;
    std::string state = won ? "   [won" : "";
    if (const auto best = progress.bestTicks.find(order[i]);
        won && best != progress.bestTicks.end())
      state += ", best " + game::gameTimeText(best->second);
    if (won) state += "]";
    entry.label = std::to_string(i + 1) + ". " + names[i] +
                  (won                ? state
                   : entry.current    ? "   (playing)"
                   : entry.selectable ? ""
                                      : "   (locked)");
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::string wonText(uint64_t ticks, std::optional<uint64_t> bestBefore) {
  const std::string time = "Level complete in " + game::gameTimeText(ticks);
  if (!bestBefore) return time;
  if (ticks < *bestBefore)
    return time + ", a new best (was " + game::gameTimeText(*bestBefore) + ")";
  return time + " (best " + game::gameTimeText(*bestBefore) + ")";
}

}  // namespace play
