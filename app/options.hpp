#pragma once
// The `sightline` command line: one command, its arguments and options.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_desc.hpp"

namespace app {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What `sightline help` prints: the commands, one line each.
std::string usage();
// What `sightline <command> --help` prints: its arguments and the options it takes.
std::string commandUsage(const std::string& command);

struct Options {
  std::string command;  // "help" and "version" too
  bool help = false;    // <command> --help
  std::vector<std::string> positional;
  uint32_t width = 320, height = 180;
  bool sizeGiven = false;
  std::optional<std::filesystem::path> out;
  std::optional<uint32_t> frames;
  scene::Tonemap tonemap = scene::Tonemap::Aces;
  float exposure = 1.0f;
  uint32_t rowGroups = 0;        // 0: the renderer's choice for the device
  bool subgroupCounters = true;  // --no-subgroup-counters: one atomic per pixel
  bool lightRoutes = true;       // --no-light-routes: direct light only
  // --upscale WxH: temporal upscaling to this output size (render, bench, bench-quality)
  std::optional<std::pair<uint32_t, uint32_t>> upscaleSize;
  bool upscale = true;      // play --no-upscale: the window's bilinear draw scales the picture
  bool fixedScale = false;  // play --fixed-scale: no dynamic render scale
  std::string device;
  bool validate = false;
  bool watch = false;
  bool reference = false;  // render: accumulate raw soft-shadow samples, no denoiser
  uint32_t samplesPerPixel = 256;
  // bench-upscale --picture-scale S: the upscaled runs trace S of each side of the render size
  // (what play's dynamic render scale does), in (0, 1]
  float pictureScale = 1.0f;
  uint32_t watchLimit = 0;                     // 0: no limit
  std::optional<std::filesystem::path> trace;  // replay: per-tick CSV of probes and player
  bool updateImages = false;    // replay: write image checkpoints instead of comparing
  uint64_t quitAfterTicks = 0;  // play: exit cleanly after this many ticks (0: play on)
  bool hudOff = false;          // play: no heads-up display over the picture
  bool windowPass = false;      // play: the picture scaled by the render pass on CPU drivers too
  std::optional<std::filesystem::path> record;  // play: write the first level's run as a replay
  bool resetProgress = false;                   // play: lock every level but the first again
  bool author = false;                          // play: start with the fly camera
  std::optional<std::pair<uint32_t, uint32_t>> windowSize;  // play: --window WxH
  std::optional<std::filesystem::path> capture;         // play: the last frame's window image (PNG)
  std::optional<std::filesystem::path> captureLoading;  // play: each loading screen, a PNG in it
  std::optional<std::filesystem::path> csv;             // bench: the table as CSV
  std::optional<std::filesystem::path> json;            // bench: the table as JSON
  uint32_t embreeFrames = 30;                           // bench: Embree reference frames (0: none)
  bool strafe = false;  // bench: the camera strafes back and forth (a moving view's passes)
};

// Throws UsageError naming the option and what was expected: an unknown option (with the
// nearest known one), or one the command does not take.
Options parseOptions(int argc, char** argv);

}  // namespace app
