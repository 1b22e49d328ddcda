#pragma once
// Live reload: notices when a level's JSON or any file it was built from changes, reloads it,
// and keeps the last good level when an edit is invalid.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "game/level.hpp"
#include "game/level_loader.hpp"

namespace game {

class LevelWatcher {
 public:
  enum class Event {
    Unchanged,  // no watched file changed since the last poll
    Reloaded,   // level() is the newly loaded level
    Failed,     // the edit is invalid: error() says why, level() is still the last good one
  };

  explicit LevelWatcher(std::filesystem::path levelFile, LevelLoadOptions options = {});

  // Cheap when nothing changed (one stat per watched file); call it a few times a second.
  // The first call always loads.
  Event poll();

  const Level* level() const { return level_ ? &*level_ : nullptr; }
  const std::string& error() const { return error_; }

 private:
  struct FileStamp {
    std::filesystem::file_time_type modified{};
    uintmax_t size = 0;
    bool exists = false;
    bool operator==(const FileStamp&) const = default;
  };
  static FileStamp stamp(const std::filesystem::path& file);
  std::map<std::filesystem::path, FileStamp> currentStamps() const;

  std::filesystem::path levelFile_;
  LevelLoadOptions options_;
  std::optional<Level> level_;
  std::string error_;
  bool loadedOnce_ = false;
  std::map<std::filesystem::path, FileStamp> stamps_;  // of the files the last load used
};

}  // namespace game
