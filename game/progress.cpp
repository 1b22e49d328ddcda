#include "game/progress.hpp"

#include <algorithm>
#include <cstdio>

#include "game/json_positions.hpp"
#include "game/user_json_file.hpp"
#include "game/user_paths.hpp"

namespace game {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr int kProgressVersion = 1;
const std::string kVersionKey = "progress";
const std::string kWhenIgnored = "starting with no levels completed";

// A bare file name: progress must not be able to name files outside the levels directory.
bool isLevelFileName(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

// "best_ticks": {"01_first_light.json": 175, ...}; a bad entry is skipped with a message.
void readBestTicks(UserJsonFile& opened, Progress& progress) {
  const auto best = opened.root().find("best_ticks");
  if (best == opened.root().end()) return;
  if (!best->is_object()) {
    opened.reportValue("/best_ticks",
                       "expected an object of level file names and tick counts, got " +
                           describeJson(*best) + "; no best times kept");
    return;
  }
  for (const auto& [name, ticks] : best->items()) {
    if (isLevelFileName(name) && ticks.is_number_unsigned() && ticks.get<uint64_t>() > 0) {
      progress.bestTicks[name] = ticks.get<uint64_t>();
    } else {
      opened.reportValue("/best_ticks/" + escapeJsonPointerToken(name),
                         "expected a level file name with a tick count above 0, got " +
                             describeJson(ticks) + "; ignored");
    }
  }
}

}  // namespace

ProgressLoad loadProgress(const fs::path& file) {
  ProgressLoad load;
  auto opened =
      UserJsonFile::open(file, kVersionKey, kProgressVersion, kWhenIgnored, load.messages);
  if (!opened) return load;
  opened->reportUnknownKeys("", {kVersionKey, "completed", "best_ticks"});
  readBestTicks(*opened, load.progress);
  const auto completed = opened->root().find("completed");
  if (completed == opened->root().end()) return load;
  if (!completed->is_array()) {
    opened->reportValue("/completed", "expected an array of level file names, got " +
                                          describeJson(*completed) + "; " + kWhenIgnored);
    return load;
  }
  for (std::size_t index = 0; index < completed->size(); ++index) {
    const Json& entry = (*completed)[index];
    if (entry.is_string() && isLevelFileName(entry.get<std::string>())) {
      load.progress.completed.insert(entry.get<std::string>());
    } else {
      opened->reportValue("/completed/" + std::to_string(index),
                          "expected a level file name such as \"01_first_light.json\", got " +
                              describeJson(entry) + "; ignored");
    }
  }
  return load;
}

void saveProgress(const Progress& progress, const fs::path& file) {
  Json json;
  json[kVersionKey] = kProgressVersion;
  json["completed"] = Json::array();
  for (const std::string& level : progress.completed) json["completed"].push_back(level);
  json["best_ticks"] = Json::object();
  for (const auto& [level, ticks] : progress.bestTicks) json["best_ticks"][level] = ticks;
  writeFileAtomically(file, json.dump(2) + "\n");
}

bool unlocked(const Progress& progress, const std::vector<std::string>& order,
              const std::string& level) {
  const auto position = std::find(order.begin(), order.end(), level);
  if (position == order.end()) return false;
  if (position == order.begin()) return true;
  return progress.completed.contains(*std::prev(position));
}

std::optional<uint64_t> markWon(Progress& progress, const std::string& level, uint64_t ticks) {
  progress.completed.insert(level);
  std::optional<uint64_t> before;
  if (const auto best = progress.bestTicks.find(level); best != progress.bestTicks.end())
    before = best->second;
  if (ticks > 0 && (!before || ticks < *before)) progress.bestTicks[level] = ticks;
  return before;
}

std::string gameTimeText(uint64_t ticks) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", double(ticks) / 60.0);
  return text;
}

}  // namespace game
