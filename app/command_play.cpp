// play: the game in a GLFW window. Fixed 60 Hz ticks drive the simulation; every displayed
// frame renders a picture at the internal resolution and the presenter scales it to the window.
// Without a display (or when no window can be opened) it renders the level headless instead.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "game/progress.hpp"
#include "game/replay.hpp"
#include "game/rules.hpp"
#include "game/settings.hpp"
#include "game/user_paths.hpp"
#include "render/context.hpp"
#include "render/presenter.hpp"
#include "render/vulkan_error.hpp"
#include "sim/simulation.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

constexpr int kWindowWidth = 1280, kWindowHeight = 720;
constexpr double kTickSeconds = game::Rules::TICK_SECONDS;
// A frame slower than this many ticks lets the game fall behind real time instead of
// spending ever longer frames catching up.
constexpr int kMaxTicksPerFrame = 5;
constexpr double kOutcomeSeconds = 2.0;  // how long "won"/"lost" shows before moving on
constexpr float kStickDegreesPerSecond = 150.0f;
constexpr float kStickDeadZone = 0.2f;
constexpr uint32_t kWheelAdjustTicks = 6;  // one wheel notch adjusts for 0.1 s
constexpr double kTitleSeconds = 0.5;      // how often the title's fps and progress refresh

std::string glfwErrorText = "unknown error";

void onGlfwError(int, const char* description) {
  glfwErrorText = description ? description : "unknown error";
}

int renderHeadless(const Options& options, const fs::path& level) {
  Options headless = options;
  headless.positional = {level.string()};
  return commandRender(headless);
}

// Presses and wheel turns since the last frame, gathered by GLFW's callbacks.
struct PendingEvents {
  std::vector<int> keysPressed;
  double wheel = 0.0;
};

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_PRESS)
    static_cast<PendingEvents*>(glfwGetWindowUserPointer(window))->keysPressed.push_back(key);
}

void onScroll(GLFWwindow* window, double, double y) {
  static_cast<PendingEvents*>(glfwGetWindowUserPointer(window))->wheel += y;
}

float deadZone(float axis) {
  return std::abs(axis) < kStickDeadZone ? 0.0f : axis;
}

// The first connected joystick GLFW knows as a gamepad, if any.
bool readGamepad(GLFWgamepadstate* state) {
  for (int joystick = GLFW_JOYSTICK_1; joystick <= GLFW_JOYSTICK_LAST; ++joystick) {
    if (glfwJoystickIsGamepad(joystick) && glfwGetGamepadState(joystick, state)) return true;
  }
  return false;
}

class Game {
 public:
  Game(const Options& options, const game::Settings& settings, GLFWwindow* window,
       const render::Context& context, render::ShaderCompiler& compiler,
       render::Presenter& presenter)
      : options_(options),
        settings_(settings),
        window_(window),
        context_(context),
        compiler_(compiler),
        presenter_(presenter),
        levels_(shippedLevels(findDataRoot())),
        shownExtent_(presenter.extent()),
        shownMode_(presenter.presentMode()) {
    glfwSetWindowUserPointer(window_, &events_);
    glfwSetKeyCallback(window_, onKey);
    glfwSetScrollCallback(window_, onScroll);
  }

  // Plays until the window closes or --quit-after-ticks; returns the exit status.
  int run(const fs::path& firstLevel) {
    load(firstLevel);
    if (options_.record) startRecording();
    setPaused(false);
    const double started = glfwGetTime();
    double titleAt = started;
    uint32_t framesSinceTitle = 0;
    while (!glfwWindowShouldClose(window_)) {
      if (paused_)
        glfwWaitEventsTimeout(0.05);  // nothing moves: no need to spin
      else
        glfwPollEvents();
      handlePresses();
      const double now = glfwGetTime();
      const double elapsed = now - lastFrameAt_;
      lastFrameAt_ = now;
      if (!paused_) {
        gatherMouseLook();
        runTicks(elapsed);
        if (options_.quitAfterTicks != 0 && ticksPlayed_ >= options_.quitAfterTicks) {
          std::printf("quit after %llu ticks, %llu frames shown (%.1f fps)\n",
                      static_cast<unsigned long long>(ticksPlayed_),
                      static_cast<unsigned long long>(framesShown_),
                      double(framesShown_) / std::max(now - started, 1e-3));
          break;
        }
        advanceAfterOutcome(now);
      }
      simulation_->renderPicture();
      const std::vector<render::HudRect> hud =
          options_.hudOff ? std::vector<render::HudRect>{} : hudRects();
      if (presenter_.present(simulation_->renderer(), hud)) ++framesShown_;
      reportSwapchainChange();
      ++framesSinceTitle;
      if (now - titleAt >= kTitleSeconds) {
        updateTitle(framesSinceTitle / (now - titleAt));
        titleAt = now;
        framesSinceTitle = 0;
      }
    }
    finishRecording();
    // The presenter's last blit reads the renderer's image: finish it before either goes.
    vkDeviceWaitIdle(context_.device());
    simulation_.reset();
    return 0;
  }

