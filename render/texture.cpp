#include "render/texture.hpp"

#include "render/context.hpp"
#include "render/storage_image.hpp"
#include "render/vulkan_error.hpp"

namespace render {

Texture::Texture(const Context& context, const scene::TextureDesc& desc)
    : device_(context.device()) {
  if (desc.width == 0 || desc.height == 0 ||
      desc.rgba.size() != size_t(desc.width) * desc.height * 4) {
    throw RenderError("texture '" + desc.name + "' has no pixels or a wrong size");
  }
  const VkFormat format = desc.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  image_ = createImage2D(context, desc.width, desc.height, format,
                         VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                         "texture " + desc.name, &memory_);
  try {
    uploadImage2D(context, image_, desc.width, desc.height, desc.rgba.data(),
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_READ_BIT);
    view_ = createImageView(context, image_, format, "texture " + desc.name);
  } catch (...) {  // the destructor does not run for a constructor that throws
    destroyHandles();
    throw;
  }
}

Texture::~Texture() {
  destroyHandles();
}

void Texture::destroyHandles() {
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
}

}  // namespace render
