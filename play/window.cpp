#include "play/window.hpp"

#include <cstdio>
#include <string>

#include <GLFW/glfw3.h>

#include "game/level.hpp"
#include "game/settings.hpp"
#include "render/presenter.hpp"
#include "sim/simulation.hpp"

namespace play {
namespace {

// F3, for level authors: the probe readings the rules use now, and the tick they show.
std::string rawProbeValues(const sim::Simulation& simulation) {
  const auto& readings = simulation.latestReadings();
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

}  // namespace

void showTitle(GLFWwindow* window, const game::Level& level, const sim::Simulation& simulation,
               double fps, bool paused, bool authorOverlay) {
  std::string title = "Sightline | " + level.name;
  if (fps > 0.0) title += " | " + std::to_string(int(fps + 0.5)) + " fps";
  const auto& progress = simulation.rules().progress();
  if (!progress.empty()) {
    title += " | " + progress[0].label + ": " +
             std::to_string(int(progress[0].progress * 100.0f + 0.5f)) + "%";
  }
  switch (simulation.outcome()) {
    case game::Outcome::Won:
      title += " | Won!";
      break;
    case game::Outcome::Lost:
      title += " | Lost (" + simulation.rules().reason() + "); restarting";
      break;
    case game::Outcome::Playing:
      break;
  }
  if (paused) title += " | Paused: Esc resumes, F5 restarts, close the window to quit";
  if (authorOverlay) title += " | " + rawProbeValues(simulation);
  glfwSetWindowTitle(window, title.c_str());
}

void toggleFullscreen(GLFWwindow* window, WindowedPlacement& windowed) {
  if (glfwGetWindowMonitor(window)) {
    glfwSetWindowMonitor(window, nullptr, windowed.x, windowed.y, windowed.width, windowed.height,
                         0);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  if (!mode) return;
  glfwGetWindowPos(window, &windowed.x, &windowed.y);
  glfwGetWindowSize(window, &windowed.width, &windowed.height);
  glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

void toggleVsync(render::Presenter& presenter, game::Settings& settings) {
  presenter.setVsync(!presenter.vsync());
  settings.vsync = presenter.vsync();
  std::printf("vsync %s\n", presenter.vsync() ? "on" : "off");
}

void reportSwapchainChange(const render::Presenter& presenter, ShownSwapchain& shown) {
  const VkExtent2D extent = presenter.extent();
  const VkPresentModeKHR mode = presenter.presentMode();
  if (extent.width == shown.extent.width && extent.height == shown.extent.height &&
      mode == shown.mode)
    return;
  shown.extent = extent;
  shown.mode = mode;
  std::printf("swapchain now %ux%u %s\n", extent.width, extent.height,
              render::Presenter::presentModeName(mode));
  std::fflush(stdout);
}

}  // namespace play
