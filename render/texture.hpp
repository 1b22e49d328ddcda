#pragma once
// A sampled 2D texture on the device, uploaded once from RGBA8 data.
#include <string>

#include <vulkan/vulkan.h>

#include "scene/scene_desc.hpp"

namespace render {

class Context;

class Texture {
 public:
  // sRGB colour textures use *_SRGB (the sampler decodes to linear); data textures *_UNORM.
  Texture(const Context& context, const scene::TextureDesc& desc);
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  VkImageView view() const { return view_; }

 private:
  void destroyHandles();

  VkDevice device_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace render
