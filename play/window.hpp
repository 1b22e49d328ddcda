#pragma once
// The play window: its title, fullscreen, vsync and the swapchain as reported.
#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace game {
struct Level;
struct Settings;
}  // namespace game
namespace render {
class Presenter;
}
namespace sim {
class Simulation;
}

namespace play {

constexpr int kWindowWidth = 1280, kWindowHeight = 720;  // the window's size unless --window

// "Sightline | level | fps | first goal's progress", then the outcome, the pause and (F3) the
// probe values. No fps while `fps` is 0.
void showTitle(GLFWwindow* window, const game::Level& level, const sim::Simulation& simulation,
               double fps, bool paused, bool authorOverlay);

// Where the window was before fullscreen, to go back to.
struct WindowedPlacement {
  int x = 0, y = 0, width = kWindowWidth, height = kWindowHeight;
};

void toggleFullscreen(GLFWwindow* window, WindowedPlacement& windowed);

// V: vsync on (FIFO) or off (MAILBOX or IMMEDIATE where offered), kept in the settings.
void toggleVsync(render::Presenter& presenter, game::Settings& settings);

// The swapchain as last reported.
struct ShownSwapchain {
  VkExtent2D extent;
  VkPresentModeKHR mode;
};

// Resizes, fullscreen and vsync rebuild the swapchain; say what it became.
void reportSwapchainChange(const render::Presenter& presenter, ShownSwapchain& shown);

}  // namespace play
