// render and preview: draw a level headless and write a PNG (play falls back to render).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/session.hpp"
#include "game/level_loader.hpp"
#include "game/level_watcher.hpp"
#include "render/gpu_types.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

// A one-line progress bar on stderr, redrawn in place.
void printProgress(uint32_t done, uint32_t total) {
  constexpr int kWidth = 40;
  const int filled = int(uint64_t(done) * kWidth / total);
  std::fprintf(stderr, "\r[%s%s] %u/%u samples", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), '-').c_str(), done, total);
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

struct RenderResult {
  render::FrameStats last;
  double milliseconds = 0.0;  // the first frame's, or the median of the rest
};

// Renders `frames` frames of a level and writes the last one as a PNG.
RenderResult renderToPng(const render::Context& context, render::ShaderCompiler& compiler,
                         const game::Level& level, const Options& options, uint32_t frames,
                         const fs::path& out) {
  render::Renderer renderer(context, compiler, game::buildSceneDesc(level),
                            rendererOptionsFor(options, options.width, options.height));
  std::vector<double> times;
  RenderResult result;
  const bool showProgress = options.reference && frames > 1;
  for (uint32_t i = 0; i < frames; ++i) {
    scene::FrameDesc frame = frameFor(level, options, i);
    frame.referenceAccumulation = options.reference;
    result.last = renderer.renderFrame(frame, i + 1 == frames);
    times.push_back(result.last.milliseconds);
    if (showProgress) printProgress(i + 1, frames);
  }
  render::writePng(out, {renderer.outputWidth(), renderer.outputHeight(), renderer.pixels()});
  result.milliseconds =
      frames > 1 ? median(std::vector<double>(times.begin() + 1, times.end())) : times.front();
  return result;
}

void printWarnings(const game::Level& level) {
  for (const std::string& warning : level.warnings)
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
}

// Renders a level headless, writes the PNG, prints timing. Returns the exit code.
int renderLevel(const fs::path& levelFile, const Options& options, const fs::path& out) {
  const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
  printWarnings(level);
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  // Soft shadows are denoised over frames: by default, render until the history is full, so
  // the picture is the one play settles on, not one frame's stipple.
  const bool softShadows = game::levelFeatures(level).areaLights;
  const uint32_t settledFrames = softShadows ? uint32_t(DENOISER_MAX_HISTORY) : 1;
  const uint32_t frames =
      options.reference ? options.samplesPerPixel : options.frames.value_or(settledFrames);
  if (softShadows && !options.reference && frames < uint32_t(DENOISER_MAX_HISTORY)) {
    std::fprintf(stderr,
                 "note: %u frame%s of a level with soft shadows: the denoiser settles over %u "
                 "frames, so the shadows are still noisy\n",
                 frames, frames == 1 ? "" : "s", uint32_t(DENOISER_MAX_HISTORY));
  }
  const RenderResult result = renderToPng(context, compiler, level, options, frames, out);
  std::printf("%s: %ux%u on %s (%s)\n", level.name.c_str(), options.width, options.height,
              context.deviceInfo().name.c_str(), context.deviceInfo().driver.c_str());
  std::printf("frame time %.2f ms%s, %.2f Mrays/s (%llu surface + %llu shadow/glass rays)\n",
              result.milliseconds,
              frames > 1 ? " (median after the first)" : " (first frame, includes shader JIT)",
              double(result.last.rays()) / (result.milliseconds * 1000.0),
              static_cast<unsigned long long>(result.last.surfaceRays),
              static_cast<unsigned long long>(result.last.secondaryRays));
  const render::PassTimes& gpu = result.last.gpu;
  std::printf(
      "GPU time of the last frame: trace %.2f ms, denoise %.2f ms, tonemap %.2f ms, "
      "readback %.2f ms\n",
      gpu.traceMs, gpu.denoiseMs, gpu.tonemapMs, gpu.readbackMs);
  std::printf("wrote %s\n", fs::absolute(out).c_str());
  return validationExitCode(context);
}

// Re-renders whenever the level or a file it uses changes; an invalid edit keeps the last
// good image. Runs until interrupted, or until `watchLimit` renders.
int watchLevel(const fs::path& levelFile, const Options& options, const fs::path& out) {
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  game::LevelWatcher watcher(levelFile, levelLoadOptions());
  std::printf("watching %s and the files it uses; Ctrl-C stops\n", levelFile.c_str());
  std::fflush(stdout);
  uint32_t renders = 0;
  for (;;) {
    switch (watcher.poll()) {
      case game::LevelWatcher::Event::Unchanged:
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        continue;
      case game::LevelWatcher::Event::Failed:
        std::fprintf(stderr, "%s\n%s\n", watcher.error().c_str(),
                     watcher.level() ? "(keeping the last good level)" : "(waiting for a fix)");
        std::fflush(stderr);
        continue;
      case game::LevelWatcher::Event::Reloaded: {
        const game::Level& level = *watcher.level();
        printWarnings(level);
        const RenderResult result = renderToPng(context, compiler, level, options, 1, out);
        ++renders;
        std::printf("%s %s -> %s (%.1f ms)\n", renders == 1 ? "rendered" : "reloaded",
                    level.name.c_str(), fs::absolute(out).c_str(), result.milliseconds);
        std::fflush(stdout);
        if (options.watchLimit != 0 && renders >= options.watchLimit)
          return validationExitCode(context);
        break;
      }
    }
  }
}

fs::path defaultOutput(const fs::path& levelFile) {
  return fs::path("out") / (levelFile.stem().string() + ".png");
}

}  // namespace

int commandRender(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("render: expected one level file");
  const fs::path level = options.positional[0];
  return renderLevel(level, options, options.out.value_or(defaultOutput(level)));
}

}  // namespace app

namespace app {

int commandPreview(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("preview: expected one level file");
  const fs::path level = options.positional[0];
  const fs::path out =
      options.out.value_or(fs::path("out") / (level.stem().string() + ".preview.png"));
  return options.watch ? watchLevel(level, options, out) : renderLevel(level, options, out);
}

}  // namespace app
