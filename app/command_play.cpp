// play: opens the game window and plays in it (play/). Without a display (or when no window can
// be opened) it renders the level headless instead.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include <GLFW/glfw3.h>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/session.hpp"
#include "game/progress.hpp"
#include "game/settings.hpp"
#include "game/user_paths.hpp"
#include "play/game.hpp"
#include "play/level_flow.hpp"
#include "play/window.hpp"
#include "render/context.hpp"
#include "render/presenter.hpp"
#include "render/vulkan_error.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

std::string glfwErrorText = "unknown error";

void onGlfwError(int, const char* description) {
  glfwErrorText = description ? description : "unknown error";
}

int renderHeadless(const Options& options, const fs::path& level) {
  Options headless = options;
  headless.positional = {level.string()};
  return commandRender(headless);
}

play::PlayOptions playOptions(const Options& options) {
  play::PlayOptions playing;
  if (options.sizeGiven) playing.pictureSize = std::pair(options.width, options.height);
  playing.quitAfterTicks = options.quitAfterTicks;
  playing.hudOff = options.hudOff;
  playing.upscale = options.upscale;
  playing.fixedScale = options.fixedScale;
  playing.record = options.record;
  playing.capture = options.capture;
  playing.captureLoading = options.captureLoading;
  playing.author = options.author;
  playing.levelLoading = levelLoadOptions();
  return playing;
}

// GLFW's library state, ended on every path out.
struct GlfwLibrary {
  ~GlfwLibrary() { glfwTerminate(); }
};

struct WindowDeleter {
  void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
};

}  // namespace

int commandPlay(const Options& options) {
  if (options.capture && options.quitAfterTicks == 0)
    throw UsageError("play: --capture needs --quit-after-ticks N (the tick whose frame it saves)");
  if (options.author && options.record)
    throw UsageError("play: --author flies through walls, which a replay cannot; drop --record");
  if (options.resetProgress) {
    game::saveProgress({}, game::progressFile());
    std::printf("progress reset: every level but the first is locked again\n");
  }
  fs::path level;
  if (!options.positional.empty()) {
    level = options.positional[0];
  } else {
    const auto levels = shippedLevels(findDataRoot());
    if (levels.empty()) throw UsageError("play: no levels found in levels/");
    level = play::firstUnwonLevel(levels);
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
  const auto [windowWidth, windowHeight] = options.windowSize.value_or(
      std::pair<uint32_t, uint32_t>(play::kWindowWidth, play::kWindowHeight));
  std::unique_ptr<GLFWwindow, WindowDeleter> window(
      glfwCreateWindow(int(windowWidth), int(windowHeight), "Sightline", nullptr, nullptr));
  if (!window) return fallBack("glfwCreateWindow failed: " + glfwErrorText);

  uint32_t extensionCount = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
  if (!extensions) return fallBack("no Vulkan surface for this window system: " + glfwErrorText);
  render::ContextOptions contextSettings = contextOptions(options);
  contextSettings.extraInstanceExtensions.assign(extensions, extensions + extensionCount);
  contextSettings.presentation = true;

  // Compiles the presenter's shaders and, later, the renderer's.
  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  // The presenter (its surface) must go before the context (its instance).
  std::unique_ptr<render::Context> context;
  std::unique_ptr<render::Presenter> presenter;
  try {
    context = std::make_unique<render::Context>(contextSettings);
    presenter = std::make_unique<render::Presenter>(*context, window.get(), settings.settings.vsync,
                                                    compiler, !options.windowPass);
  } catch (const render::RenderError& error) {
    presenter.reset();
    context.reset();
    window.reset();
    return fallBack(error.what());
  }
  std::printf("window: %ux%u, swapchain %s %s, on %s%s%s\n", presenter->extent().width,
              presenter->extent().height, render::Presenter::formatName(presenter->format()),
              render::Presenter::presentModeName(presenter->presentMode()),
              context->deviceInfo().name.c_str(),
              presenter->hasOwnXConnection() ? ", presenting over its own X connection" : "",
              presenter->scalesOnHost() ? ", the picture scaled by the CPU at 1x and 2x" : "");
  std::printf(
      "WASD move, mouse look, Space jump, E interact (held), wheel or Q/R adjust, Esc pause "
      "(menu: levels, settings, keys), F5 restart, F11 fullscreen, V vsync, F12 screenshot; "
      "for authors: F3 overlay, F4 fly camera, F6 copy the view as JSON; saving the level "
      "reloads it\n");
  std::fflush(stdout);

  const play::PlayOptions playing = playOptions(options);
  int status = 0;
  {
    play::Game game(playing, settings.settings, shippedLevels(findDataRoot()),
                    shippedChapters(findDataRoot()), window.get(), *context, compiler, *presenter);
    status = game.run(level);
  }
  presenter.reset();
  const int validation = validationExitCode(*context);
  return status != 0 ? status : validation;
}

}  // namespace app
