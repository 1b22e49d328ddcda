#pragma once
// The campaign's level order, levels/order.txt: one level file name a line; blank lines and
// everything after a '#' are ignored.
#include <filesystem>
#include <string>
#include <vector>

#include "game/level_loader.hpp"

namespace game {

// The level file names of `levelsDirectory`/order.txt, in order. Throws LevelError, one line:
// "<dir>/order.txt: cannot open level order file", "<dir>/order.txt: lists no levels", or
// "<dir>/order.txt:<line>: <problem>" for a name that is a path, not a .json file, not in the
// directory, or listed twice.
std::vector<std::string> loadLevelOrder(const std::filesystem::path& levelsDirectory);

}  // namespace game
