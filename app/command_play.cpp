// play: the game in a GLFW window. Fixed 60 Hz ticks drive the simulation; every displayed
// frame renders a picture at the internal resolution and the presenter scales it to the window.
// Without a display (or when no window can be opened) it renders the level headless instead.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/key_names.hpp"
#include "app/session.hpp"
#include "app/ui_layer.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "game/level_order.hpp"
#include "game/progress.hpp"
#include "game/replay.hpp"
#include "game/rules.hpp"
#include "game/settings.hpp"
#include "game/tick_clock.hpp"
#include "game/user_paths.hpp"
#include "render/context.hpp"
#include "render/image_io.hpp"
#include "render/presenter.hpp"
#include "render/vulkan_error.hpp"
#include "sim/simulation.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

constexpr int kWindowWidth = 1280, kWindowHeight = 720;
constexpr double kTickSeconds = game::Rules::TICK_SECONDS;
constexpr double kOutcomeSeconds = 2.0;  // how long "won"/"lost" shows before moving on
constexpr float kStickDegreesPerSecond = 150.0f;
constexpr float kStickDeadZone = 0.2f;
constexpr uint32_t kWheelAdjustTicks = 6;  // one wheel notch adjusts for 0.1 s
constexpr double kTitleSeconds = 0.5;      // how often the title's fps and progress refresh
constexpr uint32_t kMinRenderSide = 16;    // the smallest internal image side render scale gives

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

// The HUD's bars, in fractions of the picture: rows grow upwards from the bottom one.
constexpr float kBarTop = 0.93f, kBarGap = 0.045f, kBarHeight = 0.025f, kBarWidth = 0.3f;
constexpr float kGoalBarLeft = 0.02f, kExposureBarLeft = 0.68f;
constexpr size_t kHudRows = 4;

