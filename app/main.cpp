// `sightline` — the program entry: composes the game (levels) and the renderer.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/data_paths.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "render/context.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"
#include "render/shader_compiler.hpp"
#include "render/vulkan_error.hpp"

namespace fs = std::filesystem;

namespace {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr const char* kUsage = R"(usage: sightline <command> [options]

commands:
  play [level.json]            play (headless render until the window lands; see README)
  render <level.json>          render a level headless and write a PNG
  bench [level.json...]        time every shipped level (or the given ones)
  validate <level.json...>     check levels and report the first error in each
  devices                      list Vulkan devices and whether they can run Sightline

options:
  --size WxH          image size (render: 320x180)
  --out FILE          PNG to write (render: out/<level>.png)
  --frames N          frames to render (render: 1, bench: 300)
  --tonemap MODE      aces (default) or identity (exposure, then clamp)
  --exposure X        linear exposure multiplier (default 1)
  --row-groups N      interleave launch rows in N groups (default 8, 1 = off)
  --device SEL        device index or part of its name (see `sightline devices`)
  --validate          enable the Vulkan validation layer (with synchronization checks)
)";

struct Options {
  std::string command;
  std::vector<std::string> positional;
  uint32_t width = 320, height = 180;
  bool sizeGiven = false;
  std::optional<fs::path> out;
  std::optional<uint32_t> frames;
  render::Tonemap tonemap = render::Tonemap::Aces;
  float exposure = 1.0f;
  uint32_t rowGroups = 8;
  std::string device;
  bool validate = false;
};

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

void parseSize(const std::string& text, uint32_t* width, uint32_t* height) {
  const size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError("--size: expected WIDTHxHEIGHT, got '" + text + "'");
  *width = parseCount("--size width", text.substr(0, x), 1, 16384);
  *height = parseCount("--size height", text.substr(x + 1), 1, 16384);
}

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
      parseSize(value(), &options.width, &options.height);
      options.sizeGiven = true;
    } else if (argument == "--out") {
      options.out = value();
    } else if (argument == "--frames") {
      options.frames = parseCount("--frames", value(), 1, 1000000);
    } else if (argument == "--tonemap") {
      const std::string mode = value();
      if (mode == "aces")
        options.tonemap = render::Tonemap::Aces;
      else if (mode == "identity")
        options.tonemap = render::Tonemap::Identity;
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
    } else if (argument == "--device") {
      options.device = value();
    } else if (argument == "--validate") {
      options.validate = true;
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

render::ContextOptions contextOptions(const Options& options) {
  render::ContextOptions context;
  context.validate = options.validate;
  context.deviceSelector = options.device;
  return context;
}

render::ShaderCompiler makeCompiler(const fs::path& dataRoot) {
  return render::ShaderCompiler(dataRoot / "shaders",
                                render::ShaderCompiler::defaultCacheDirectory());
}

render::FrameDesc frameFor(const game::Level& level, const Options& options, uint32_t index) {
  render::FrameDesc frame;
  frame.camera = level.camera;
  frame.exposure = options.exposure;
  frame.tonemap = options.tonemap;
  frame.frameIndex = index;
  return frame;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

int validationExitCode(const render::Context& context) {
  if (context.validationEnabled() && context.validationMessageCount() > 0) {
    std::cerr << "sightline: " << context.validationMessageCount()
              << " validation message(s) (see above)\n";
    return 3;
  }
  return 0;
}

// Renders a level headless, writes the PNG, prints timing. Returns the exit code.
int renderLevel(const fs::path& levelFile, const Options& options, const fs::path& out) {
  const fs::path dataRoot = app::findDataRoot();
  const game::Level level = game::loadLevel(levelFile);
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(dataRoot);
  render::RendererOptions rendererOptions;
  rendererOptions.width = options.width;
  rendererOptions.height = options.height;
  rendererOptions.rowGroups = options.rowGroups;
  render::Renderer renderer(context, compiler, game::buildSceneDesc(level), rendererOptions);
  const uint32_t frames = options.frames.value_or(1);
  std::vector<double> times;
  render::FrameStats stats;
  for (uint32_t i = 0; i < frames; ++i) {
    stats = renderer.renderFrame(frameFor(level, options, i), i + 1 == frames);
    times.push_back(stats.milliseconds);
  }
  render::writePng(out, {renderer.width(), renderer.height(), renderer.pixels()});
  const double shown =
      frames > 1 ? median(std::vector<double>(times.begin() + 1, times.end())) : times.front();
  std::printf("%s: %ux%u on %s (%s)\n", level.name.c_str(), renderer.width(), renderer.height(),
              context.deviceInfo().name.c_str(), context.deviceInfo().driver.c_str());
  std::printf("frame time %.2f ms%s, %.2f Mrays/s (%llu primary + %llu shadow rays)\n", shown,
              frames > 1 ? " (median after the first)" : " (first frame, includes shader JIT)",
              double(stats.rays()) / (shown * 1000.0),
              static_cast<unsigned long long>(stats.primaryRays),
              static_cast<unsigned long long>(stats.shadowRays));
  std::printf("wrote %s\n", fs::absolute(out).c_str());
  return validationExitCode(context);
}

fs::path defaultOutput(const fs::path& levelFile) {
  return fs::path("out") / (levelFile.stem().string() + ".png");
}

int commandRender(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("render: expected one level file");
  const fs::path level = options.positional[0];
  return renderLevel(level, options, options.out.value_or(defaultOutput(level)));
}

int commandPlay(const Options& options) {
  fs::path level;
  if (!options.positional.empty()) {
    level = options.positional[0];
  } else {
    const auto levels = app::shippedLevels(app::findDataRoot());
    if (levels.empty()) throw UsageError("play: no levels found in levels/");
    level = levels.front();
  }
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display && *display) || (wayland && *wayland)) {
    std::printf("The game window is not built yet; rendering %s headless instead.\n",
                level.c_str());
  } else {
    std::printf("No display (DISPLAY and WAYLAND_DISPLAY are unset): rendering %s headless.\n",
                level.c_str());
  }
  return renderLevel(level, options, options.out.value_or(defaultOutput(level)));
}