 private:
  // The heads-up display: each focus region's frame, a bar per goal (blue, green when met),
  // a meter per exposure probe (orange), and a band at the top once the level is won (green)
  // or lost (red-orange).
  std::vector<render::HudRect> hudRects() const {
    using render::HudColour;
    std::vector<render::HudRect> rects;
    for (const game::FocusProbe& focus : simulation_->layout().focus) {
      const float x0 = 0.5f - focus.region.x / 2, x1 = 0.5f + focus.region.x / 2;
      const float y0 = 0.5f - focus.region.y / 2, y1 = 0.5f + focus.region.y / 2;
      constexpr float kLine = 0.004f;
      rects.push_back({x0, y0, x1, y0 + kLine, HudColour::White});
      rects.push_back({x0, y1 - kLine, x1, y1, HudColour::White});
      rects.push_back({x0, y0, x0 + kLine, y1, HudColour::White});
      rects.push_back({x1 - kLine, y0, x1, y1, HudColour::White});
    }
    auto bar = [&](float x0, int row, float value, HudColour fill) {
      constexpr float kWidth = 0.3f, kHeight = 0.025f, kGap = 0.045f;
      const float y0 = 0.93f - kGap * float(row), y1 = y0 + kHeight;
      rects.push_back({x0, y0, x0 + kWidth, y1, HudColour::Shade});
      if (value > 0.0f)
        rects.push_back({x0, y0, x0 + kWidth * std::clamp(value, 0.0f, 1.0f), y1, fill});
    };
    const auto& goals = simulation_->rules().progress();
    for (size_t i = 0; i < goals.size() && i < 4; ++i)
      bar(0.02f, int(i), goals[i].progress,
          goals[i].met ? HudColour::BluishGreen : HudColour::SkyBlue);
    if (const auto& readings = simulation_->latestReadings()) {
      for (size_t i = 0; i < readings->exposure.size() && i < 4; ++i)
        bar(0.68f, int(i), readings->exposure[i], HudColour::Orange);
    }
    const game::Outcome outcome = simulation_->outcome();
    if (outcome != game::Outcome::Playing)
      rects.push_back(
          {0.0f, 0.02f, 1.0f, 0.06f,
           outcome == game::Outcome::Won ? HudColour::BluishGreen : HudColour::Vermillion});
    return rects;
  }

