#pragma once
// The campaign's level order, levels/order.txt: one level file name a line, in chapters: a line
// "chapter: Mirrors" starts a chapter that holds the levels below it. Blank lines and everything
// after a '#' are ignored.
#include <filesystem>
#include <string>
#include <vector>

#include "game/level_loader.hpp"

namespace game {

struct OrderedLevel {
  std::string file;     // "01_first_light.json"
  std::string chapter;  // "" for levels listed before the first chapter line
  bool operator==(const OrderedLevel&) const = default;
};

// The levels of `levelsDirectory`/order.txt, in order, with their chapters. Throws LevelError,
// one line: "<dir>/order.txt: cannot open level order file", "<dir>/order.txt: lists no levels",
// or "<dir>/order.txt:<line>: <problem>" for a name that is a path, not a .json file, not in the
// directory, or listed twice, and for a chapter without a name, named twice or without levels.
std::vector<OrderedLevel> loadCampaign(const std::filesystem::path& levelsDirectory);

// The file names of loadCampaign, in order.
std::vector<std::string> loadLevelOrder(const std::filesystem::path& levelsDirectory);

}  // namespace game
