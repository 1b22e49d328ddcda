#include "game/progress.hpp"

#include <algorithm>

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

}  // namespace

ProgressLoad loadProgress(const fs::path& file) {
  ProgressLoad load;
  auto opened =
      UserJsonFile::open(file, kVersionKey, kProgressVersion, kWhenIgnored, load.messages);
  if (!opened) return load;
  opened->reportUnknownKeys("", {kVersionKey, "completed"});
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
  writeFileAtomically(file, json.dump(2) + "\n");
}

bool unlocked(const Progress& progress, const std::vector<std::string>& order,
              const std::string& level) {
  const auto position = std::find(order.begin(), order.end(), level);
  if (position == order.end()) return false;
  if (position == order.begin()) return true;
  return progress.completed.contains(*std::prev(position));
}

void markWon(Progress& progress, const std::string& level) {
  progress.completed.insert(level);
}

}  // namespace game
