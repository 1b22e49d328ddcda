#include "game/user_paths.hpp"
#include "game/json_error_sax.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

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
  std::string text;
  char chunk[1 << 14];
  while (text.size() <= maxBytes && (stream.read(chunk, sizeof chunk) || stream.gcount() > 0))
    text.append(chunk, static_cast<std::size_t>(stream.gcount()));
  if (stream.bad()) throw UserFileError(file.string() + ": cannot read: I/O error");
  if (text.size() > maxBytes)
    throw UserFileError(file.string() + ": larger than the " + std::to_string(maxBytes) +
                        "-byte limit");
  return text;
}

namespace {

constexpr std::size_t kMaxUserFileBytes = 1u << 20;

std::string locate(const fs::path& file, SourcePosition at) {
  return file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": ";
}

// Collects the first error of a SAX parse: syntax errors and numbers too large for a double
// alike, each with the byte where it was found (json::parse gives no position for the latter).
struct FirstJsonError : JsonErrorOnlySax<nlohmann::ordered_json> {
  std::size_t bytesRead = 0;
  std::string reason;

  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& error) override {
    bytesRead = position;
    // what() reads "[json.exception.parse_error.101] parse error at line 1, column 7: <reason>".
    reason = error.what();
    if (const std::size_t prefixEnd = reason.find("] "); prefixEnd != std::string::npos)
      reason.erase(0, prefixEnd + 2);
    if (reason.rfind("parse error", 0) == 0) {
      if (const std::size_t colon = reason.find(": "); colon != std::string::npos)
        reason.erase(0, colon + 2);
    }
    return false;
  }
};

}  // namespace

std::string describeJson(const nlohmann::ordered_json& value) {
  constexpr std::size_t kMaxShown = 40;
  std::string text = value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown - 3) + "...";
  return text;
}

std::optional<UserJsonFile> UserJsonFile::open(const fs::path& file, const std::string& versionKey,
                                               int version, const std::string& whenIgnored,
                                               std::vector<std::string>& messages) {
  std::optional<std::string> text;
  try {
    text = readUserFile(file, kMaxUserFileBytes);
  } catch (const UserFileError& error) {
    messages.push_back(error.what() + ("; " + whenIgnored));
    return std::nullopt;
  }
  if (!text) return std::nullopt;

  nlohmann::ordered_json root;
  try {
    root = nlohmann::ordered_json::parse(*text);
  } catch (const nlohmann::ordered_json::exception&) {
    FirstJsonError error;
    nlohmann::ordered_json::sax_parse(*text, &error);
    messages.push_back(locate(file, positionOfParseError(*text, error.bytesRead)) +
                       "invalid JSON: " + error.reason + "; " + whenIgnored);
    return std::nullopt;
  }
  if (!root.is_object()) {
    messages.push_back(locate(file, {}) + "expected an object, got " + describeJson(root) + "; " +
                       whenIgnored);
    return std::nullopt;
  }
  UserJsonFile opened(file, std::move(root), JsonPositions::scan(*text), messages);
  if (const auto& duplicate = opened.positions_.firstDuplicateKey()) {
    opened.reportAt(duplicate->position, duplicate->pointer, "duplicate key; the last one is used");
  }

  const std::string versionPointer = "/" + escapeJsonPointerToken(versionKey);
  const auto versionValue = opened.root_.find(versionKey);
  if (versionValue == opened.root_.end()) {
    // Older hand-written files may lack it; the fields still mean what version 1 says.
    opened.reportValue("", "missing \"" + versionKey + "\": " + std::to_string(version) +
                               "; reading the file as version " + std::to_string(version));
  } else if (!versionValue->is_number_integer() || versionValue->get<int64_t>() != version) {
    // A newer game wrote it (or it is damaged): its fields may mean something else.
    const SourcePosition at = opened.positions_.valueAt(versionPointer);
    messages.push_back(locate(file, at) + versionKey + ": expected version " +
                       std::to_string(version) + ", got " + describeJson(*versionValue) + "; " +
                       whenIgnored);
    return std::nullopt;
  }
  return opened;
}

void UserJsonFile::reportAt(SourcePosition at, const std::string& pointer,
                            const std::string& problem) {
  const std::string field = positions_.dottedPath(pointer);
  messages_->push_back(locate(file_, at) + (field.empty() ? "" : field + ": ") + problem);
}

void UserJsonFile::reportValue(const std::string& pointer, const std::string& problem) {
  reportAt(positions_.valueAt(pointer), pointer, problem);
}

void UserJsonFile::reportKey(const std::string& pointer, const std::string& problem) {
  reportAt(positions_.keyAt(pointer), pointer, problem);
}

void UserJsonFile::reportUnknownKeys(const std::string& pointer,
                                     const std::vector<std::string>& known,
                                     const std::string& what) {
  const nlohmann::ordered_json& object = root_.at(nlohmann::ordered_json::json_pointer(pointer));
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end())
      reportKey(pointer + "/" + escapeJsonPointerToken(key), what + "; ignored");
  }
}

}  // namespace game