  // A won level unlocks the next one (progress.json); a failed save is said, not fatal.
  void saveWin() {
    const fs::path file = game::progressFile();
    game::ProgressLoad loaded = game::loadProgress(file);
    game::markWon(loaded.progress, levelFile_.filename().string());
    try {
      game::saveProgress(loaded.progress, file);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "progress not saved: %s\n", error.what());
    }
  }

  // --record: the first level's run, from its first tick until it is won, lost, left or the
  // game quits, as a replay that `sightline replay` plays back to the same outcome.
  void startRecording() {
    game::Replay replay;
    replay.file = fs::absolute(*options_.record);
    replay.level = fs::absolute(levelFile_);
    replay.width = options_.width;
    replay.height = options_.height;
    sim::SimulationOptions defaults;
    replay.probeEveryTicks = defaults.probeEveryTicks;
    replay.probeLatency = defaults.probeLatency;
    replay.ticks = 0;
    recording_ = std::move(replay);
  }

  void finishRecording() {
    if (!recording_) return;
    game::Replay& replay = *recording_;
    const game::Outcome outcome = simulation_->outcome();
    replay.outcome.outcome = outcome == game::Outcome::Won    ? game::ReplayOutcome::Won
                             : outcome == game::Outcome::Lost ? game::ReplayOutcome::Lost
                                                              : game::ReplayOutcome::Playing;
    replay.outcome.firstTick = replay.outcome.lastTick = simulation_->tick();
    if (replay.ticks == 0) replay.ticks = 1;  // a replay runs at least one tick
    std::ofstream out(replay.file);
    out << game::replayToJson(replay);
    if (!out) throw std::runtime_error("cannot write the recording " + replay.file.string());
    std::printf("recorded %llu ticks of %s to %s\n",
                static_cast<unsigned long long>(simulation_->tick()), level_->name.c_str(),
                replay.file.c_str());
    std::fflush(stdout);
    recording_.reset();
  }

  void load(const fs::path& file) {
    if (simulation_) finishRecording();  // leaving the recorded level
    auto level = std::make_unique<game::Level>(game::loadLevel(file));
    for (const std::string& warning : level->warnings)
      std::fprintf(stderr, "warning: %s\n", warning.c_str());
    vkDeviceWaitIdle(context_.device());  // the last blit may still read the old image
    simulation_.reset();
    level_ = std::move(level);
    levelFile_ = file;
    sim::SimulationOptions simulationOptions;
    simulationOptions.width = options_.width;
    simulationOptions.height = options_.height;
    simulation_ =
        std::make_unique<sim::Simulation>(context_, compiler_, *level_, simulationOptions);
    accumulator_ = 0.0;
    lastFrameAt_ = glfwGetTime();  // loading time is not play time
    outcomeAt_ = -1.0;
    std::printf("playing %s (%s) at %ux%u\n", level_->name.c_str(), file.c_str(), options_.width,
                options_.height);
    std::fflush(stdout);
    updateTitle(0.0);
  }

  // F5 and "lost": the same file again, re-read so an edited level shows its changes. A level
  // that no longer loads keeps the one being played.
  void restart() {
    try {
      load(levelFile_);
    } catch (const game::LevelError& error) {
      std::fprintf(stderr, "%s\n(keeping the level as it was)\n", error.what());
    }
  }

  void loadNextLevel() {
    auto current = std::find_if(levels_.begin(), levels_.end(), [&](const fs::path& level) {
      return fs::weakly_canonical(level) == fs::weakly_canonical(levelFile_);
    });
    if (current == levels_.end()) {  // not a shipped level: play it again
      restart();
      return;
    }
    ++current;
    if (current == levels_.end()) {
      std::printf("that was the last level; starting again from the first\n");
      current = levels_.begin();
    }
    load(*current);
  }

  void setPaused(bool paused) {
    paused_ = paused;
    // Playing captures the mouse for looking; paused gives it back.
    glfwSetInputMode(window_, GLFW_CURSOR, paused ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_DISABLED);
    if (!paused && glfwRawMouseMotionSupported())
      glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    glfwGetCursorPos(window_, &cursorX_, &cursorY_);  // no jump from where the cursor was
    pendingLook_ = glm::vec2(0.0f);
    updateTitle(0.0);
  }

  void toggleFullscreen() {
    if (glfwGetWindowMonitor(window_)) {
      glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_,
                           windowedHeight_, 0);
      return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (!mode) return;
    glfwGetWindowPos(window_, &windowedX_, &windowedY_);
    glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
  }

  void handlePresses() {
    GLFWgamepadstate pad{};
    const bool hasPad = readGamepad(&pad);
    const bool startPressed = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START] && !startWasDown_;
    startWasDown_ = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START];
    if (startPressed) setPaused(!paused_);
    for (int key : events_.keysPressed) {
      switch (key) {
        case GLFW_KEY_ESCAPE:
          setPaused(!paused_);
          break;
        case GLFW_KEY_F5:
          restart();
          break;
        case GLFW_KEY_F11:
          toggleFullscreen();
          break;
        case GLFW_KEY_V:
          presenter_.setVsync(!presenter_.vsync());
          std::printf("vsync %s\n", presenter_.vsync() ? "on" : "off");
          break;
        case GLFW_KEY_F3:
          authorOverlay_ = !authorOverlay_;
          break;
        default:
          break;
      }
    }
    events_.keysPressed.clear();
    if (!paused_ && events_.wheel != 0.0) {
      wheelDirection_ = events_.wheel > 0.0 ? 1.0f : -1.0f;
      wheelTicksLeft_ = uint32_t(std::ceil(std::abs(events_.wheel))) * kWheelAdjustTicks;
    }
    events_.wheel = 0.0;
  }

  void gatherMouseLook() {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    // Right turns right (negative yaw), up looks up (positive pitch).
    pendingLook_ +=
        glm::vec2(-float(x - cursorX_), -float(y - cursorY_) * (settings_.invertY ? -1.0f : 1.0f)) *
        settings_.mouseSensitivity;
    cursorX_ = x;
    cursorY_ = y;
  }

  // What is held now, from the keyboard and a gamepad; look comes separately.
  game::TickInput heldInput() const {
    auto down = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
    game::TickInput input;
    input.move = {float(down(GLFW_KEY_D)) - float(down(GLFW_KEY_A)),
                  float(down(GLFW_KEY_W)) - float(down(GLFW_KEY_S))};
    input.jump = down(GLFW_KEY_SPACE);
    input.interact = down(GLFW_KEY_E);
    input.adjust = float(down(GLFW_KEY_R)) - float(down(GLFW_KEY_Q));
    GLFWgamepadstate pad{};
    if (readGamepad(&pad)) {
      // GLFW's stick y grows downwards.
      input.move += glm::vec2(deadZone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X]),
                              -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_Y]));
      const float stickDegrees = kStickDegreesPerSecond * float(kTickSeconds);
      input.yawDeltaDegrees = -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_X]) * stickDegrees;
      input.pitchDeltaDegrees = -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_Y]) * stickDegrees;
      input.jump = input.jump || pad.buttons[GLFW_GAMEPAD_BUTTON_A];
      input.interact = input.interact || pad.buttons[GLFW_GAMEPAD_BUTTON_X];
      input.adjust += float(pad.buttons[GLFW_GAMEPAD_BUTTON_RIGHT_BUMPER]) -
                      float(pad.buttons[GLFW_GAMEPAD_BUTTON_LEFT_BUMPER]);
    }
    // Diagonals are no faster than straight lines.
    const float length = glm::length(input.move);
    if (length > 1.0f) input.move /= length;
    input.adjust = std::clamp(input.adjust, -1.0f, 1.0f);
    return input;
  }

  void runTicks(double elapsed) {
    if (simulation_->outcome() != game::Outcome::Playing) return;  // the world waits
    accumulator_ += elapsed;
    int due = int(accumulator_ / kTickSeconds);
    if (due > kMaxTicksPerFrame) {
      due = kMaxTicksPerFrame;
      accumulator_ = due * kTickSeconds;  // drop the rest of the backlog
    }
    if (due == 0) return;
    accumulator_ -= due * kTickSeconds;
    const game::TickInput held = heldInput();
    // The mouse moved over the whole frame: spread it evenly over the frame's ticks.
    const glm::vec2 lookPerTick = pendingLook_ / float(due);
    pendingLook_ = glm::vec2(0.0f);
    for (int i = 0; i < due; ++i) {
      game::TickInput input = held;
      input.yawDeltaDegrees += lookPerTick.x;
      input.pitchDeltaDegrees += lookPerTick.y;
      if (wheelTicksLeft_ > 0) {
        --wheelTicksLeft_;
        input.adjust = std::clamp(input.adjust + wheelDirection_, -1.0f, 1.0f);
      }
      simulation_->step(input);
      if (recording_) game::appendTickInput(*recording_, input);
      ++ticksPlayed_;
      if (options_.quitAfterTicks != 0 && ticksPlayed_ >= options_.quitAfterTicks) return;
      if (simulation_->outcome() != game::Outcome::Playing) return;
    }
  }

  // Won: the next level after a moment; lost: this level again.
  void advanceAfterOutcome(double now) {
    const game::Outcome outcome = simulation_->outcome();
    if (outcome == game::Outcome::Playing) return;
    if (outcomeAt_ < 0.0) {
      outcomeAt_ = now;
      finishRecording();
      if (outcome == game::Outcome::Won) saveWin();
      std::printf("%s %s at tick %llu%s%s\n", outcome == game::Outcome::Won ? "won" : "lost",
                  level_->name.c_str(), static_cast<unsigned long long>(simulation_->tick()),
                  simulation_->rules().reason().empty() ? "" : ": ",
                  simulation_->rules().reason().c_str());
      std::fflush(stdout);
      updateTitle(0.0);
      return;
    }
    if (now - outcomeAt_ < kOutcomeSeconds) return;
    if (outcome == game::Outcome::Won)
      loadNextLevel();
    else
      restart();
  }

  // Resizes, fullscreen and vsync rebuild the swapchain; say what it became.
  void reportSwapchainChange() {
    const VkExtent2D extent = presenter_.extent();
    const VkPresentModeKHR mode = presenter_.presentMode();
    if (extent.width == shownExtent_.width && extent.height == shownExtent_.height &&
        mode == shownMode_)
      return;
    shownExtent_ = extent;
    shownMode_ = mode;
    std::printf("swapchain now %ux%u %s\n", extent.width, extent.height,
                render::Presenter::presentModeName(mode));
    std::fflush(stdout);
  }

  // F3, for level authors: the probe readings the rules use now, and the tick they show.
  std::string rawProbeValues() const {
    const auto& readings = simulation_->latestReadings();
    if (!readings) return "probes: none yet";
    char text[64];
    std::string values = "probes of tick " + std::to_string(readings->tick) + ":";
    for (size_t i = 0; i < readings->focusCoverage.size(); ++i) {
      std::snprintf(text, sizeof text, " focus%zu %.3f", i, double(readings->focusCoverage[i]));
      values += text;
    }
    for (size_t i = 0; i < readings->exposure.size(); ++i) {
      std::snprintf(text, sizeof text, " exposure%zu %.3f", i, double(readings->exposure[i]));
      values += text;
    }
    return values;
  }

  void updateTitle(double fps) {
    std::string title = "Sightline | " + level_->name;
    if (fps > 0.0) title += " | " + std::to_string(int(fps + 0.5)) + " fps";
    const auto& progress = simulation_->rules().progress();
    if (!progress.empty()) {
      title += " | " + progress[0].label + ": " +
               std::to_string(int(progress[0].progress * 100.0f + 0.5f)) + "%";
    }
    switch (simulation_->outcome()) {
      case game::Outcome::Won:
        title += " | Won! Next level in a moment";
        break;
      case game::Outcome::Lost:
        title += " | Lost (" + simulation_->rules().reason() + "); restarting";
        break;
      case game::Outcome::Playing:
        break;
    }
    if (paused_) title += " | Paused: Esc resumes, F5 restarts, close the window to quit";
    if (authorOverlay_) title += " | " + rawProbeValues();
    glfwSetWindowTitle(window_, title.c_str());
  }

  const Options& options_;
  const game::Settings& settings_;
  GLFWwindow* window_;
  const render::Context& context_;
  render::ShaderCompiler& compiler_;
  render::Presenter& presenter_;
  const std::vector<fs::path> levels_;
  VkExtent2D shownExtent_;      // the swapchain as last reported
  bool authorOverlay_ = false;  // F3: raw probe values in the title
  VkPresentModeKHR shownMode_;
  PendingEvents events_;
  // The simulation holds a reference to its level: it goes first.
  std::unique_ptr<game::Level> level_;
  std::unique_ptr<sim::Simulation> simulation_;
  fs::path levelFile_;
  bool paused_ = false;
  double accumulator_ = 0.0;  // real time not yet turned into ticks
  double lastFrameAt_ = 0.0;
  double outcomeAt_ = -1.0;                // when the level was won or lost; < 0 while playing
  uint64_t ticksPlayed_ = 0;               // over all levels, for --quit-after-ticks
  std::optional<game::Replay> recording_;  // --record, until the first level's run ends
  uint64_t framesShown_ = 0;
  glm::vec2 pendingLook_{0.0f};  // yaw, pitch degrees from the mouse since the last tick
  double cursorX_ = 0.0, cursorY_ = 0.0;
  float wheelDirection_ = 0.0f;
  uint32_t wheelTicksLeft_ = 0;
  bool startWasDown_ = false;
  int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = kWindowWidth,
      windowedHeight_ = kWindowHeight;
};