class Game {
 public:
  Game(const Options& options, const game::Settings& settings, GLFWwindow* window,
       const render::Context& context, render::ShaderCompiler& compiler,
       render::Presenter& presenter)
      : options_(options),
        settings_(settings),
        savedSettings_(settings),
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
    bindKeys();
    float scaleX = 1.0f, scaleY = 1.0f;
    glfwGetWindowContentScale(window_, &scaleX, &scaleY);
    // After the callbacks above: ImGui's GLFW backend calls them after its own.
    ui_ = std::make_unique<UiLayer>(context_, window_, presenter_, std::max(1.0f, scaleY));
    for (const fs::path& file : levels_) levelNames_.push_back(levelDisplayName(file));
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
      bool quitting = false;
      if (!paused_) {
        gatherMouseLook();
        runTicks(elapsed);
        quitting = options_.quitAfterTicks != 0 && ticksPlayed_ >= options_.quitAfterTicks;
        if (!quitting) advanceAfterOutcome(now);
      }
      if (quitting && options_.capture) presenter_.captureNextPresent();
      simulation_->renderPicture();
      const std::vector<render::HudRect> hud =
          options_.hudOff ? std::vector<render::HudRect>{} : hudRects();
      ui_->beginFrame();
      if (!options_.hudOff) drawScreenText(fps_);
      if (paused_) drawPauseMenu();
      const render::OverlayDraw overlay = ui_->endFrame();
      if (presenter_.present(simulation_->renderer(), hud, overlay)) ++framesShown_;
      reportSwapchainChange();
      if (screenshotRequested_ && !quitting) saveScreenshot();
      if (quitting) {
        if (options_.capture) writeCapture();
        std::printf("quit after %llu ticks, %llu frames shown (%.1f fps)\n",
                    static_cast<unsigned long long>(ticksPlayed_),
                    static_cast<unsigned long long>(framesShown_),
                    double(framesShown_) / std::max(now - started, 1e-3));
        break;
      }
      if (quitRequested_) glfwSetWindowShouldClose(window_, GLFW_TRUE);
      ++framesSinceTitle;
      if (now - titleAt >= kTitleSeconds) {
        fps_ = framesSinceTitle / (now - titleAt);
        updateTitle(fps_);
        titleAt = now;
        framesSinceTitle = 0;
      }
    }
    finishRecording();
    saveSettingsIfChanged();
    // The presenter's last blit reads the renderer's image: finish it before either goes.
    vkDeviceWaitIdle(context_.device());
    simulation_.reset();
    ui_.reset();
    return captureFailed_ ? 1 : 0;
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
      const float y0 = kBarTop - kBarGap * float(row), y1 = y0 + kBarHeight;
      rects.push_back({x0, y0, x0 + kBarWidth, y1, HudColour::Shade});
      if (value > 0.0f)
        rects.push_back({x0, y0, x0 + kBarWidth * std::clamp(value, 0.0f, 1.0f), y1, fill});
    };
    const auto& goals = simulation_->rules().progress();
    for (size_t i = 0; i < goals.size() && i < kHudRows; ++i)
      bar(kGoalBarLeft, int(i), goals[i].progress,
          goals[i].met ? HudColour::BluishGreen : HudColour::SkyBlue);
    if (const auto& readings = simulation_->latestReadings()) {
      for (size_t i = 0; i < readings->exposure.size() && i < kHudRows; ++i)
        bar(kExposureBarLeft, int(i), readings->exposure[i], HudColour::Orange);
    }
    const game::Outcome outcome = simulation_->outcome();
    if (outcome != game::Outcome::Playing)
      rects.push_back(
          {0.0f, 0.02f, 1.0f, 0.06f,
           outcome == game::Outcome::Won ? HudColour::BluishGreen : HudColour::Vermillion});
    return rects;
  }

  // ----- key bindings, render size, settings -----

  void bindKeys() {
    keyCodes_.clear();
    for (const auto& [action, name] : settings_.keyBindings)
      keyCodes_[action] = glfwKeyFromName(name);
  }

  int keyFor(const std::string& action) const {
    const auto found = keyCodes_.find(action);
    return found == keyCodes_.end() ? GLFW_KEY_UNKNOWN : found->second;
  }

  // --size wins; otherwise the window's size (in screen units, so a high-DPI screen does not
  // quadruple the work) times the render scale: 1280x720 at 0.25 gives 320x180.
  void chooseRenderSize() {
    if (options_.sizeGiven) {
      renderWidth_ = options_.width;
      renderHeight_ = options_.height;
      return;
    }
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (width <= 0 || height <= 0) {  // minimised: the default window's shape
      width = kWindowWidth;
      height = kWindowHeight;
    }
    renderWidth_ = std::max(kMinRenderSide, uint32_t(std::lround(width * settings_.renderScale)));
    renderHeight_ = std::max(kMinRenderSide, uint32_t(std::lround(height * settings_.renderScale)));
  }

  void saveSettingsIfChanged() {
    if (settings_ == savedSettings_) return;
    try {
      game::saveSettings(settings_, game::settingsFile());
      savedSettings_ = settings_;
    } catch (const std::exception& error) {
      std::fprintf(stderr, "settings not saved: %s\n", error.what());
    }
  }

  static std::string levelDisplayName(const fs::path& file) {
    try {
      return game::loadLevel(file).name;
    } catch (const std::exception&) {
      return file.stem().string();  // play says what is wrong with it when it is chosen
    }
  }

  // ----- text and menus (Dear ImGui) -----

  static ImU32 colour(uint8_t red, uint8_t green, uint8_t blue) {
    return IM_COL32(red, green, blue, 255);
  }

  // Text with a dark drop shadow, readable over bright and dark parts of the picture.
  static void shadowedText(ImDrawList* list, ImVec2 at, ImU32 textColour, const std::string& text,
                           float size, float wrapWidth = 0.0f) {
    ImFont* font = ImGui::GetFont();
    list->AddText(font, size, ImVec2(at.x + 1.5f, at.y + 1.5f), IM_COL32(0, 0, 0, 220),
                  text.c_str(), nullptr, wrapWidth);
    list->AddText(font, size, at, textColour, text.c_str(), nullptr, wrapWidth);
  }

  static std::string percent(float share) {
    return std::to_string(int(std::clamp(share, 0.0f, 1.0f) * 100.0f + 0.5f)) + "%";
  }

  // Level name and hint (top left), fps (top right), a label beside each HUD bar, the outcome,
  // and with F3 the raw probe readings.
  void drawScreenText(double fps) {
    ImDrawList* list = ImGui::GetForegroundDrawList();
    const render::PictureRect picture = presenter_.pictureRect(renderWidth_, renderHeight_);
    const float size = ImGui::GetFontSize();
    const float margin = std::max(6.0f, picture.width * 0.015f);
    auto at = [&](float x, float y) {
      return ImVec2(picture.x + x * picture.width, picture.y + y * picture.height);
    };
    const ImU32 white = colour(255, 255, 255);
    const ImU32 green = colour(0, 158, 115), vermillion = colour(213, 94, 0);
    ImVec2 top(picture.x + margin, picture.y + picture.height * 0.07f);
    shadowedText(list, top, white, level_->name, size * 1.35f);
    if (!level_->hint.empty()) {
      top.y += size * 1.6f;
      shadowedText(list, top, colour(230, 230, 230), level_->hint, size, picture.width * 0.55f);
    }
    const std::string fpsText = std::to_string(int(fps + 0.5)) + " fps";
    const float fpsWidth = ImGui::CalcTextSize(fpsText.c_str()).x;
    const ImVec2 topRight = at(1.0f, 0.07f);
    shadowedText(list, ImVec2(topRight.x - margin - fpsWidth, topRight.y), white, fpsText, size);

    // Beside the bars hudRects() draws: goals on the left, exposure meters on the right.
    const auto& goals = simulation_->rules().progress();
    for (size_t i = 0; i < goals.size() && i < kHudRows; ++i) {
      const float y = kBarTop - kBarGap * float(i) + kBarHeight / 2;
      const ImVec2 position = at(kGoalBarLeft + kBarWidth + 0.01f, y);
      shadowedText(list, ImVec2(position.x, position.y - size / 2), goals[i].met ? green : white,
                   goals[i].label + "  " + percent(goals[i].progress), size);
    }
    if (const auto& readings = simulation_->latestReadings()) {
      for (size_t i = 0; i < readings->exposure.size() && i < kHudRows; ++i) {
        const float y = kBarTop - kBarGap * float(i) + kBarHeight / 2;
        const std::string text =
            "sensor " + std::to_string(i + 1) + " lit  " + percent(readings->exposure[i]);
        const ImVec2 position = at(kExposureBarLeft - 0.01f, y);
        shadowedText(
            list, ImVec2(position.x - ImGui::CalcTextSize(text.c_str()).x, position.y - size / 2),
            white, text, size);
      }
    }
    const game::Outcome outcome = simulation_->outcome();
    if (outcome != game::Outcome::Playing) {
      const std::string text = outcome == game::Outcome::Won
                                   ? "Level complete! The next level follows in a moment."
                                   : "Lost: " + simulation_->rules().reason() + ". Restarting.";
      const float big = size * 1.5f;
      const float width = ImGui::CalcTextSize(text.c_str()).x * 1.5f;
      shadowedText(list, ImVec2(picture.x + (picture.width - width) / 2, at(0, 0.3f).y),
                   outcome == game::Outcome::Won ? green : vermillion, text, big);
    }
    if (authorOverlay_) drawAuthorOverlay();
  }

  // F3: what the rules see, for level authors tuning goals.
  void drawAuthorOverlay() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y * 0.15f), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.7f);
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("Probe values (F3)", nullptr, flags)) {
      ImGui::Text("tick %llu, %ux%u", static_cast<unsigned long long>(simulation_->tick()),
                  renderWidth_, renderHeight_);
      if (const auto& readings = simulation_->latestReadings()) {
        ImGui::Text("readings of tick %llu", static_cast<unsigned long long>(readings->tick));
        for (size_t i = 0; i < readings->focusCoverage.size(); ++i)
          ImGui::Text("focus %zu coverage  %.4f", i, double(readings->focusCoverage[i]));
        for (size_t i = 0; i < readings->exposure.size(); ++i)
          ImGui::Text("exposure %zu  %.4f", i, double(readings->exposure[i]));
      } else {
        ImGui::TextUnformatted("no readings yet");
      }
      for (const game::GoalProgress& goal : simulation_->rules().progress())
        ImGui::Text("%s  %.4f%s", goal.label.c_str(), double(goal.progress),
                    goal.met ? " (met)" : "");
    }
    ImGui::End();
  }

  // Esc: resume, restart, quit; the level list; the settings; a progress reset.
  void drawPauseMenu() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(display.x * 0.4f, 0.0f),
                                        ImVec2(display.x * 0.9f, display.y * 0.9f));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings;
    if (!ImGui::Begin("Paused", nullptr, flags)) {
      ImGui::End();
      return;
    }
    ImGui::Text("%s", level_->name.c_str());
    if (ImGui::Button("Resume (Esc)")) resumeRequested_ = true;
    ImGui::SameLine();
    if (ImGui::Button("Restart level")) pendingLevel_ = levelFile_;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) quitRequested_ = true;

    if (ImGui::CollapsingHeader("Levels", ImGuiTreeNodeFlags_DefaultOpen)) drawLevelList();
    if (ImGui::CollapsingHeader("Settings")) drawSettings();
    ImGui::End();
  }

  void drawLevelList() {
    std::vector<std::string> order;
    for (const fs::path& file : levels_) order.push_back(file.filename().string());
    for (size_t i = 0; i < levels_.size(); ++i) {
      const bool won = menuProgress_.completed.contains(order[i]);
      const bool open = game::unlocked(menuProgress_, order, order[i]);
      const bool current = fs::weakly_canonical(levels_[i]) == fs::weakly_canonical(levelFile_);
      const std::string label = std::to_string(i + 1) + ". " + levelNames_[i] +
                                (won    ? "   [won]"
                                 : open ? ""
                                        : "   (locked)");
      ImGui::BeginDisabled(!open);
      if (ImGui::Selectable(label.c_str(), current)) pendingLevel_ = levels_[i];
      ImGui::EndDisabled();
    }
    if (!confirmReset_) {
      if (ImGui::Button("Reset progress...")) confirmReset_ = true;
    } else {
      ImGui::TextUnformatted("Forget every win and lock all but the first level?");
      if (ImGui::Button("Yes, reset")) {
        menuProgress_ = {};
        try {
          game::saveProgress(menuProgress_, game::progressFile());
          std::printf("progress reset\n");
        } catch (const std::exception& error) {
          std::fprintf(stderr, "progress not reset: %s\n", error.what());
        }
        confirmReset_ = false;
      }
      ImGui::SameLine();
      if (ImGui::Button("Keep it")) confirmReset_ = false;
    }
  }

  void drawSettings() {
    ImGui::SliderFloat("Mouse sensitivity", &settings_.mouseSensitivity, 0.01f, 1.0f,
                       "%.2f degrees per pixel");
    ImGui::Checkbox("Invert mouse Y", &settings_.invertY);
    bool levelFov = !settings_.fieldOfViewDegrees;
    if (ImGui::Checkbox("Each level's own field of view", &levelFov))
      settings_.fieldOfViewDegrees =
          levelFov ? std::nullopt : std::optional<float>(level_->camera.verticalFovDegrees);
    if (settings_.fieldOfViewDegrees)
      ImGui::SliderFloat("Field of view", &*settings_.fieldOfViewDegrees,
                         game::kMinFieldOfViewDegrees, game::kMaxFieldOfViewDegrees,
                         "%.0f degrees (vertical)");
    ImGui::SliderFloat("Render scale", &settings_.renderScale, 0.1f, 1.0f, "%.2f");
    settings_.renderScale = std::clamp(settings_.renderScale, 0.1f, 1.0f);
    if (ImGui::Checkbox("Vsync (V)", &settings_.vsync)) presenter_.setVsync(settings_.vsync);
    if (settings_.fieldOfViewDegrees != activeFov_ || settings_.renderScale != activeScale_) {
      ImGui::TextUnformatted("Field of view and render scale apply when a level starts.");
      if (ImGui::Button("Apply now (restarts the level)")) pendingLevel_ = levelFile_;
    }
    ImGui::Text("Picture: %ux%u, scaled to the window", renderWidth_, renderHeight_);

    ImGui::Separator();
    ImGui::TextUnformatted("Keys");
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
      for (const auto& [action, key] : settings_.keyBindings) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(action.c_str());
        ImGui::TableNextColumn();
        const bool waiting = rebinding_ && *rebinding_ == action;
        const std::string label =
            (waiting ? std::string("press a key (Esc keeps it)") : key) + "##" + action;
        if (ImGui::Button(label.c_str())) rebinding_ = action;
      }
      ImGui::EndTable();
    }
    if (ImGui::Button("Default keys")) {
      settings_.keyBindings = game::Settings::defaultKeyBindings();
      bindKeys();
    }
  }

  // --capture: the window's image of the last frame, as shown, as a PNG.
  void writeCapture() {
    const std::optional<render::Rgba8Image> image = presenter_.takeCapture();
    if (!image) {
      std::fprintf(stderr, "--capture: no frame was shown to capture (minimised window?)\n");
      captureFailed_ = true;
      return;
    }
    render::writePng(*options_.capture, *image);
    std::printf("captured the window (%ux%u) at tick %llu to %s\n", image->width, image->height,
                static_cast<unsigned long long>(simulation_->tick()), options_.capture->c_str());
  }

  // F12: the window as shown, in dataDirectory()/screenshots.
  void saveScreenshot() {
    const std::optional<render::Rgba8Image> image = presenter_.takeCapture();
    if (!image) return;  // nothing shown yet (minimised): the capture waits for the next frame
    screenshotRequested_ = false;
    const fs::path directory = game::dataDirectory() / "screenshots";
    std::error_code error;
    fs::create_directories(directory, error);
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "sightline-%Y%m%d-%H%M%S.png", std::localtime(&now));
    try {
      render::writePng(directory / name, *image);
      std::printf("screenshot saved to %s\n", (directory / name).c_str());
    } catch (const std::exception& failure) {
      std::fprintf(stderr, "screenshot not saved: %s\n", failure.what());
    }
    std::fflush(stdout);
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
    replay.width = renderWidth_;
    replay.height = renderHeight_;
    replay.verticalFovDegrees = settings_.fieldOfViewDegrees;
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
    chooseRenderSize();
    activeFov_ = settings_.fieldOfViewDegrees;
    activeScale_ = settings_.renderScale;
    sim::SimulationOptions simulationOptions;
    simulationOptions.width = renderWidth_;
    simulationOptions.height = renderHeight_;
    simulationOptions.verticalFovDegrees = settings_.fieldOfViewDegrees;
    simulation_ =
        std::make_unique<sim::Simulation>(context_, compiler_, *level_, simulationOptions);
    tickClock_.reset();
    lastFrameAt_ = glfwGetTime();  // loading time is not play time
    outcomeAt_ = -1.0;
    std::printf("playing %s (%s) at %ux%u\n", level_->name.c_str(), file.c_str(), renderWidth_,
                renderHeight_);
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
    rebinding_.reset();
    confirmReset_ = false;
    if (paused) {
      const game::ProgressLoad loaded = game::loadProgress(game::progressFile());
      for (const std::string& message : loaded.messages)
        std::fprintf(stderr, "%s\n", message.c_str());
      menuProgress_ = loaded.progress;
    } else {
      saveSettingsIfChanged();
    }
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
    // What the menu chose last frame, now that no frame is being built.
    if (pendingLevel_) {
      const fs::path file = *pendingLevel_;
      pendingLevel_.reset();
      try {
        load(file);
        setPaused(false);
      } catch (const game::LevelError& error) {
        std::fprintf(stderr, "%s\n(keeping the level as it was)\n", error.what());
      }
    }
    if (resumeRequested_) {
      resumeRequested_ = false;
      setPaused(false);
    }
    GLFWgamepadstate pad{};
    const bool hasPad = readGamepad(&pad);
    const bool startPressed = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START] && !startWasDown_;
    startWasDown_ = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START];
    if (startPressed) setPaused(!paused_);
    for (int key : events_.keysPressed) {
      if (rebinding_) {  // the menu waits for the key to bind; Escape cancels
        if (key != GLFW_KEY_ESCAPE && !keyNameFromGlfw(key).empty()) {
          settings_.keyBindings[*rebinding_] = keyNameFromGlfw(key);
          bindKeys();
        }
        rebinding_.reset();
        continue;
      }
      if (key == keyFor("pause")) {
        setPaused(!paused_);
        continue;
      }
      if (key == keyFor("restart")) {
        restart();
        continue;
      }
      if (key == keyFor("fullscreen")) {
        toggleFullscreen();
        continue;
      }
      switch (key) {
        case GLFW_KEY_V:
          presenter_.setVsync(!presenter_.vsync());
          settings_.vsync = presenter_.vsync();
          std::printf("vsync %s\n", presenter_.vsync() ? "on" : "off");
          break;
        case GLFW_KEY_F3:
          authorOverlay_ = !authorOverlay_;
          break;
        case GLFW_KEY_F12:
          screenshotRequested_ = true;
          presenter_.captureNextPresent();
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
    auto down = [&](const char* action) {
      const int key = keyFor(action);
      return key != GLFW_KEY_UNKNOWN && glfwGetKey(window_, key) == GLFW_PRESS;
    };
    game::TickInput input;
    input.move = {float(down("right")) - float(down("left")),
                  float(down("forward")) - float(down("back"))};
    input.jump = down("jump");
    input.interact = down("interact");
    input.adjust = float(down("adjust_up")) - float(down("adjust_down"));
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
    // At most TickClock::MAX_TICKS_PER_FRAME; the backlog of a longer frame is dropped.
    const int due = tickClock_.advance(elapsed);
    if (due == 0) return;
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
  game::Settings settings_;       // as the menu changes them
  game::Settings savedSettings_;  // as settings.json holds them
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
  game::TickClock tickClock_;  // real time into ticks
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
  std::map<std::string, int> keyCodes_;   // action -> GLFW key, from the settings
  std::unique_ptr<UiLayer> ui_;           // text and menus
  std::vector<std::string> levelNames_;   // of levels_, for the menu
  std::optional<std::string> rebinding_;  // the action waiting for its new key
  std::optional<fs::path> pendingLevel_;  // chosen in the menu; loaded before the next frame
  bool resumeRequested_ = false;
  bool quitRequested_ = false;
  bool confirmReset_ = false;
  bool captureFailed_ = false;
  bool screenshotRequested_ = false;
  game::Progress menuProgress_;  // read when the menu opens
  double fps_ = 0.0;
  uint32_t renderWidth_ = 320, renderHeight_ = 180;  // the simulation's picture
  std::optional<float> activeFov_;                   // what the current level started with
  float activeScale_ = 0.0f;
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
  if (options.capture && options.quitAfterTicks == 0)
    throw UsageError("play: --capture needs --quit-after-ticks N (the tick whose frame it saves)");
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
  const auto [windowWidth, windowHeight] =
      options.windowSize.value_or(std::pair<uint32_t, uint32_t>(kWindowWidth, kWindowHeight));
  std::unique_ptr<GLFWwindow, WindowDeleter> window(
      glfwCreateWindow(int(windowWidth), int(windowHeight), "Sightline", nullptr, nullptr));
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
        std::make_unique<render::Presenter>(*context, window.get(), settings.settings.vsync, true);
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
      "WASD move, mouse look, Space jump, E interact (held), wheel or Q/R adjust, Esc pause "
      "(menu: levels, settings, keys), F5 restart, F11 fullscreen, V vsync, F3 probe values, "
      "F12 screenshot\n");
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
