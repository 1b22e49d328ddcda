#include "game/level_watcher.hpp"

#include <utility>

namespace game {
namespace fs = std::filesystem;

LevelWatcher::LevelWatcher(fs::path levelFile, LevelLoadOptions options)
    : levelFile_(std::move(levelFile)), options_(std::move(options)) {}

LevelWatcher::FileStamp LevelWatcher::stamp(const fs::path& file) {
  std::error_code error;
  FileStamp result;
  result.modified = fs::last_write_time(file, error);
  if (error) return {};
  result.size = fs::file_size(file, error);
  result.exists = !error;
  return result;
}

std::map<fs::path, LevelWatcher::FileStamp> LevelWatcher::currentStamps() const {
  std::map<fs::path, FileStamp> stamps;
  stamps[levelFile_] = stamp(levelFile_);
  // After a failed edit the last good level's files are still the ones worth watching.
  if (level_) {
    for (const fs::path& file : level_->sourceFiles) stamps[file] = stamp(file);
  }
  return stamps;
}

LevelWatcher::Event LevelWatcher::poll() {
  std::map<fs::path, FileStamp> stamps = currentStamps();
  if (loadedOnce_ && stamps == stamps_) return Event::Unchanged;
  loadedOnce_ = true;
  stamps_ = std::move(stamps);
  try {
    level_ = loadLevel(levelFile_, options_);
    error_.clear();
    // Watch what the new level uses, with the stamps from before loading, so a save that
    // lands during the load is noticed at the next poll.
    std::map<fs::path, FileStamp> used;
    for (const auto& [file, newStamp] : currentStamps()) {
      auto before = stamps_.find(file);
      used[file] = before != stamps_.end() ? before->second : newStamp;
    }
    stamps_ = std::move(used);
    return Event::Reloaded;
  } catch (const LevelError& failure) {
    error_ = failure.what();
    return Event::Failed;
  }
}

}  // namespace game
