// bench: median frame times and ray throughput of every shipped level.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

struct Measurement {
  double medianMs = 0.0;
  uint64_t rays = 0;
  size_t triangles = 0;
};

// Median host time over `frames` frames after 3 warm-up frames.
Measurement measure(const render::Context& context, render::ShaderCompiler& compiler,
                    const game::Level& level, const Options& options, uint32_t width,
                    uint32_t height, uint32_t frames, bool allFeatures) {
  render::RendererOptions rendererOptions;
  rendererOptions.width = width;
  rendererOptions.height = height;
  rendererOptions.rowGroups = options.rowGroups;
  rendererOptions.allFeatures = allFeatures;
  render::Renderer renderer(context, compiler, game::buildSceneDesc(level), rendererOptions);
  for (uint32_t i = 0; i < 3; ++i) renderer.renderFrame(frameFor(level, options, i), false);
  std::vector<double> times;
  Measurement result;
  for (uint32_t i = 0; i < frames; ++i) {
    const render::FrameStats stats = renderer.renderFrame(frameFor(level, options, i), false);
    times.push_back(stats.milliseconds);
    result.rays = stats.rays();
  }
  result.medianMs = median(times);
  result.triangles = renderer.triangleCount();
  return result;
}

}  // namespace

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
  std::printf(
      "own variant = the pipeline built for the level's features; all = every feature on\n");
  std::printf("%-24s %-9s %7s %10s %8s %9s %9s %10s %9s\n", "level", "size", "frames", "median ms",
              "fps", "Mrays/s", "triangles", "all ms", "own/all");
  for (const fs::path& levelFile : levels) {
    const game::Level level = game::loadLevel(levelFile);
    for (const auto& [width, height] : sizes) {
      const Measurement own =
          measure(context, compiler, level, options, width, height, frames, false);
      const Measurement all =
          measure(context, compiler, level, options, width, height, frames, true);
      std::printf("%-24s %4ux%-4u %7u %10.2f %8.1f %9.2f %9zu %10.2f %9.2f\n",
                  levelFile.stem().c_str(), width, height, frames, own.medianMs,
                  1000.0 / own.medianMs, double(own.rays) / (own.medianMs * 1000.0), own.triangles,
                  all.medianMs, own.medianMs / all.medianMs);
      std::fflush(stdout);
    }
  }
  return validationExitCode(context);
}

}  // namespace app
