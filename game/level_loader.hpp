#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

#include "game/level.hpp"

namespace game {

// Thrown for any bad level input. what() is one line:
// "<file>:<line>:<column>: <JSON pointer>: expected <what>, got <what>".
class LevelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LevelLoadOptions {
  // Directories model files may be read from, besides the level file's own directory tree.
  // Default: the project's assets/ directory (found next to the levels/ directory).
  std::vector<std::filesystem::path> assetRoots;
};

// Parses, validates and resolves a level; nothing is returned half-loaded.
Level loadLevel(const std::filesystem::path& file, const LevelLoadOptions& options = {});

// Same, from text already in memory; `file` names it in messages and anchors relative paths.
Level parseLevel(const std::string& text, const std::filesystem::path& file,
                 const LevelLoadOptions& options = {});

}  // namespace game
