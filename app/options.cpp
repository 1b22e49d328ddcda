#include "app/options.hpp"

#include <cmath>
#include <cstdlib>

namespace app {

const char* const kUsage = R"(usage: sightline <command> [options]

commands:
  play [level.json]            play in a window (without a display: render headless)
  render <level.json>          render a level headless and write a PNG
  preview <level.json>         render a thumbnail from the spawn camera (--watch: re-render
                               whenever the level or a file it uses is saved)
  bench [level.json...]        time every shipped level (or the given ones)
  bench-quality <level.json>   soft-shadow error (RMSE, SSIM) against GPU time: a table, a CSV
                               and a log-log plot in --out DIR (default out/)
  validate <level.json...>     check levels and report the first error in each
  info <level.json>            triangles, instances, lights and the features a level uses
  devices                      list Vulkan devices and whether they can run Sightline
  replay <replay.json...>      run replays headless and check their expectations (exit 0
                               when all hold); --trace FILE.csv for the per-tick values
  soak <level.json>            run --frames frames (default 3000) with the movers going and
                               fail if resident memory grows more than 1 MB after frame 500;
                               with --validate also if a Vulkan object is left at exit

options:
  --size WxH          image size (render: 320x180; play: render size, scaled to the window)
  --out FILE          PNG to write (render: out/<level>.png)
  --frames N          frames to render (render: 1, bench: 300)
  --tonemap MODE      aces (default) or identity (exposure, then clamp)
  --exposure X        linear exposure multiplier (default 1)
  --row-groups N      interleave launch rows in N groups (1 = off; default 8 on CPU drivers,
                      1 on GPUs)
  --no-subgroup-counters  render, bench, bench-quality: one counter atomic per pixel even
                      where the GPU could sum them per subgroup first (to measure the difference)
  --device SEL        device index or part of its name (see `sightline devices`)
  --validate          enable the Vulkan validation layer (with synchronization checks)
  --reference         render: ground truth, averaging --spp raw soft-shadow samples
  --spp N             samples per pixel for --reference (default 256)
  --watch             preview: keep running and re-render on every save
  --watch-limit N     preview --watch: stop after N renders (for scripts and tests)
  --trace FILE.csv    replay: write each tick's probe values, goal progress and player state
  --update-images     replay: store the image checkpoints as rendered now
  --quit-after-ticks N
                      play: exit cleanly after N world ticks (for scripts and tests)
  --hud-off           play: no heads-up display (focus frame, goal bars, exposure meters)
  --record FILE.json  play: save the first level's run as a replay (until won, lost or quit)
  --reset-progress    play: forget which levels were won
  --window WxH        play: the window's size (default 1280x720)
  --capture FILE.png  play, with --quit-after-ticks: save the window's last image as the
                      swapchain holds it (picture, HUD and text)
  --csv FILE          bench: also write the table as CSV
  --json FILE         bench: also write the table as JSON
  --embree-frames N   bench: frames of the Embree CPU reference per level and size (default
                      30, 0 = skip it)
)";

namespace {

uint32_t parseCount(const std::string& option, const std::string& text, uint32_t low,
                    uint32_t high) {
  try {
    size_t used = 0;
    const unsigned long value = std::stoul(text, &used);
    if (used == text.size() && value >= low && value <= high) return static_cast<uint32_t>(value);
  } catch (const std::exception&) {
  }
  throw UsageError(option + ": expected a whole number from " + std::to_string(low) + " to " +
                   std::to_string(high) + ", got '" + text + "'");
}

void parseSize(const std::string& option, const std::string& text, uint32_t* width,
               uint32_t* height) {
  const size_t x = text.find('x');
  if (x == std::string::npos)
    throw UsageError(option + ": expected WIDTHxHEIGHT, got '" + text + "'");
  *width = parseCount(option + " width", text.substr(0, x), 1, 16384);
  *height = parseCount(option + " height", text.substr(x + 1), 1, 16384);
}

}  // namespace

Options parseOptions(int argc, char** argv) {
  Options options;
  if (argc < 2) throw UsageError("missing command");
  options.command = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(argument + ": expected a value after it");
      return argv[++i];
    };
    if (argument == "--size") {
      parseSize("--size", value(), &options.width, &options.height);
      options.sizeGiven = true;
    } else if (argument == "--out") {
      options.out = value();
    } else if (argument == "--frames") {
      options.frames = parseCount("--frames", value(), 1, 1000000);
    } else if (argument == "--tonemap") {
      const std::string mode = value();
      if (mode == "aces")
        options.tonemap = scene::Tonemap::Aces;
      else if (mode == "identity")
        options.tonemap = scene::Tonemap::Identity;
      else
        throw UsageError("--tonemap: expected aces or identity, got '" + mode + "'");
    } else if (argument == "--exposure") {
      const std::string text = value();
      char* end = nullptr;
      options.exposure = std::strtof(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(options.exposure >= 0.0f) ||
          !std::isfinite(options.exposure))
        throw UsageError("--exposure: expected a number >= 0, got '" + text + "'");
    } else if (argument == "--row-groups") {
      options.rowGroups = parseCount("--row-groups", value(), 1, 64);
    } else if (argument == "--no-subgroup-counters") {
      options.subgroupCounters = false;
    } else if (argument == "--device") {
      options.device = value();
    } else if (argument == "--validate") {
      options.validate = true;
    } else if (argument == "--reference") {
      options.reference = true;
    } else if (argument == "--spp") {
      options.samplesPerPixel = parseCount("--spp", value(), 1, 1000000);
    } else if (argument == "--watch") {
      options.watch = true;
    } else if (argument == "--watch-limit") {
      options.watchLimit = parseCount("--watch-limit", value(), 1, 1000000);
    } else if (argument == "--update-images") {
      options.updateImages = true;
    } else if (argument == "--quit-after-ticks") {
      options.quitAfterTicks = parseCount("--quit-after-ticks", value(), 1, 100000000);
    } else if (argument == "--hud-off") {
      options.hudOff = true;
    } else if (argument == "--reset-progress") {
      options.resetProgress = true;
    } else if (argument == "--window") {
      uint32_t width = 0, height = 0;
      parseSize("--window", value(), &width, &height);
      options.windowSize = {width, height};
    } else if (argument == "--capture") {
      options.capture = value();
    } else if (argument == "--record") {
      options.record = value();
    } else if (argument == "--csv") {
      options.csv = value();
    } else if (argument == "--json") {
      options.json = value();
    } else if (argument == "--embree-frames") {
      options.embreeFrames = parseCount("--embree-frames", value(), 0, 1000000);
    } else if (argument == "--trace") {
      options.trace = value();
    } else if (argument == "--help" || argument == "-h") {
      options.command = "help";
    } else if (!argument.empty() && argument[0] == '-') {
      throw UsageError("unknown option '" + argument + "'");
    } else {
      options.positional.push_back(argument);
    }
  }
  return options;
}

}  // namespace app
