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

}  // namespace app
