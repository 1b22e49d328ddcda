#pragma once
// What the glTF readers share: failing with "<file>: <problem>" and checking indices.
#include <filesystem>
#include <string>
#include <vector>

#include "game/level_loader.hpp"

namespace game::gltf {

[[noreturn]] inline void fail(const std::filesystem::path& file, const std::string& problem) {
  throw LevelError(file.string() + ": " + problem);
}

template <typename T>
bool validIndex(int index, const std::vector<T>& items) {
  return index >= 0 && static_cast<std::size_t>(index) < items.size();
}

}  // namespace game::gltf
