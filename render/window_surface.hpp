#pragma once
// The Vulkan surface of a GLFW window.
//
// On X11 with a CPU driver the surface talks to the X server over a connection of its own.
// Such a driver hands every presented image to the X server as a PutImage request (3.7 MB at
// 1280x720) unless the server offers DRI3, which Xvfb does not. Through GLFW's connection
// that upload held up the game: the next frame's event poll and the interface's window queries
// wait for a reply, and the reply came only after the server had read the whole image (play
// under Xvfb: `input` 2.1 ms a frame, 0.1 ms with a connection of its own). Elsewhere (a GPU,
// Wayland, a GLFW built without X11, a connection or surface that cannot be made) GLFW makes
// the surface as usual.
#include <vulkan/vulkan.h>

struct GLFWwindow;
struct xcb_connection_t;

namespace render {

class Context;

class WindowSurface {
 public:
  // The context's instance must have the extensions glfwGetRequiredInstanceExtensions names.
  // Throws RenderError when no surface can be made.
  WindowSurface(const Context& context, GLFWwindow* window);
  ~WindowSurface();
  WindowSurface(const WindowSurface&) = delete;
  WindowSurface& operator=(const WindowSurface&) = delete;

  VkSurfaceKHR handle() const { return surface_; }
  // Whether the surface has an X connection of its own (see above).
  bool hasOwnConnection() const { return connection_ != nullptr; }
  // With a connection of its own: returns once the X server has handled every request sent on
  // it, the presented images included (a round trip). Otherwise returns at once. On two cores
  // the server's copy of an image, left to run beside the next frame, cost that frame's passes
  // more than waiting for it here (docs/PERFORMANCE.md, session 38).
  void waitForServer() const;

 private:
  const Context& context_;
  xcb_connection_t* connection_ = nullptr;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

}  // namespace render
