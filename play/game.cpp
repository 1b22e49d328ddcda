#include "play/game.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>

#include "game/author_view.hpp"
#include "game/level_loader.hpp"
#include "play/frame_parts.hpp"
#include "play/hud.hpp"
#include "play/recording.hpp"
#include "render/context.hpp"
#include "render/frame_time_percentiles.hpp"
#include "render/presenter.hpp"
#include "render/vulkan_error.hpp"

namespace play {
namespace fs = std::filesystem;

namespace {
constexpr double kTitleSeconds = 0.5;  // how often the title's fps and progress refresh
}  // namespace

Game::Game(const PlayOptions& options, const game::Settings& settings, std::vector<fs::path> levels,
           std::vector<std::string> chapters, GLFWwindow* window, const render::Context& context,
           render::ShaderCompiler& compiler, render::Presenter& presenter)
    : options_(options),
      settings_(settings),
      savedSettings_(settings),
      window_(window),
      context_(context),
      compiler_(compiler),
      presenter_(presenter),
      levels_(std::move(levels)),
      shownSwapchain_{presenter.extent(), presenter.presentMode()},
      flying_(options.author) {
  installEventCallbacks(window_, events_);
  keyCodes_ = keyCodesFor(settings_);
  float scaleX = 1.0f, scaleY = 1.0f;
  glfwGetWindowContentScale(window_, &scaleX, &scaleY);
  // After the callbacks above: ImGui's GLFW backend calls them after its own.
  ui_ = std::make_unique<UiLayer>(context_, window_, presenter_, std::max(1.0f, scaleY));
  menu_.levelNames = levelDisplayNames(levels_, options_.levelLoading);
  menu_.levelChapters = std::move(chapters);
}

int Game::run(const fs::path& firstLevel) {
  load(firstLevel);
  if (options_.record)
    played_.recording = startRecording(*options_.record, played_.file, played_.renderWidth,
                                       played_.renderHeight, settings_.fieldOfViewDegrees);
  setPaused(false);
  const double started = glfwGetTime();
  double titleAt = started;
  uint32_t framesSinceTitle = 0;
  std::vector<double> frameMilliseconds;  // every frame's, for the percentiles at the end
  FramePartTimes parts;
  while (!glfwWindowShouldClose(window_)) {
    parts.start(FramePart::Input);
    if (paused_)
      glfwWaitEventsTimeout(0.05);  // nothing moves: no need to spin
    else
      glfwPollEvents();
    handlePresses();
    const double now = glfwGetTime();
    const double elapsed = now - played_.lastFrameAt;
    played_.lastFrameAt = now;
    frameMilliseconds.push_back(elapsed * 1000.0);
    bool quitting = false;
    if (!paused_) {
      // The frame's work: vsync's wait for the display is not something fewer pixels shorten.
      adjustPictureSize(std::max(elapsed - presenter_.lastDisplayWaitMilliseconds() / 1000.0, 0.0));
      gatherMouseLook(window_, look_, settings_);
      parts.start(FramePart::Ticks);
      runTicks(elapsed);
      quitting = options_.quitAfterTicks != 0 && ticksPlayed_ >= options_.quitAfterTicks;
      if (!quitting && advanceAfterOutcome(played_, now, levelSetup())) {
        if (played_.campaignFinished) resetMenu(menu_, true);  // the end screen's best times
        levelStarted();
      }
      // A scripted run that reaches the end screen ends there (no tick passes on it).
      quitting = quitting || (options_.quitAfterTicks != 0 && played_.campaignFinished);
      reloadIfEdited(now);
    }
    if (quitting && options_.capture) presenter_.captureNextPresent();
    parts.start(FramePart::Picture);
    played_.simulation->renderPicture(false);
    parts.recordPicture(played_.simulation->lastPictureStats());
    parts.start(FramePart::Interface);
    const std::vector<render::HudRect> hud =
        options_.hudOff ? std::vector<render::HudRect>{} : hudRects(*played_.simulation);
    ui_->beginFrame();
    if (!options_.hudOff) {
      const auto interact = settings_.keyBindings.find("interact");
      drawScreenText(played_, presenter_, fps_, authorOverlay_,
                     interact != settings_.keyBindings.end() ? interact->second : "E");
    }
    if (paused_)
      drawPauseMenu(menu_, played_, levels_, settings_, keyCodes_, presenter_);
    else if (played_.campaignFinished)
      drawEndScreen(menu_, levels_);
    const render::OverlayDraw overlay = ui_->endFrame();
    parts.start(FramePart::Present);
    if (presenter_.present(played_.simulation->renderer(), hud, overlay)) ++framesShown_;
    parts.endFrame();
    reportSwapchainChange(presenter_, shownSwapchain_);
    if (screenshotRequested_ && !quitting && saveScreenshot(presenter_))
      screenshotRequested_ = false;
    if (quitting) {
      if (options_.capture &&
          !writeCapture(presenter_, *options_.capture,
                        "at tick " + std::to_string(played_.simulation->tick())))
        captureFailed_ = true;
      std::printf("quit after %llu ticks, %llu frames shown (%.1f fps); frame times %s\n",
                  static_cast<unsigned long long>(ticksPlayed_),
                  static_cast<unsigned long long>(framesShown_),
                  double(framesShown_) / std::max(now - started, 1e-3),
                  render::frameTimePercentiles(frameMilliseconds).text().c_str());
      std::printf("frame parts: %s\n", parts.partsText(played_.simulation->probeFrames()).c_str());
      if (presenter_.scalesOnHost()) {
        std::printf("window picture: scaled by the CPU in %llu of %llu frames shown\n",
                    static_cast<unsigned long long>(presenter_.hostScaledPresents()),
                    static_cast<unsigned long long>(framesShown_));
      }
      if (const std::string passes = parts.pictureText(); !passes.empty())
        std::printf("%s\n", passes.c_str());
      reportPictureScales();
      break;
    }
    if (menu_.quitRequested) glfwSetWindowShouldClose(window_, GLFW_TRUE);
    ++framesSinceTitle;
    if (now - titleAt >= kTitleSeconds) {
      fps_ = framesSinceTitle / (now - titleAt);
      updateTitle(fps_);
      titleAt = now;
      framesSinceTitle = 0;
    }
  }
  finishRecording(played_.recording, *played_.simulation, played_.level->name);
  saveSettingsIfChanged(settings_, savedSettings_);
  // The presenter's last draw reads the renderer's image: finish it before either goes.
  vkDeviceWaitIdle(context_.device());
  played_.simulation.reset();
  ui_.reset();
  return captureFailed_ ? 1 : 0;
}

LevelSetup Game::levelSetup() {
  return {context_,
          compiler_,
          window_,
          options_,
          settings_,
          levels_,
          [this](const game::Level& level, float progress) { showLoading(level, progress); }};
}

void Game::showLoading(const game::Level& level, float progress) {
  // Answers the window manager's pings; what was pressed waits for the level (the mouse's
  // motion is dropped when it starts: levelStarted).
  glfwPollEvents();
  ui_->beginFrame();
  drawLoadingScreen(level.name, progress, context_.isCpuDevice());
  const render::OverlayDraw overlay = ui_->endFrame();
  const bool capturing = options_.captureLoading.has_value();
  bool shown = false;
  try {
    if (capturing) presenter_.captureNextPresent();
    shown = presenter_.presentWithoutPicture(overlay);
  } catch (const render::RenderError& error) {
    // The load goes on without its screen; what is wrong with the window shows again in play.
    std::fprintf(stderr, "loading screen not shown: %s\n", error.what());
    if (capturing) captureFailed_ = true;
    return;
  }
  if (capturing && shown) {  // each step's over the last: the file keeps the furthest
    const fs::path file = *options_.captureLoading / (level.file.stem().string() + ".png");
    if (!writeCapture(presenter_, file,
                      "while " + level.name + " loaded (" +
                          std::to_string(int(std::lround(progress * 100.0f))) + " %)"))
      captureFailed_ = true;
  }
}

void Game::load(const fs::path& file) {
  startLevel(played_, file, levelSetup());
  levelStarted();
}

void Game::levelStarted() {
  dynamicScale_.reset();  // the next frame starts one for the new renderer, at the full size
  played_.simulation->setAuthoring(flying_);
  if (flying_) played_.timed = false;
  if (!watcher_ || watchedFile_ != played_.file) {
    watcher_ = std::make_unique<game::LevelWatcher>(played_.file, options_.levelLoading);
    watcher_->poll();  // the files the level is made of, as they are now
    watchedFile_ = played_.file;
  }
  watchedAt_ = played_.lastFrameAt;
  if (!paused_) setMouseCaptured(window_, look_, !played_.campaignFinished);
  updateTitle(0.0);
}

void Game::restartInPlace(const char* why) {
  const game::World& world = played_.simulation->world();
  const glm::vec3 feet = world.feetPosition();
  const float yaw = world.yawDegrees(), pitch = world.pitchDegrees();
  if (!restartLevel(played_, levelSetup())) return;  // it said why
  levelStarted();
  played_.simulation->placePlayer(feet, yaw, pitch);
  played_.timed = false;  // the run did not start at the spawn point
  std::printf("%s: the rules start again, the player stays\n", why);
  std::fflush(stdout);
}

void Game::reloadIfEdited(double now) {
  constexpr double kWatchSeconds = 0.5;
  if (!watcher_ || now - watchedAt_ < kWatchSeconds) return;
  watchedAt_ = now;
  switch (watcher_->poll()) {
    case game::LevelWatcher::Event::Unchanged:
      return;
    case game::LevelWatcher::Event::Failed:
      std::fprintf(stderr, "%s\n(keeping the level as it was)\n", watcher_->error().c_str());
      return;
    case game::LevelWatcher::Event::Reloaded:
      break;
  }
  restartInPlace(("reloaded " + played_.file.string()).c_str());
}

void Game::setFlying(bool flying) {
  flying_ = flying;
  played_.simulation->setAuthoring(flying);
  if (flying) played_.timed = false;
  if (flying && played_.recording) {
    played_.recording.reset();
    std::printf("recording stopped: the fly camera goes where a replay cannot\n");
  }
  std::printf("fly camera %s\n", flying ? "on: no gravity, collision, winning or losing" : "off");
  std::fflush(stdout);
  // What the rules decided while it flew is not played out: they start again where it is.
  if (!flying && played_.simulation->rulesOutcome() != game::Outcome::Playing)
    restartInPlace("fly camera off");
  updateTitle(0.0);
}

void Game::copyView() {
  const game::World& world = played_.simulation->world();
  std::string text = game::cameraJson(world);
  if (const std::optional<game::CrosshairTarget> target = game::crosshairTarget(world))
    text += "\n" + game::positionJson(target->point);
  glfwSetClipboardString(window_, text.c_str());
  std::printf("copied to the clipboard:\n%s\n", text.c_str());
  std::fflush(stdout);
}

void Game::setPaused(bool paused) {
  paused_ = paused;
  resetMenu(menu_, paused);
  if (!paused) saveSettingsIfChanged(settings_, savedSettings_);
  setMouseCaptured(window_, look_,
                   !paused && !played_.campaignFinished);  // the end screen has buttons
  updateTitle(0.0);
}

void Game::handlePresses() {
  // What the menu chose last frame, now that no frame is being built.
  if (menu_.pendingLevel) {
    const fs::path file = *menu_.pendingLevel;
    menu_.pendingLevel.reset();
    try {
      load(file);
      setPaused(false);
    } catch (const game::LevelError& error) {
      std::fprintf(stderr, "%s\n(keeping the level as it was)\n", error.what());
    }
  }
  if (menu_.resumeRequested) {
    menu_.resumeRequested = false;
    setPaused(false);
  }
  if (gamepadStartPressed(startWasDown_)) setPaused(!paused_);
  // Taken first: a restart below loads the level, which polls the window's events while it
  // waits (what is pressed meanwhile counts next frame).
  std::vector<int> keysPressed;
  keysPressed.swap(events_.keysPressed);
  const double wheel = std::exchange(events_.wheel, 0.0);
  for (int key : keysPressed) {
    if (menu_.rebinding) {  // the menu waits for the key to bind; Escape cancels
      rebindAction(settings_, keyCodes_, *menu_.rebinding, key);
      menu_.rebinding.reset();
      continue;
    }
    switch (keyActionFor(keyCodes_, key)) {
      case KeyAction::Pause:
        setPaused(!paused_);
        break;
      case KeyAction::Restart:
        if (restartLevel(played_, levelSetup())) levelStarted();
        break;
      case KeyAction::Fullscreen:
        toggleFullscreen(window_, windowed_);
        break;
      case KeyAction::Vsync:
        toggleVsync(presenter_, settings_);
        break;
      case KeyAction::AuthorOverlay:
        authorOverlay_ = !authorOverlay_;
        break;
      case KeyAction::FlyCamera:
        setFlying(!flying_);
        break;
      case KeyAction::CopyView:
        copyView();
        break;
      case KeyAction::Screenshot:
        screenshotRequested_ = true;
        presenter_.captureNextPresent();
        break;
      case KeyAction::None:
        break;
    }
  }
  if (!paused_) startWheelAdjust(wheel_, wheel);
}

void Game::runTicks(double elapsed) {
  sim::Simulation& simulation = *played_.simulation;
  if (simulation.outcome() != game::Outcome::Playing) return;  // the world waits
  // At most TickClock::MAX_TICKS_PER_FRAME; the backlog of a longer frame is dropped.
  const int due = played_.tickClock.advance(elapsed);
  if (due == 0) return;
  const game::TickInput held = heldInput(window_, keyCodes_);
  // The mouse moved over the whole frame: spread it evenly over the frame's ticks.
  const glm::vec2 lookPerTick = look_.pending / float(due);
  look_.pending = glm::vec2(0.0f);
  for (int i = 0; i < due; ++i) {
    game::TickInput input = held;
    input.yawDeltaDegrees += lookPerTick.x;
    input.pitchDeltaDegrees += lookPerTick.y;
    applyWheelAdjust(wheel_, input);
    simulation.step(input);
    if (played_.recording) game::appendTickInput(*played_.recording, input);
    ++ticksPlayed_;
    if (options_.quitAfterTicks != 0 && ticksPlayed_ >= options_.quitAfterTicks) return;
    if (simulation.outcome() != game::Outcome::Playing) return;
  }
}

void Game::adjustPictureSize(double frameSeconds) {
  render::Renderer& renderer = played_.simulation->renderer();
  const bool wanted = !options_.fixedScale && !options_.pictureSize && settings_.dynamicRenderScale;
  if (wanted != dynamicScale_.has_value()) {
    if (wanted)
      dynamicScale_.emplace(renderer.width(), renderer.height());
    else
      dynamicScale_.reset();
    renderer.setPictureSize(renderer.width(), renderer.height());
    return;
  }
  if (!dynamicScale_) return;
  if (dynamicScale_->frameFinished(frameSeconds * 1000.0)) {
    const PictureSize size = dynamicScale_->size();
    renderer.setPictureSize(size.width, size.height);
  }
  if (options_.quitAfterTicks != 0) pictureScales_.push_back(dynamicScale_->scale());
}

void Game::reportPictureScales() const {
  if (pictureScales_.empty()) {
    std::printf("picture scale: 1 (fixed)\n");
    return;
  }
  std::vector<float> sorted = pictureScales_;
  std::sort(sorted.begin(), sorted.end());
  const size_t atOrAboveOne =
      size_t(sorted.end() - std::lower_bound(sorted.begin(), sorted.end(), 1.0f));
  std::printf(
      "picture scale: p50 %.3f  min %.3f  max %.3f, full size in %.0f %% of %zu frames "
      "(dynamic, aiming at %.0f fps)\n",
      double(sorted[sorted.size() / 2]), double(sorted.front()), double(sorted.back()),
      100.0 * double(atOrAboveOne) / double(sorted.size()), sorted.size(),
      1000.0 / DynamicScale::kTargetMilliseconds);
}

void Game::updateTitle(double fps) {
  showTitle(window_, *played_.level, *played_.simulation, fps, paused_, authorOverlay_);
}

}  // namespace play
