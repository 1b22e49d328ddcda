#pragma once
// What the settings and progress fuzz targets share: the input written where the loader reads
// it (the loaders read files), and the rule that every message is one line naming the file.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fuzz {

[[noreturn]] inline void die(const std::string& problem, const std::string& detail) {
  std::fprintf(stderr, "user_file_fuzz: %s: %s\n", problem.c_str(), detail.c_str());
  std::abort();
}

// Writes the input to <temp>/sightline-fuzz-<pid>/<name> and returns that path.
inline std::filesystem::path writeInput(const std::string& name, const uint8_t* data,
                                        std::size_t size) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("sightline-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(directory);
  const std::filesystem::path file = directory / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

inline void checkMessages(const std::vector<std::string>& messages,
                          const std::filesystem::path& file) {
  for (const std::string& message : messages) {
    if (message.rfind(file.string() + ":", 0) != 0)
      die("a message does not start with the file", message);
    if (message.find('\n') != std::string::npos) die("a message spans lines", message);
  }
}

// The whole check for one user file: `name` holds the input; `load(path)` gives a result with
// `messages`, and `held(result)` what it holds; `save(held, path)` writes that back.
template <typename Load, typename Held, typename Save>
void checkUserFile(const std::string& name, const uint8_t* data, std::size_t size, Load load,
                   Held held, Save save) {
  const std::filesystem::path file = writeInput(name, data, size);
  decltype(load(file)) loaded;
  try {
    loaded = load(file);
  } catch (const std::exception& error) {
    die("loading " + name + " threw", error.what());
  }
  checkMessages(loaded.messages, file);
  const std::filesystem::path again = file.parent_path() / ("saved_" + name);
  save(held(loaded), again);
  const auto reloaded = load(again);
  if (!reloaded.messages.empty())
    die("saved " + name + " loads with a message", reloaded.messages[0]);
  if (!(held(reloaded) == held(loaded))) die(name + " changed in a save and load", "");
}

}  // namespace fuzz
