#pragma once
// Moving through the levels: starting one, restarting it, the next after a win, and the saved
// progress (a won level unlocks the next; play starts at the first not yet won).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "game/level.hpp"
#include "game/replay.hpp"
#include "game/settings.hpp"
#include "game/tick_clock.hpp"
#include "play/play_options.hpp"
#include "sim/simulation.hpp"

struct GLFWwindow;

namespace play {

// The level being played.
struct PlayedLevel {
  // The simulation holds a reference to its level: it goes first.
  std::unique_ptr<game::Level> level;
  std::unique_ptr<sim::Simulation> simulation;
  std::filesystem::path file;
  uint32_t renderWidth = 320, renderHeight = 180;  // the simulation's rays and probes
  uint32_t outputWidth = 0, outputHeight = 0;      // its upscaled picture (0: not upscaled)
  std::optional<float> activeFov;                  // what the level started with
  float activeScale = 0.0f;
  game::TickClock tickClock;  // real time into ticks
  double lastFrameAt = 0.0;
  double outcomeAt = -1.0;             // when the level was won or lost; < 0 while playing
  std::optional<uint64_t> bestBefore;  // won: the level's best time before this win
  bool campaignFinished = false;       // the last shipped level was won: the end screen
  // False once the fly camera was used or the level was reloaded in place: a win then saves no
  // best time.
  bool timed = true;
  std::optional<game::Replay> recording;  // --record, until the first level's run ends
};

// What starting a level reads besides its file.
struct LevelSetup {
  const render::Context& context;
  render::ShaderCompiler& compiler;
  GLFWwindow* window;  // without --size, the picture follows its size
  const PlayOptions& options;
  const game::Settings& settings;                    // field of view, render scale
  const std::vector<std::filesystem::path>& levels;  // shipped, in play order
  // Shows that `level` is loading and how far it got (0 to 1, by the time each step took on a
  // 2-core CPU driver, where the first load compiles for seconds): once its file has been read,
  // once its simulation is made, and between the frames that prepare its pictures. Only when
  // the level started is another file than the one being played.
  std::function<void(const game::Level& level, float progress)> showLoading;
};

// Ends the recording of the level being left, then starts `file` (showing that it loads, see
// LevelSetup::showLoading). Throws game::LevelError when it does not load; the level being
// played stays.
void startLevel(PlayedLevel& played, const std::filesystem::path& file, const LevelSetup& setup);

// The functions below return true when a level started or the outcome just showed, so that the
// caller refreshes what shows the level (the window's title).

// F5 and "lost": the same file again, re-read so an edited level shows its changes. A level
// that no longer loads keeps the one being played (and says why).
bool restartLevel(PlayedLevel& played, const LevelSetup& setup);

// Won: the next shipped level; after the last, the end screen (campaignFinished); a level not
// shipped plays again.
bool startNextLevel(PlayedLevel& played, const LevelSetup& setup);

// Once the level is won or lost: ends the recording, saves a win (and its time) and says so; a
// moment later, won moves on to the next level and lost restarts this one.
bool advanceAfterOutcome(PlayedLevel& played, double now, const LevelSetup& setup);

// Where a new session starts: the first shipped level not yet won (all won: the first).
std::filesystem::path firstUnwonLevel(const std::vector<std::filesystem::path>& levels);

}  // namespace play
