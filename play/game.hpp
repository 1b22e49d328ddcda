#pragma once
// play: the game in a GLFW window. Fixed 60 Hz ticks drive the simulation; every displayed
// frame renders a picture at the internal resolution and the presenter scales it to the window.
// The loop composes the parts: input, level flow, HUD, menu, recording and the window.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "game/level_watcher.hpp"
#include "game/settings.hpp"
#include "play/dynamic_scale.hpp"
#include "play/input.hpp"
#include "play/level_flow.hpp"
#include "play/menu.hpp"
#include "play/play_options.hpp"
#include "play/ui_layer.hpp"
#include "play/window.hpp"

struct GLFWwindow;

namespace play {

class Game {
 public:
  // `levels`: the shipped levels in play order (the menu's list; a win moves on to the next);
  // `chapters` parallel to it.
  Game(const PlayOptions& options, const game::Settings& settings,
       std::vector<std::filesystem::path> levels, std::vector<std::string> chapters,
       GLFWwindow* window, const render::Context& context, render::ShaderCompiler& compiler,
       render::Presenter& presenter);

  // Plays until the window closes or --quit-after-ticks; returns the exit status.
  int run(const std::filesystem::path& firstLevel);

 private:
  LevelSetup levelSetup();
  // One frame that says the level is loading and how far it got (LevelSetup::showLoading), and
  // the window's events, so that the desktop does not take the game for hung; --capture-loading
  // saves it.
  void showLoading(const game::Level& level, float progress);
  void load(const std::filesystem::path& file);
  void setPaused(bool paused);
  void handlePresses();
  void runTicks(double elapsed);
  // The dynamic render scale after a played frame of `frameSeconds` of work: it follows the
  // settings (on unless --fixed-scale, --size or the menu says otherwise) and sets the next picture
  // size.
  void adjustPictureSize(double frameSeconds);
  // The dynamic render scale over the frames played, for --quit-after-ticks's report.
  void reportPictureScales() const;
  void updateTitle(double fps);
  void setFlying(bool flying);
  // After any level start (load, F5, a loss's restart, a win's next level): the fly camera, the
  // live-reload watcher and the mouse follow the new level.
  void levelStarted();
  // Starts the played level again from its file, keeping the player where they are.
  void restartInPlace(const char* why);
  void copyView();
  // Saving the level (or a file it uses) reloads it in place: the player stays where they are
  // and the rules start again. A save that does not load keeps the level as it was.
  void reloadIfEdited(double now);

  const PlayOptions& options_;
  game::Settings settings_;       // as the menu changes them
  game::Settings savedSettings_;  // as settings.json holds them
  GLFWwindow* window_;
  const render::Context& context_;
  render::ShaderCompiler& compiler_;
  render::Presenter& presenter_;
  const std::vector<std::filesystem::path> levels_;
  ShownSwapchain shownSwapchain_;
  WindowedPlacement windowed_;
  PendingEvents events_;  // before ui_: ImGui's GLFW backend passes events on to its callbacks
  KeyCodes keyCodes_;
  MouseLook look_;
  WheelAdjust wheel_;
  bool startWasDown_ = false;
  PlayedLevel played_;
  bool paused_ = false;
  bool authorOverlay_ = false;                   // F3: raw probe values on screen and in the title
  bool flying_ = false;                          // F4 or --author: the fly camera
  std::unique_ptr<game::LevelWatcher> watcher_;  // the played level's files, for live reload
  std::filesystem::path watchedFile_;            // the level the watcher watches
  double watchedAt_ = 0.0;                       // when the watcher last looked
  uint64_t ticksPlayed_ = 0;                     // over all levels, for --quit-after-ticks
  uint64_t framesShown_ = 0;
  std::optional<DynamicScale> dynamicScale_;  // none: the picture is the whole render size
  std::vector<float> pictureScales_;  // each played frame's, for --quit-after-ticks's report
  double fps_ = 0.0;
  bool screenshotRequested_ = false;
  bool captureFailed_ = false;
  std::unique_ptr<UiLayer> ui_;  // text and menus; goes before the level (it waits for the GPU)
  Menu menu_;
};

}  // namespace play
