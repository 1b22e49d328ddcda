#include "app/data_paths.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include "game/level_order.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {
bool looksLikeDataRoot(const fs::path& root) {
  std::error_code error;
  return fs::is_directory(root / "shaders", error) && fs::is_directory(root / "levels", error);
}

fs::path executableDirectory() {
  std::error_code error;
  fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : self.parent_path();
}
}  // namespace

fs::path findDataRoot() {
  if (const char* explicitRoot = std::getenv("SIGHTLINE_DATA_DIR"); explicitRoot && *explicitRoot)
    return explicitRoot;
  const fs::path exeDir = executableDirectory();
  for (const fs::path& candidate :
       {exeDir / ".." / "share" / "sightline", exeDir, fs::path(SIGHTLINE_SOURCE_DIR)}) {
    if (!candidate.empty() && looksLikeDataRoot(candidate)) return fs::weakly_canonical(candidate);
  }
  return SIGHTLINE_SOURCE_DIR;
}

std::vector<fs::path> shippedLevels(const fs::path& dataRoot) {
  const fs::path levelsDirectory = dataRoot / "levels";
  std::vector<fs::path> levels;
  std::error_code error;
  // A broken order file throws game::LevelError: a shipped mistake should be loud, not reorder
  // the campaign silently.
  if (fs::exists(levelsDirectory / "order.txt", error)) {
    for (const std::string& name : game::loadLevelOrder(levelsDirectory))
      levels.push_back(levelsDirectory / name);
    return levels;
  }
  for (const auto& entry : fs::directory_iterator(levelsDirectory, error)) {
    const fs::path& path = entry.path();
    if (path.extension() == ".json" &&
        path.filename().string().find(".schema.") == std::string::npos)
      levels.push_back(path);
  }
  std::sort(levels.begin(), levels.end());
  return levels;
}

std::vector<std::string> shippedChapters(const fs::path& dataRoot) {
  const fs::path levelsDirectory = dataRoot / "levels";
  std::error_code error;
  if (!fs::exists(levelsDirectory / "order.txt", error))
    return std::vector<std::string>(shippedLevels(dataRoot).size());
  std::vector<std::string> chapters;
  for (const game::OrderedLevel& level : game::loadCampaign(levelsDirectory))
    chapters.push_back(level.chapter);
  return chapters;
}

game::LevelLoadOptions levelLoadOptions() {
  game::LevelLoadOptions options;
  options.assetRoots.push_back(findDataRoot() / "assets");
  return options;
}

}  // namespace app