int commandValidate(const Options& options) {
  if (options.positional.empty()) throw UsageError("validate: expected level files");
  int failures = 0;
  for (const std::string& file : options.positional) {
    try {
      const game::Level level = game::loadLevel(file);
      std::printf("%s: ok (%zu entities, %zu meshes, %zu lights)\n", file.c_str(),
                  level.entities.size(), level.meshes.size(), level.lights.size());
    } catch (const game::LevelError& error) {
      std::fprintf(stderr, "%s\n", error.what());
      ++failures;
    }
  }
  return failures ? 1 : 0;
}

int commandDevices() {
  const auto devices = render::Context::listDevices();
  if (devices.empty()) std::printf("no Vulkan devices found\n");
  for (const auto& device : devices) {
    std::printf("%u: %s [%s] %s — %s\n", device.index, device.name.c_str(),
                render::deviceTypeName(device.type), device.driver.c_str(),
                device.missingExtensions.empty()
                    ? "ray tracing: yes"
                    : render::describeMissingRayTracing(device).c_str());
  }
  return 0;
}

int commandBench(const Options& options) {
  const fs::path dataRoot = app::findDataRoot();
  std::vector<fs::path> levels(options.positional.begin(), options.positional.end());
  if (levels.empty()) levels = app::shippedLevels(dataRoot);
  std::vector<std::pair<uint32_t, uint32_t>> sizes = {{320, 180}, {640, 360}};
  if (options.sizeGiven) sizes = {{options.width, options.height}};
  const uint32_t frames = options.frames.value_or(300);
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(dataRoot);
  std::printf("device: %s (%s), %s\n", context.deviceInfo().name.c_str(),
              context.deviceInfo().driver.c_str(),
              render::deviceTypeName(context.deviceInfo().type));
  std::printf("%-24s %-9s %7s %10s %8s %9s %9s\n", "level", "size", "frames", "median ms", "fps",
              "Mrays/s", "triangles");
  for (const fs::path& levelFile : levels) {
    const game::Level level = game::loadLevel(levelFile);
    for (const auto& [width, height] : sizes) {
      render::RendererOptions rendererOptions;
      rendererOptions.width = width;
      rendererOptions.height = height;
      rendererOptions.rowGroups = options.rowGroups;
      render::Renderer renderer(context, compiler, game::buildSceneDesc(level), rendererOptions);
      for (uint32_t i = 0; i < 3; ++i) renderer.renderFrame(frameFor(level, options, i), false);
      std::vector<double> times;
      uint64_t rays = 0;
      for (uint32_t i = 0; i < frames; ++i) {
        const render::FrameStats stats = renderer.renderFrame(frameFor(level, options, i), false);
        times.push_back(stats.milliseconds);
        rays = stats.rays();
      }
      const double ms = median(times);
      std::printf("%-24s %4ux%-4u %7u %10.2f %8.1f %9.2f %9zu\n", levelFile.stem().c_str(), width,
                  height, frames, ms, 1000.0 / ms, double(rays) / (ms * 1000.0),
                  renderer.triangleCount());
      std::fflush(stdout);
    }
  }
  return validationExitCode(context);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parseOptions(argc, argv);
    if (options.command == "render") return commandRender(options);
    if (options.command == "play") return commandPlay(options);
    if (options.command == "bench") return commandBench(options);
    if (options.command == "validate") return commandValidate(options);
    if (options.command == "devices") return commandDevices();
    if (options.command == "help" || options.command == "--help" || options.command == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    throw UsageError("unknown command '" + options.command + "'");
  } catch (const UsageError& error) {
    std::fprintf(stderr, "sightline: %s\n\n%s", error.what(), kUsage);
    return 2;
  } catch (const game::LevelError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  } catch (const render::ShaderCompileError& error) {
    std::fprintf(stderr, "sightline: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sightline: %s\n", error.what());
    return 1;
  }
}
