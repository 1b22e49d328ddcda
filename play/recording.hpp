#pragma once
// What play writes of itself: --record's replay, --capture's PNG and F12 screenshots.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "game/replay.hpp"

namespace render {
class Presenter;
}
namespace sim {
class Simulation;
}

namespace play {

// --record: the first level's run, from its first tick until it is won, lost, left or the
// game quits, as a replay that `sightline replay` plays back to the same outcome. The ticks'
// inputs are appended as they are played (game::appendTickInput).
game::Replay startRecording(const std::filesystem::path& replayFile,
                            const std::filesystem::path& levelFile, uint32_t width, uint32_t height,
                            std::optional<float> verticalFovDegrees);

// Writes the run with the simulation's outcome and stops recording; nothing without a
// recording. Throws std::runtime_error when the file cannot be written.
void finishRecording(std::optional<game::Replay>& recording, const sim::Simulation& simulation,
                     const std::string& levelName);

// --capture and --capture-loading: the window's image of the frame captured last, as shown, as a
// PNG; says so with `when` ("at tick 600"). False (and said) when no frame was shown or the
// file could not be written.
bool writeCapture(render::Presenter& presenter, const std::filesystem::path& file,
                  const std::string& when);

// F12: the window as shown, in dataDirectory()/screenshots. False when nothing was shown yet
// (minimised): the capture waits for the next frame.
bool saveScreenshot(render::Presenter& presenter);

}  // namespace play
