#include "render/window_surface.hpp"

#include <cstdlib>
#include <cstring>
#include <span>
#include <string>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

// Last: Xlib's headers define macros (None, Bool, Status, Success) that must not meet the
// project's names.
#if SIGHTLINE_GLFW_HAS_X11
#include <xcb/xcb.h>  // before vulkan_xcb.h, which declares with its types

#include <vulkan/vulkan_xcb.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#endif

namespace render {
namespace {

#if SIGHTLINE_GLFW_HAS_X11
bool glfwSurfaceIsXcb() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) return false;
  for (const char* name : std::span<const char*>(names, count))
    if (std::strcmp(name, VK_KHR_XCB_SURFACE_EXTENSION_NAME) == 0) return true;
  return false;
}

// The X display GLFW opened, or null where GLFW does not run on X11 (it then reports an error
// through its callback, which this check does not want: so the platform is asked first).
Display* glfwX11Display() {
#if GLFW_VERSION_MAJOR > 3 || (GLFW_VERSION_MAJOR == 3 && GLFW_VERSION_MINOR >= 4)
  if (glfwGetPlatform() != GLFW_PLATFORM_X11) return nullptr;
#endif
  return glfwGetX11Display();
}

// A surface for the window over a new connection to GLFW's X display; null (and no
// connection) where that cannot be made, and GLFW's own connection is then the way.
VkSurfaceKHR createOwnXcbSurface(VkInstance instance, GLFWwindow* window,
                                 xcb_connection_t** connection) {
  Display* display = glfwX11Display();
  if (!display) return VK_NULL_HANDLE;
  auto createXcbSurface = reinterpret_cast<PFN_vkCreateXcbSurfaceKHR>(
      vkGetInstanceProcAddr(instance, "vkCreateXcbSurfaceKHR"));
  if (!createXcbSurface) return VK_NULL_HANDLE;
  xcb_connection_t* opened = xcb_connect(DisplayString(display), nullptr);
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  if (!xcb_connection_has_error(opened)) {
    VkXcbSurfaceCreateInfoKHR info{VK_STRUCTURE_TYPE_XCB_SURFACE_CREATE_INFO_KHR};
    info.connection = opened;
    info.window = xcb_window_t(glfwGetX11Window(window));
    if (createXcbSurface(instance, &info, nullptr, &surface) != VK_SUCCESS)
      surface = VK_NULL_HANDLE;
  }
  if (!surface) {
    xcb_disconnect(opened);
    return VK_NULL_HANDLE;
  }
  *connection = opened;
  return surface;
}
#endif

}  // namespace

WindowSurface::WindowSurface(const Context& context, GLFWwindow* window) : context_(context) {
#if SIGHTLINE_GLFW_HAS_X11
  if (context.isCpuDevice() && glfwSurfaceIsXcb()) {
    surface_ = createOwnXcbSurface(context.instance(), window, &connection_);
    if (surface_) return;
  }
#endif
  const VkResult result = glfwCreateWindowSurface(context.instance(), window, nullptr, &surface_);
  if (result != VK_SUCCESS)
    throw RenderError(std::string("glfwCreateWindowSurface failed (") + vkResultName(result) + ")");
}

void WindowSurface::waitForServer() const {
#if SIGHTLINE_GLFW_HAS_X11
  if (!connection_) return;
  // Any request with a reply will do: the server answers requests in order.
  std::free(xcb_get_input_focus_reply(connection_, xcb_get_input_focus(connection_), nullptr));
#endif
}

WindowSurface::~WindowSurface() {
  vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
#if SIGHTLINE_GLFW_HAS_X11
  if (connection_) xcb_disconnect(connection_);
#endif
}

}  // namespace render
