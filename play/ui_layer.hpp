#pragma once
// Dear ImGui over the play window: its context, the GLFW and Vulkan backends and the font
// texture. The text and menus are drawn in the presenter's overlay render pass.
#include <vulkan/vulkan.h>

#include "render/presenter.hpp"

struct GLFWwindow;

namespace render {
class Context;
}

namespace play {

class UiLayer {
 public:
  // Install the window's own GLFW callbacks first: the GLFW backend calls them after its own.
  // `uiScale` multiplies font and widget sizes (the window's content scale). Throws
  // RenderError.
  UiLayer(const render::Context& context, GLFWwindow* window, const render::Presenter& presenter,
          float uiScale);
  ~UiLayer();
  UiLayer(const UiLayer&) = delete;
  UiLayer& operator=(const UiLayer&) = delete;

  // Starts a frame of ImGui calls (after the window's events were polled).
  void beginFrame();
  // Ends the frame; the returned draw records it for the presenter (empty when nothing shows).
  render::OverlayDraw endFrame();

 private:
  void release();

  const render::Context& context_;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  bool glfwBackend_ = false;
  bool vulkanBackend_ = false;
};

}  // namespace play
