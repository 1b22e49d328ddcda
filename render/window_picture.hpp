#pragma once
// Draws into a swapchain image inside the presenter's render pass: the renderer's picture,
// scaled into its rectangle of the window, and solid rectangles (the HUD's bars and frames,
// the black bars beside a picture that does not fill the window). What this costs on lavapipe
// against transfer blits: docs/PERFORMANCE.md, session 34.
#include <array>

#include <vulkan/vulkan.h>

namespace render {

class Context;
class ShaderCompiler;

class WindowPicture {
 public:
  // `renderPass`: the presenter's, whose one subpass has one colour attachment. `filter`
  // scales the picture. Throws RenderError or ShaderCompileError. Its owner destroys it only
  // once no submitted draw of it is pending.
  WindowPicture(const Context& context, ShaderCompiler& compiler, VkRenderPass renderPass,
                VkFilter filter);
  ~WindowPicture();
  WindowPicture(const WindowPicture&) = delete;
  WindowPicture& operator=(const WindowPicture&) = delete;

  // The picture that drawPicture shows: `view` of an image in VK_IMAGE_LAYOUT_GENERAL. Only
  // while no submitted command buffer that draws it is still pending.
  void setPicture(VkImageView view);
  // Inside the render pass: the picture's top-left `shownWidth` x `shownHeight` texels of its
  // `pictureWidth` x `pictureHeight`, scaled into `area` of the window.
  void drawPicture(VkCommandBuffer commands, VkRect2D area, uint32_t shownWidth,
                   uint32_t shownHeight, uint32_t pictureWidth, uint32_t pictureHeight) const;
  // Inside the render pass: `area` of the window in one colour (RGBA, 0-1, written as it is).
  void fill(VkCommandBuffer commands, VkRect2D area, const std::array<float, 4>& colour) const;

 private:
  void release();

  const Context& context_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline picturePipeline_ = VK_NULL_HANDLE;
  VkPipeline fillPipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