// GLFW's library state, ended on every path out.
struct GlfwLibrary {
  ~GlfwLibrary() { glfwTerminate(); }
};

struct WindowDeleter {
  void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
};

}  // namespace

// Where a new session starts: the first shipped level not yet won (all won: the first).
fs::path firstUnwonLevel(const std::vector<fs::path>& levels) {
  const game::ProgressLoad loaded = game::loadProgress(game::progressFile());
  for (const std::string& message : loaded.messages) std::fprintf(stderr, "%s\n", message.c_str());
  for (const fs::path& level : levels) {
    if (!loaded.progress.completed.contains(level.filename().string())) return level;
  }
  return levels.front();
}

int commandPlay(const Options& options) {
  if (options.resetProgress) {
    game::saveProgress({}, game::progressFile());
    std::printf("progress reset: every level but the first is locked again\n");
  }
  fs::path level;
  if (!options.positional.empty()) {
    level = options.positional[0];
  } else {
    const auto levels = app::shippedLevels(app::findDataRoot());
    if (levels.empty()) throw UsageError("play: no levels found in levels/");
    level = firstUnwonLevel(levels);
  }
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if (!(display && *display) && !(wayland && *wayland)) {
    std::printf("No display (DISPLAY and WAYLAND_DISPLAY are unset): rendering %s headless.\n",
                level.c_str());
    return renderHeadless(options, level);
  }
  auto fallBack = [&](const std::string& why) {
    std::printf("Could not open the game window (%s): rendering %s headless instead.\n",
                why.c_str(), level.c_str());
    return renderHeadless(options, level);
  };

  const game::SettingsLoad settings = game::loadSettings(game::settingsFile());
  for (const std::string& message : settings.messages)
    std::fprintf(stderr, "%s\n", message.c_str());

  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) return fallBack("glfwInit failed: " + glfwErrorText);
  GlfwLibrary library;
  if (!glfwVulkanSupported()) return fallBack("GLFW found no Vulkan loader: " + glfwErrorText);
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws, not OpenGL
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  std::unique_ptr<GLFWwindow, WindowDeleter> window(
      glfwCreateWindow(kWindowWidth, kWindowHeight, "Sightline", nullptr, nullptr));
  if (!window) return fallBack("glfwCreateWindow failed: " + glfwErrorText);

  uint32_t extensionCount = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
  if (!extensions) return fallBack("no Vulkan surface for this window system: " + glfwErrorText);
  render::ContextOptions contextSettings = contextOptions(options);
  contextSettings.extraInstanceExtensions.assign(extensions, extensions + extensionCount);
  contextSettings.presentation = true;

  // The presenter (its surface) must go before the context (its instance).
  std::unique_ptr<render::Context> context;
  std::unique_ptr<render::Presenter> presenter;
  try {
    context = std::make_unique<render::Context>(contextSettings);
    presenter =
        std::make_unique<render::Presenter>(*context, window.get(), settings.settings.vsync);
  } catch (const render::RenderError& error) {
    presenter.reset();
    context.reset();
    window.reset();
    return fallBack(error.what());
  }
  std::printf("window: %ux%u, swapchain %s %s, on %s\n", presenter->extent().width,
              presenter->extent().height, render::Presenter::formatName(presenter->format()),
              render::Presenter::presentModeName(presenter->presentMode()),
              context->deviceInfo().name.c_str());
  std::printf(
      "WASD move, mouse look, Space jump, E interact (held), wheel or Q/R adjust, Esc pause, "
      "F5 restart, F11 fullscreen, V vsync, F3 probe values\n");
  std::fflush(stdout);

  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  int status = 0;
  {
    Game game(options, settings.settings, window.get(), *context, compiler, *presenter);
    status = game.run(level);
  }
  presenter.reset();
  const int validation = validationExitCode(*context);
  return status != 0 ? status : validation;
}

}  // namespace app
