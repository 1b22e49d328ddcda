#pragma once
// A 2D image the shaders read and write, kept in VK_IMAGE_LAYOUT_GENERAL.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

namespace render {

class Context;

class StorageImage {
 public:
  StorageImage(const Context& context, uint32_t width, uint32_t height, VkFormat format,
               VkImageUsageFlags extraUsage, const std::string& name);
  ~StorageImage();
  StorageImage(const StorageImage&) = delete;
  StorageImage& operator=(const StorageImage&) = delete;

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  VkDevice device_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  uint32_t width_;
  uint32_t height_;
};

// A device-local 2D image (one mip, one layer) and its memory; throws RenderError.
VkImage createImage2D(const Context& context, uint32_t width, uint32_t height, VkFormat format,
                      VkImageUsageFlags usage, const std::string& name, VkDeviceMemory* memory);
// Fills a whole 2D image (created with TRANSFER_DST usage, contents undefined) with RGBA8
// `bytes` through a staging buffer, then moves it to `finalLayout` for the stages and accesses
// that use it next; waits until done.
void uploadImage2D(const Context& context, VkImage image, uint32_t width, uint32_t height,
                   const void* bytes, VkImageLayout finalLayout, VkPipelineStageFlags nextStages,
                   VkAccessFlags nextAccess);
// The texels of a float image kept in GENERAL (created with TRANSFER_SRC usage): rgba16f when
// `halfFloats`, else rgba32f. A test and debugging hook: submits and waits.
std::vector<glm::vec4> readTexels(const Context& context, const StorageImage& image,
                                  bool halfFloats);
VkImageView createImageView(const Context& context, VkImage image, VkFormat format,
                            const std::string& name);

}  // namespace render
