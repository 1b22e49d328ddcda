#pragma once
// The player's own files (settings.json, progress.json): where they live (the XDG base
// directory spec), how they are written safely and read with a size cap.
#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace game {

// A user file that could not be written; what() names the file and the reason.
class UserFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// $XDG_CONFIG_HOME/sightline, else $HOME/.config/sightline. Relative values are ignored, as the
// spec requires; without a usable $HOME the password database's home directory is used, and
// with none at all UserFileError is thrown.
std::filesystem::path configDirectory();

// $XDG_DATA_HOME/sightline, else $HOME/.local/share/sightline; same rules.
std::filesystem::path dataDirectory();

// configDirectory()/settings.json and dataDirectory()/progress.json.
std::filesystem::path settingsFile();
std::filesystem::path progressFile();

// Replaces `file` with `contents` so that a crash or a power cut leaves either the old or the new
// file, never a half-written one: writes "<file>.tmp" in the same directory, flushes it to disk,
// renames it over `file`, then flushes the directory (and the parents of any directories it had
// to create), so the new file is on disk when this returns. Throws UserFileError.
void writeFileAtomically(const std::filesystem::path& file, const std::string& contents);

// A screenshot's file in `directory` named after `now` to the millisecond
// ("sightline-20261125-121530-042.png", local time), with "-2", "-3", ... added when a file of
// that name exists already, so no screenshot overwrites another.
std::filesystem::path newScreenshotFile(const std::filesystem::path& directory,
                                        std::chrono::system_clock::time_point now);

// The whole file, std::nullopt when it does not exist; throws UserFileError when it exists but
// cannot be read (a directory, no permission) or is larger than `maxBytes`.
std::optional<std::string> readUserFile(const std::filesystem::path& file, std::size_t maxBytes);

}  // namespace game
