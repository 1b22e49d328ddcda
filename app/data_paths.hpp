#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "game/level_loader.hpp"

namespace app {

// The directory holding shaders/, levels/ and assets/: $SIGHTLINE_DATA_DIR, else next to the
// installed binary (../share/sightline), else the source tree the binary was built from.
std::filesystem::path findDataRoot();

// The shipped levels in play order: levels/order.txt when it exists, else levels/*.json by
// file name (the schema is not a level).
std::vector<std::filesystem::path> shippedLevels(const std::filesystem::path& dataRoot);
// Their chapters, parallel to shippedLevels ("" without order.txt or before its first chapter).
std::vector<std::string> shippedChapters(const std::filesystem::path& dataRoot);

// How every command loads a level: a path starting with "assets/" names the game's own asset
// directory (findDataRoot()/assets), wherever the level lives, installed or not.
game::LevelLoadOptions levelLoadOptions();

}  // namespace app
