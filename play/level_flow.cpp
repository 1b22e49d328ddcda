#include "play/level_flow.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <GLFW/glfw3.h>

#include "game/level_loader.hpp"
#include "game/progress.hpp"
#include "game/user_paths.hpp"
#include "play/recording.hpp"
#include "play/window.hpp"
#include "render/context.hpp"

namespace play {
namespace fs = std::filesystem;

namespace {

constexpr double kOutcomeSeconds = 2.0;  // how long "won"/"lost" shows before moving on
constexpr uint32_t kMinRenderSide = 16;  // the smallest internal image side render scale gives
// Of a level's first load on lavapipe (2-core AMD EPYC, Mesa's cache empty), the part until its
// simulation is made (the ray tracing pipeline compiles for its first probe frame): 0.51 of
// 3.4 s (01) to 0.77 of 11.2 s (07); the rest prepares the pictures (docs/PERFORMANCE.md,
// session 41).
constexpr float kSimulationShareOfLoading = 0.65f;

// --size wins; otherwise the window's size (in screen units, so a high-DPI screen does not
// quadruple the work) times the render scale: 1280x720 at 0.25 gives 320x180.
// With upscaling, the picture is upscaled temporally to the window's size; on a CPU driver to at
// most twice the render size (where each output pixel costs about as much as a traced one: 1280
// x 720 took 39 ms, 640 x 360 10 ms on lavapipe), and the window's bilinear draw does the rest.
void chooseRenderSize(PlayedLevel& played, const LevelSetup& setup) {
  int width = 0, height = 0;
  glfwGetWindowSize(setup.window, &width, &height);
  if (width <= 0 || height <= 0) {  // minimised: the default window's shape
    width = kWindowWidth;
    height = kWindowHeight;
  }
  if (setup.options.pictureSize) {
    played.renderWidth = setup.options.pictureSize->first;
    played.renderHeight = setup.options.pictureSize->second;
  } else {
    const float scale = setup.settings.renderScale;
    played.renderWidth = std::max(kMinRenderSide, uint32_t(std::lround(width * scale)));
    played.renderHeight = std::max(kMinRenderSide, uint32_t(std::lround(height * scale)));
  }
  played.outputWidth = played.outputHeight = 0;
  if (!setup.options.upscale) return;
  const bool cpu = setup.context.isCpuDevice();
  played.outputWidth = cpu ? std::min(uint32_t(width), 2 * played.renderWidth) : uint32_t(width);
  played.outputHeight =
      cpu ? std::min(uint32_t(height), 2 * played.renderHeight) : uint32_t(height);
  // Not smaller than the picture: then there is nothing to upscale, only to anti-alias.
  played.outputWidth = std::max(played.outputWidth, played.renderWidth);
  played.outputHeight = std::max(played.outputHeight, played.renderHeight);
}

// Whether two paths name one file, however they are written (relative, with "..").
bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code errorA, errorB;
  const fs::path canonicalA = fs::weakly_canonical(a, errorA);
  const fs::path canonicalB = fs::weakly_canonical(b, errorB);
  return errorA || errorB ? a == b : canonicalA == canonicalB;
}

void finishRecordingOf(PlayedLevel& played) {
  finishRecording(played.recording, *played.simulation, played.level->name);
}

// A won level unlocks the next one and keeps its best time (progress.json); a failed save is
// said, not fatal. Returns the best time before this win.
std::optional<uint64_t> saveWin(const fs::path& levelFile, uint64_t ticks) {
  const fs::path file = game::progressFile();
  game::ProgressLoad loaded = game::loadProgress(file);
  const std::optional<uint64_t> before =
      game::markWon(loaded.progress, levelFile.filename().string(), ticks);
  try {
    game::saveProgress(loaded.progress, file);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "progress not saved: %s\n", error.what());
  }
  return before;
}

}  // namespace

