#include "render/window_surface.hpp"

#include <cstring>
#include <span>
#include <string>

#include <xcb/xcb.h>  // before vulkan_xcb.h, which declares with its types

#include <vulkan/vulkan_xcb.h>
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {
namespace {

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

}  // namespace

WindowSurface::WindowSurface(const Context& context, GLFWwindow* window) : context_(context) {
  Display* display = context.isCpuDevice() && glfwSurfaceIsXcb() ? glfwX11Display() : nullptr;
  if (display) {
    xcb_connection_t* connection = xcb_connect(DisplayString(display), nullptr);
    if (xcb_connection_has_error(connection)) {
      xcb_disconnect(connection);  // GLFW's connection still works: use it
    } else {
      connection_ = connection;
      auto createXcbSurface = reinterpret_cast<PFN_vkCreateXcbSurfaceKHR>(
          vkGetInstanceProcAddr(context.instance(), "vkCreateXcbSurfaceKHR"));
      VkXcbSurfaceCreateInfoKHR info{VK_STRUCTURE_TYPE_XCB_SURFACE_CREATE_INFO_KHR};
      info.connection = connection_;
      info.window = xcb_window_t(glfwGetX11Window(window));
      const VkResult result = createXcbSurface
                                  ? createXcbSurface(context.instance(), &info, nullptr, &surface_)
                                  : VK_ERROR_EXTENSION_NOT_PRESENT;
      if (result != VK_SUCCESS) {
        xcb_disconnect(connection_);
        throw RenderError(std::string("vkCreateXcbSurfaceKHR failed (") + vkResultName(result) +
                          ")");
      }
      return;
    }
  }
  const VkResult result = glfwCreateWindowSurface(context.instance(), window, nullptr, &surface_);
  if (result != VK_SUCCESS)
    throw RenderError(std::string("glfwCreateWindowSurface failed (") + vkResultName(result) + ")");
}

WindowSurface::~WindowSurface() {
  vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
  if (connection_) xcb_disconnect(connection_);
}

}  // namespace render
