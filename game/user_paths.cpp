#include "game/user_paths.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>

#include "game/json_document.hpp"

namespace game {

namespace fs = std::filesystem;

namespace {

// Set, non-empty and absolute; the XDG spec says relative paths are invalid and to be ignored.
std::optional<fs::path> absoluteEnvironmentPath(const char* name) {
  const char* value = std::getenv(name);
  if (!value || !*value) return std::nullopt;
  fs::path path(value);
  if (!path.is_absolute()) return std::nullopt;
  return path;
}

fs::path homeDirectory() {
  if (auto home = absoluteEnvironmentPath("HOME")) return *home;
  // $HOME can be missing under service managers; the password database still knows the home.
  if (const passwd* entry = getpwuid(getuid()); entry && entry->pw_dir && entry->pw_dir[0] == '/')
    return entry->pw_dir;
  throw UserFileError("no home directory: $HOME is unset or relative and getpwuid() has none");
}

fs::path xdgDirectory(const char* variable, const fs::path& underHome) {
  if (auto base = absoluteEnvironmentPath(variable)) return *base / "sightline";
  return homeDirectory() / underHome / "sightline";
}

std::string systemError(int error) {
  return std::strerror(error);
}

// Flushes a directory's entries (a rename, a new file or subdirectory) to the disk; `file` is
// the file being written, for the message.
void syncDirectory(const fs::path& directory, const fs::path& file) {
  const fs::path target = directory.empty() ? fs::path(".") : directory;
  const int descriptor = ::open(target.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0)
    throw UserFileError(file.string() + ": cannot open its directory " + target.string() +
                        " to flush it: " + systemError(errno));
  const int result = ::fsync(descriptor);
  const int error = errno;
  ::close(descriptor);
  // EINVAL: a file system that cannot flush directories (it has nothing more to do).
  if (result != 0 && error != EINVAL)
    throw UserFileError(file.string() + ": cannot flush its directory " + target.string() + ": " +
                        systemError(error));
}

}  // namespace

fs::path configDirectory() {
  return xdgDirectory("XDG_CONFIG_HOME", ".config");
}

fs::path dataDirectory() {
  return xdgDirectory("XDG_DATA_HOME", fs::path(".local") / "share");
}

fs::path settingsFile() {
  return configDirectory() / "settings.json";
}

fs::path progressFile() {
  return dataDirectory() / "progress.json";
}

void writeFileAtomically(const fs::path& file, const std::string& contents) {
  const fs::path directory = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  // The directories this call creates, deepest first: each one's entry in its parent must reach
  // the disk too, or a power cut could lose the new file together with its directory.
  std::vector<fs::path> created;
  for (fs::path missing = directory; !missing.empty(); missing = missing.parent_path()) {
    std::error_code error;
    if (fs::exists(missing, error) || error || missing == missing.parent_path()) break;
    created.push_back(missing);
  }
  {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error)
      throw UserFileError(file.string() + ": cannot create directory " + directory.string() + ": " +
                          error.message());
  }
  fs::path temporary = file;
  temporary += ".tmp";
  // POSIX calls rather than a stream: only they can fsync. The order is what makes a crash or
  // power cut at any moment leave the old file or the new one: the new contents reach the disk
  // (fsync of the temporary) before the rename makes them the file, and the rename itself
  // reaches the disk (fsync of the directory) before this returns.
  const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (descriptor < 0)
    throw UserFileError(temporary.string() + ": cannot create: " + systemError(errno));
  auto fail = [&](const std::string& what, int error) {
    ::close(descriptor);
    ::unlink(temporary.c_str());
    throw UserFileError(temporary.string() + ": cannot " + what + ": " + systemError(error));
  };
  for (std::size_t written = 0; written < contents.size();) {
    const ssize_t count = ::write(descriptor, contents.data() + written, contents.size() - written);
    if (count < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    written += static_cast<std::size_t>(count);
  }
  if (::fsync(descriptor) != 0) fail("flush", errno);
  if (::close(descriptor) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw UserFileError(temporary.string() + ": cannot close: " + systemError(error));
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw UserFileError(file.string() + ": cannot replace: " + systemError(error));
  }
  syncDirectory(directory, file);
  for (const fs::path& made : created) syncDirectory(made.parent_path(), file);
}

fs::path newScreenshotFile(const fs::path& directory, std::chrono::system_clock::time_point now) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto milliseconds =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm local{};
  localtime_r(&seconds, &local);
  char stamp[64];
  std::strftime(stamp, sizeof stamp, "sightline-%Y%m%d-%H%M%S", &local);
  char name[96];
  std::snprintf(name, sizeof name, "%s-%03d", stamp, int(milliseconds));
  fs::path file = directory / (std::string(name) + ".png");
  std::error_code error;
  for (int copy = 2; fs::exists(file, error); ++copy)
    file = directory / (std::string(name) + "-" + std::to_string(copy) + ".png");
  return file;
}

std::optional<std::string> readUserFile(const fs::path& file, std::size_t maxBytes) {
  std::error_code error;
  const fs::file_status status = fs::status(file, error);
  if (status.type() == fs::file_type::not_found) return std::nullopt;
  if (error) throw UserFileError(file.string() + ": cannot read: " + error.message());
  if (status.type() != fs::file_type::regular)
    throw UserFileError(file.string() + ": cannot read: not a regular file");
  std::ifstream stream(file, std::ios::binary);
  if (!stream.is_open()) throw UserFileError(file.string() + ": cannot read: cannot open");
  // Read in chunks and stop past the limit, so a huge file is never held in memory whole.
  std::string text = readAtMostPastLimit(stream, maxBytes);
  if (stream.bad()) throw UserFileError(file.string() + ": cannot read: I/O error");
  if (text.size() > maxBytes)
    throw UserFileError(file.string() + ": larger than the " + std::to_string(maxBytes) +
                        "-byte limit");
  return text;
}

}  // namespace game