void startLevel(PlayedLevel& played, const fs::path& file, const LevelSetup& setup) {
  if (played.simulation) finishRecordingOf(played);  // leaving the recorded level
  const double loadingStarted = glfwGetTime();
  auto level = std::make_unique<game::Level>(game::loadLevel(file, setup.options.levelLoading));
  for (const std::string& warning : level->warnings)
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  const game::Level& loading = *level;
  const bool announced = setup.showLoading && (!played.simulation || !sameFile(file, played.file));
  if (announced) setup.showLoading(loading, 0.0f);
  vkDeviceWaitIdle(setup.context.device());  // the last draw may still read the old image
  played.simulation.reset();
  played.level = std::move(level);
  played.file = file;
  chooseRenderSize(played, setup);
  played.activeFov = setup.settings.fieldOfViewDegrees;
  played.activeScale = setup.settings.renderScale;
  sim::SimulationOptions simulationOptions;
  simulationOptions.width = played.renderWidth;
  simulationOptions.height = played.renderHeight;
  simulationOptions.outputWidth = played.outputWidth;
  simulationOptions.outputHeight = played.outputHeight;
  simulationOptions.verticalFovDegrees = setup.settings.fieldOfViewDegrees;
  // A level's first probe frame on a CPU driver compiles for up to 8 s (07 The Crossing, Mesa's
  // cache empty): the window answers the desktop's pings meanwhile; what else happens waits.
  simulationOptions.whileWaiting = [] { glfwPollEvents(); };
  played.simulation = std::make_unique<sim::Simulation>(setup.context, setup.compiler,
                                                        *played.level, simulationOptions);
  if (announced) setup.showLoading(loading, kSimulationShareOfLoading);
  // No stall in the first frames played. Not shown after the last frame: the level starts.
  played.simulation->preparePictures([&](uint32_t done, uint32_t frames) {
    if (announced && done < frames)
      setup.showLoading(loading, kSimulationShareOfLoading + (1.0f - kSimulationShareOfLoading) *
                                                                 float(done) / float(frames));
  });
  played.tickClock.reset();
  played.lastFrameAt = glfwGetTime();  // loading time is not play time
  const double loadingSeconds = played.lastFrameAt - loadingStarted;
  played.outcomeAt = -1.0;
  played.bestBefore.reset();
  played.campaignFinished = false;
  played.timed = true;
  const std::string upscaled = played.outputWidth > 0
                                   ? ", upscaled to " + std::to_string(played.outputWidth) + "x" +
                                         std::to_string(played.outputHeight)
                                   : "";
  std::printf("playing %s (%s) at %ux%u%s; loaded in %.2f s\n", played.level->name.c_str(),
              file.c_str(), played.renderWidth, played.renderHeight, upscaled.c_str(),
              loadingSeconds);
  std::fflush(stdout);
}

bool restartLevel(PlayedLevel& played, const LevelSetup& setup) {
  try {
    startLevel(played, played.file, setup);
    return true;
  } catch (const game::LevelError& error) {
    std::fprintf(stderr, "%s\n(keeping the level as it was)\n", error.what());
    return false;
  }
}

bool startNextLevel(PlayedLevel& played, const LevelSetup& setup) {
  auto current = std::find_if(setup.levels.begin(), setup.levels.end(),
                              [&](const fs::path& level) { return sameFile(level, played.file); });
  if (current == setup.levels.end()) return restartLevel(played, setup);  // not shipped: again
  ++current;
  if (current == setup.levels.end()) {
    std::printf("that was the last level: the campaign is finished\n");
    std::fflush(stdout);
    played.campaignFinished = true;
    return true;
  }
  startLevel(played, *current, setup);
  return true;
}

bool advanceAfterOutcome(PlayedLevel& played, double now, const LevelSetup& setup) {
  const game::Outcome outcome = played.simulation->outcome();
  if (outcome == game::Outcome::Playing || played.campaignFinished) return false;
  if (played.outcomeAt < 0.0) {
    played.outcomeAt = now;
    finishRecordingOf(played);
    if (outcome == game::Outcome::Won)
      played.bestBefore = saveWin(played.file, played.timed ? played.simulation->tick() : 0);
    const game::Rules& rules = played.simulation->rules();
    std::printf("%s %s at tick %llu%s%s\n", outcome == game::Outcome::Won ? "won" : "lost",
                played.level->name.c_str(),
                static_cast<unsigned long long>(played.simulation->tick()),
                rules.reason().empty() ? "" : ": ", rules.reason().c_str());
    std::fflush(stdout);
    return true;
  }
  if (now - played.outcomeAt < kOutcomeSeconds) return false;
  if (outcome == game::Outcome::Won) return startNextLevel(played, setup);
  return restartLevel(played, setup);
}

fs::path firstUnwonLevel(const std::vector<fs::path>& levels) {
  const game::ProgressLoad loaded = game::loadProgress(game::progressFile());
  for (const std::string& message : loaded.messages) std::fprintf(stderr, "%s\n", message.c_str());
  for (const fs::path& level : levels) {
    if (!loaded.progress.completed.contains(level.filename().string())) return level;
  }
  return levels.front();
}

}  // namespace play
