#pragma once
// What `sightline play` takes from the command line (app/ parses it).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <utility>

#include "game/level_loader.hpp"

namespace play {

struct PlayOptions {
  // --size WxH fixes the picture; otherwise it follows the window and the render scale.
  std::optional<std::pair<uint32_t, uint32_t>> pictureSize;
  uint64_t quitAfterTicks = 0;  // exit cleanly after this many ticks (0: play on)
  bool hudOff = false;          // no heads-up display or text over the picture
  // Temporal upscaling of the picture to the window's size (false: the window's bilinear draw
  // scales it).
  bool upscale = true;
  // No dynamic render scale (--fixed-scale); --size fixes the picture too.
  bool fixedScale = false;
  std::optional<std::filesystem::path> record;   // write the first level's run as a replay
  std::optional<std::filesystem::path> capture;  // the last frame's window image (PNG)
  // A folder for the window's image while each level loads (<level file name>.png).
  std::optional<std::filesystem::path> captureLoading;
  bool author = false;                  // --author: the fly camera from the start (F4 toggles it)
  game::LevelLoadOptions levelLoading;  // where "assets/" paths lead
};

}  // namespace play
