#include "app/options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "game/json_reader.hpp"

namespace app {

namespace {

// Every command: its arguments and what it does, as `sightline help` and `<command> --help` say.
struct CommandSpec {
  const char* name;
  const char* arguments;
  const char* summary;  // lines after the first are indented to line up
};

const std::vector<CommandSpec> kCommands{
    {"play", "[level.json]", "play in a window (without a display: render headless)"},
    {"render", "<level.json>", "render a level headless and write a PNG"},
    {"preview", "<level.json>",
     "render a thumbnail from the spawn camera (--watch: re-render\n"
     "whenever the level or a file it uses is saved)"},
    {"bench", "[level.json...]", "time every shipped level (or the given ones)"},
    {"bench-quality", "<level.json>",
     "soft-shadow error (RMSE, SSIM) against GPU time: a table, a CSV\n"
     "and a log-log plot in --out DIR (default out/)"},
    {"bench-upscale", "<level.json>",
     "the presented picture's error (RMSE, SSIM) against a supersampled one at\n"
     "--upscale WxH (default 1280x720): bilinear upscale, native 2x, temporal\n"
     "upscaling static and strafing; a table, a CSV and a plot in --out DIR"},
    {"bench-input", "",
     "time each file reader (level, replay, settings, progress, glTF)\n"
     "on worst-shaped input at 1x, 4x and 16x size (docs/ROBUSTNESS.md)"},
    {"validate", "<level.json...>", "check levels and report the first error in each"},
    {"info", "<level.json>", "triangles, instances, lights and the features a level uses"},
    {"devices", "", "list Vulkan devices and whether they can run Sightline"},
    {"replay", "<replay.json...>",
     "run replays headless and check their expectations (exit 0\n"
     "when all hold); --trace FILE.csv for the per-tick values"},
    {"campaign", "",
     "run every shipped level's replays: each level in levels/order.txt needs\n"
     "a winning and a failing one; prints the steps and game time of each win\n"
     "and checks the campaign's figures (docs/LEVELS.md)"},
    {"soak", "<level.json>",
     "run --frames frames (default 3000) with the movers going and\n"
     "fail if resident memory grows more than 1 MB after frame 500;\n"
     "with --validate also if a Vulkan object is left at exit"},
};

// Every option: its value (empty for a switch), what it does and the commands that take it.
struct OptionSpec {
  const char* name;
  const char* value;
  const char* help;
  std::vector<std::string> commands;
};

// The commands that make a Vulkan device and render with it.
const std::vector<std::string> kRendering{"play",   "render",        "preview",
                                          "bench",  "bench-quality", "bench-upscale",
                                          "replay", "campaign",      "soak"};
const std::vector<std::string> kPicture{"render", "preview", "bench", "bench-quality",
                                        "bench-upscale"};

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const std::vector<OptionSpec> kOptions{
    {"--size",
     "WxH",
     "image size (render: 320x180; play: render size, scaled to the window)",
     {"play", "render", "preview", "bench", "bench-quality", "bench-upscale", "soak"}},
    {"--out",
     "FILE",
     "PNG to write (render: out/<level>.png; bench-quality: a directory)",
     {"render", "preview", "bench-quality", "bench-upscale"}},
    {"--frames",
     "N",
     "frames to render (render: 1, bench: 300, soak: 3000)",
     {"render", "preview", "bench", "soak"}},
    {"--tonemap", "MODE", "aces (default) or identity (exposure, then clamp)", kPicture},
    {"--exposure", "X", "linear exposure multiplier (default 1)", kPicture},
    {"--row-groups", "N",
     "interleave launch rows in N groups (1 = off; default 8 on CPU drivers,\n1 on GPUs)",
     kPicture},
    {"--no-subgroup-counters", "",
     "one counter atomic per pixel even where the GPU could sum them per\nsubgroup first (to "
     "measure the difference)",
     kPicture},
    {"--no-light-routes", "",
     "light reaches surfaces and sensors only directly, not via mirrors (to\nmeasure what routing "
     "costs; probes then differ from the game's)",
     kPicture},
    {"--upscale",
     "WxH",
     "upscale temporally to this output size: jittered rays accumulated into\na history at WxH "
     "(the --size again gives plain temporal anti-aliasing)",
     {"render", "bench", "bench-upscale"}},
    {"--no-upscale",
     "",
     "scale the picture to the window bilinearly instead of temporal\nupscaling",
     {"play"}},
    {"--fixed-scale",
     "",
     "keep the render scale; without it, play traces fewer pixels while frames\ntake longer "
     "than 30 fps allows (the settings can turn that off)",
     {"play"}},
    {"--device", "SEL", "device index or part of its name (see `sightline devices`)", kRendering},
    {"--validate", "", "enable the Vulkan validation layer (with synchronization checks)",
     join(kRendering, {"devices"})},
    {"--reference", "", "ground truth, averaging --spp raw soft-shadow samples", {"render"}},
    {"--spp",
     "N",
     "samples per pixel for --reference (default 256)",
     {"render", "bench-quality", "bench-upscale"}},
    {"--picture-scale",
     "S",
     "the upscaled runs trace S of each side of the render size, as play's\ndynamic render "
     "scale does (default 1)",
     {"bench-upscale"}},
    {"--watch", "", "keep running and re-render on every save", {"preview"}},
    {"--watch-limit",
     "N",
     "with --watch: stop after N renders (for scripts and tests)",
     {"preview"}},
    {"--trace",
     "FILE.csv",
     "write each tick's probe values, goal progress, rules and player state",
     {"replay"}},
    {"--update-images", "", "store the image checkpoints as rendered now", {"replay"}},
    {"--quit-after-ticks",
     "N",
     "exit cleanly after N world ticks (for scripts and tests)",
     {"play"}},
    {"--hud-off", "", "no heads-up display (focus frame, goal bars, exposure meters)", {"play"}},
    {"--window-pass",
     "",
     "scale the picture into the window in the render pass on a CPU driver\ntoo, as on GPUs "
     "(where the CPU scales it otherwise; to compare)",
     {"play"}},
    {"--record",
     "FILE.json",
     "save the first level's run as a replay (until won, lost or quit)",
     {"play"}},
    {"--reset-progress", "", "forget which levels were won", {"play"}},
    {"--author",
     "",
     "start with the fly camera (F4): no gravity, collision, winning, losing\nor recording",
     {"play"}},
    {"--window", "WxH", "the window's size (default 1280x720)", {"play"}},
    {"--capture",
     "FILE.png",
     "with --quit-after-ticks: save the window's last image as the swapchain\nholds it "
     "(picture, HUD and text)",
     {"play"}},
    {"--capture-loading",
     "DIR",
     "save the window's image while each level loads (the loading screen)\nas DIR/<level>.png",
     {"play"}},
    {"--csv", "FILE", "also write the table as CSV", {"bench"}},
    {"--strafe",
     "",
     "the camera strafes 1 cm a frame, back and forth over 32 cm, so the\ndenoiser and the "
     "upscaler work as for a moving view",
     {"bench"}},
    {"--json", "FILE", "also write the table as JSON", {"bench"}},
    {"--embree-frames",
     "N",
     "frames of the Embree CPU reference per level and size (default 30,\n0 = skip it)",
     {"bench"}},
};

const CommandSpec* findCommand(const std::string& name) {
  for (const CommandSpec& command : kCommands)
    if (name == command.name) return &command;
  return nullptr;
}

const OptionSpec* findOption(const std::string& name) {
  for (const OptionSpec& option : kOptions)
    if (name == option.name) return &option;
  return nullptr;
}

bool takes(const OptionSpec& option, const std::string& command) {
  return std::find(option.commands.begin(), option.commands.end(), command) !=
         option.commands.end();
}

// `text` with every line after the first indented by `indent` spaces.
std::string indented(const std::string& text, size_t indent) {
  std::string result;
  for (const char c : text) {
    result += c;
    if (c == '\n') result += std::string(indent, ' ');
  }
  return result;
}

std::string column(std::string text, size_t width) {
  if (text.size() < width) return text + std::string(width - text.size(), ' ');
  return text + "\n" + std::string(width, ' ');
}

}  // namespace

std::string usage() {
  std::string text = "usage: sightline <command> [options]\n\ncommands:\n";
  for (const CommandSpec& command : kCommands) {
    const std::string head = std::string(command.name) + " " + command.arguments;
    text += "  " + column(head, 29) + indented(command.summary, 31) + "\n";
  }
  text +=
      "\n`sightline <command> --help` lists a command's options; `sightline --version` prints the\n"
      "version and the Vulkan device the game would use.\n";
  return text;
}

std::string commandUsage(const std::string& name) {
  const CommandSpec* command = findCommand(name);
  if (command == nullptr) return usage();
  std::string text = std::string("usage: sightline ") + command->name +
                     (*command->arguments ? std::string(" ") + command->arguments : "") +
                     " [options]\n\n" + command->summary + "\n";
  std::string options;
  for (const OptionSpec& option : kOptions) {
    if (!takes(option, name)) continue;
    const std::string head = std::string(option.name) + (*option.value ? " " : "") + option.value;
    options += "  " + column(head, 24) + indented(option.help, 26) + "\n";
  }
  text += options.empty() ? "\nno options\n" : "\noptions:\n" + options;
  return text;
}

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
  if (options.command == "--help" || options.command == "-h") options.command = "help";
  if (options.command == "--version" || options.command == "-V") options.command = "version";
  const bool known = findCommand(options.command) != nullptr || options.command == "help" ||
                     options.command == "version";
  if (!known) {
    std::vector<std::string> names{"help", "version"};
    for (const CommandSpec& command : kCommands) names.push_back(command.name);
    throw UsageError("unknown command '" + options.command + "'" +
                     game::didYouMean(game::nearMiss(options.command, names)));
  }
  for (int i = 2; i < argc; ++i) {
    const std::string argument = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(argument + ": expected a value after it");
      return argv[++i];
    };
    if (argument == "--help" || argument == "-h") {
      options.help = true;
      continue;
    }
    if (argument.size() > 1 && argument[0] == '-') {
      const OptionSpec* option = findOption(argument);
      if (option == nullptr) {
        std::vector<std::string> names;
        for (const OptionSpec& spec : kOptions) names.push_back(spec.name);
        throw UsageError("unknown option '" + argument + "'" +
                         game::didYouMean(game::nearMiss(argument, names)));
      }
      if (!takes(*option, options.command)) {
        throw UsageError(options.command + " does not take " + argument + "; `sightline " +
                         options.command + " --help` lists what it takes");
      }
    }
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
    } else if (argument == "--picture-scale") {
      const std::string text = value();
      char* end = nullptr;
      options.pictureScale = std::strtof(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(options.pictureScale > 0.0f) ||
          !(options.pictureScale <= 1.0f))
        throw UsageError("--picture-scale: expected a number in (0, 1], got '" + text + "'");
    } else if (argument == "--row-groups") {
      options.rowGroups = parseCount("--row-groups", value(), 1, 64);
    } else if (argument == "--no-subgroup-counters") {
      options.subgroupCounters = false;
    } else if (argument == "--no-light-routes") {
      options.lightRoutes = false;
    } else if (argument == "--upscale") {
      uint32_t width = 0, height = 0;
      parseSize("--upscale", value(), &width, &height);
      options.upscaleSize = {width, height};
    } else if (argument == "--no-upscale") {
      options.upscale = false;
    } else if (argument == "--fixed-scale") {
      options.fixedScale = true;
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
    } else if (argument == "--window-pass") {
      options.windowPass = true;
    } else if (argument == "--reset-progress") {
      options.resetProgress = true;
    } else if (argument == "--author") {
      options.author = true;
    } else if (argument == "--window") {
      uint32_t width = 0, height = 0;
      parseSize("--window", value(), &width, &height);
      options.windowSize = {width, height};
    } else if (argument == "--capture") {
      options.capture = value();
    } else if (argument == "--capture-loading") {
      options.captureLoading = value();
    } else if (argument == "--record") {
      options.record = value();
    } else if (argument == "--strafe") {
      options.strafe = true;
    } else if (argument == "--csv") {
      options.csv = value();
    } else if (argument == "--json") {
      options.json = value();
    } else if (argument == "--embree-frames") {
      options.embreeFrames = parseCount("--embree-frames", value(), 0, 1000000);
    } else if (argument == "--trace") {
      options.trace = value();
    } else {
      options.positional.push_back(argument);
    }
  }
  return options;
}

}  // namespace app
