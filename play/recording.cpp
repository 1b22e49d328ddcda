#include "play/recording.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "game/user_paths.hpp"
#include "render/image_io.hpp"
#include "render/presenter.hpp"
#include "sim/simulation.hpp"

namespace play {
namespace fs = std::filesystem;

game::Replay startRecording(const fs::path& replayFile, const fs::path& levelFile, uint32_t width,
                            uint32_t height, std::optional<float> verticalFovDegrees) {
  game::Replay replay;
  replay.file = fs::absolute(replayFile);
  replay.level = fs::absolute(levelFile);
  replay.width = width;
  replay.height = height;
  replay.verticalFovDegrees = verticalFovDegrees;
  sim::SimulationOptions defaults;
  replay.probeEveryTicks = defaults.probeEveryTicks;
  replay.probeLatency = defaults.probeLatency;
  replay.ticks = 0;
  return replay;
}

void finishRecording(std::optional<game::Replay>& recording, const sim::Simulation& simulation,
                     const std::string& levelName) {
  if (!recording) return;
  game::Replay& replay = *recording;
  const game::Outcome outcome = simulation.outcome();
  replay.outcome.outcome = outcome == game::Outcome::Won    ? game::ReplayOutcome::Won
                           : outcome == game::Outcome::Lost ? game::ReplayOutcome::Lost
                                                            : game::ReplayOutcome::Playing;
  replay.outcome.firstTick = replay.outcome.lastTick = simulation.tick();
  if (replay.ticks == 0) replay.ticks = 1;  // a replay runs at least one tick
  std::ofstream out(replay.file);
  out << game::replayToJson(replay);
  if (!out) throw std::runtime_error("cannot write the recording " + replay.file.string());
  std::printf("recorded %llu ticks of %s to %s\n",
              static_cast<unsigned long long>(simulation.tick()), levelName.c_str(),
              replay.file.c_str());
  std::fflush(stdout);
  recording.reset();
}

bool writeCapture(render::Presenter& presenter, const fs::path& file, const std::string& when) {
  const std::optional<render::Rgba8Image> image = presenter.takeCapture();
  if (!image) {
    std::fprintf(stderr, "%s: no frame was shown to capture (minimised window?)\n", file.c_str());
    return false;
  }
  try {
    render::writePng(file, *image);
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "capture not saved: %s\n", failure.what());
    return false;
  }
  std::printf("captured the window (%ux%u) %s to %s\n", image->width, image->height, when.c_str(),
              file.c_str());
  std::fflush(stdout);
  return true;
}

bool saveScreenshot(render::Presenter& presenter) {
  const std::optional<render::Rgba8Image> image = presenter.takeCapture();
  if (!image) return false;
  const fs::path directory = game::dataDirectory() / "screenshots";
  std::error_code error;
  fs::create_directories(directory, error);
  const fs::path file = game::newScreenshotFile(directory, std::chrono::system_clock::now());
  try {
    render::writePng(file, *image);
    std::printf("screenshot saved to %s\n", file.c_str());
  } catch (const std::exception& failure) {
    std::fprintf(stderr, "screenshot not saved: %s\n", failure.what());
  }
  std::fflush(stdout);
  return true;
}

}  // namespace play
