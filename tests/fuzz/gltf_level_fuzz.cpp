// Fuzz target for glTF models inside a level: the input becomes a model file (model.glb when it
// starts with the binary glTF magic "glTF", else model.gltf) in a temporary level root, next to a
// fixed level that uses it, and game::loadLevel must either load the level or throw a
// game::LevelError whose message is one line naming the level file. Bait files wait in the
// directory above the root; opening any of them (a model that reaches outside its root through
// "..", an absolute path or a URI) is a finding, seen through inotify. Anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding too.
#include <sys/inotify.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "game/level_loader.hpp"

namespace {

namespace fs = std::filesystem;

// The fixed level: one mesh from the model, one entity that uses the model's own material (so
// its textures are decoded too) and one that names a level material.
constexpr std::string_view kLevelTemplate = R"({
  "format": 1,
  "name": "glTF fuzz",
  "camera": {"position": [0, 1, 5]},
  "materials": {"grey": {"color": [0.5, 0.5, 0.5]}},
  "meshes": {"model": {"gltf": "MODEL"}},
  "entities": {
    "plain": {"mesh": "model", "material": "grey"},
    "own": {"mesh": "model", "position": [2, 0, 0]}
  },
  "lights": {"sun": {"type": "directional", "direction": [0, -1, 0]}}
}
)";

// Files a seed model may name next to it (the shipped crate's buffer and textures), and the
// same names plus a few more above the root as bait.
constexpr std::array kRootFiles = {"crate.bin", "crate_color.png", "crate_normal.png"};
constexpr std::array kBaitFiles = {"crate.bin",   "crate_color.png", "crate_normal.png",
                                   "outside.bin", "outside.png",     "level.json"};

[[noreturn]] void die(const std::string& problem) {
  std::fprintf(stderr, "gltf_level_fuzz: %s\n", problem.c_str());
  std::abort();
}

void writeFile(const fs::path& file, std::string_view contents) {
  std::ofstream stream(file, std::ios::binary | std::ios::trunc);
  stream.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  if (!stream) die("cannot write " + file.string());
}

std::string levelText(const std::string& model) {
  std::string text(kLevelTemplate);
  text.replace(text.find("MODEL"), 5, model);
  return text;
}

class FuzzRoot {
 public:
  FuzzRoot() {
    std::string pattern = (fs::temp_directory_path() / "sightline-gltf-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) die("mkdtemp failed");
    work_ = pattern;
    root_ = work_ / "level";
    fs::create_directories(root_);
    const fs::path assets = fs::path(SIGHTLINE_SOURCE_DIR) / "assets";
    for (const char* name : kRootFiles) fs::copy_file(assets / name, root_ / name);
    for (const char* name : kBaitFiles) writeFile(work_ / name, "bait: outside the level root\n");
    writeFile(root_ / "level_gltf.json", levelText("model.gltf"));
    writeFile(root_ / "level_glb.json", levelText("model.glb"));
    // Opens of files in the directory above the root, not of the root itself (a directory).
    inotify_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (inotify_ < 0 || inotify_add_watch(inotify_, work_.c_str(), IN_OPEN | IN_ACCESS) < 0)
      die("inotify: " + std::string(std::strerror(errno)));
  }
  ~FuzzRoot() {
    if (inotify_ >= 0) close(inotify_);
    std::error_code ignored;
    fs::remove_all(work_, ignored);
  }

  const fs::path& root() const { return root_; }

  // Aborts naming the file when anything opened or read a bait file since the last call.
  void checkNothingOutsideWasOpened() const {
    alignas(inotify_event) char buffer[4096];
    const ssize_t length = read(inotify_, buffer, sizeof buffer);
    if (length <= 0) return;  // EAGAIN: no events
    for (ssize_t at = 0; at < length;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (!(event->mask & IN_ISDIR) && event->len > 0)
        die("the loader opened " + (work_ / event->name).string() + ", outside the level root");
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }

 private:
  fs::path work_;
  fs::path root_;
  int inotify_ = -1;
};

const FuzzRoot& fuzzRoot() {
  static const FuzzRoot root;
  return root;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const FuzzRoot& work = fuzzRoot();
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const bool binary = bytes.substr(0, 4) == "glTF";
  const fs::path model = work.root() / (binary ? "model.glb" : "model.gltf");
  const fs::path level = work.root() / (binary ? "level_glb.json" : "level_gltf.json");
  writeFile(model, bytes);
  try {
    game::loadLevel(level);
  } catch (const game::LevelError& error) {
    // Shown as "<file>:...": it must name the level file and stay on one line.
    const std::string message = error.what();
    if (message.rfind(level.string() + ":", 0) != 0)
      die("LevelError message does not start with the level file: " + message);
    if (message.find('\n') != std::string::npos)
      die("LevelError message spans several lines: " + message);
  }
  work.checkNothingOutsideWasOpened();
  return 0;
}
