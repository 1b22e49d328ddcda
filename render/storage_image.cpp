#include "render/storage_image.hpp"

#include <glm/gtc/packing.hpp>

#include "render/barriers.hpp"
#include "render/buffer.hpp"
#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {

namespace {

void destroyImage(VkDevice device, VkImageView view, VkImage image, VkDeviceMemory memory) {
  if (view) vkDestroyImageView(device, view, nullptr);
  if (image) vkDestroyImage(device, image, nullptr);
  if (memory) vkFreeMemory(device, memory, nullptr);
}

}  // namespace

VkImage createImage2D(const Context& context, uint32_t width, uint32_t height, VkFormat format,
                      VkImageUsageFlags usage, const std::string& name, VkDeviceMemory* memory) {
  VkDevice device = context.device();
  VkImageCreateInfo imageInfo{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  imageInfo.imageType = VK_IMAGE_TYPE_2D;
  imageInfo.format = format;
  imageInfo.extent = {width, height, 1};
  imageInfo.mipLevels = 1;
  imageInfo.arrayLayers = 1;
  imageInfo.samples = VK_SAMPLE_COUNT_1_BIT;
  imageInfo.tiling = VK_IMAGE_TILING_OPTIMAL;
  imageInfo.usage = usage;
  imageInfo.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  vkCheck(vkCreateImage(device, &imageInfo, nullptr, &image), "vkCreateImage");
  context.setName(image, VK_OBJECT_TYPE_IMAGE, name);
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocateInfo.allocationSize = requirements.size;
  allocateInfo.memoryTypeIndex =
      context.findMemoryType(requirements.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkResult result = injectedFaultBefore("vkAllocateMemory");
  if (result == VK_SUCCESS) result = vkAllocateMemory(device, &allocateInfo, nullptr, memory);
  if (result != VK_SUCCESS) {
    vkDestroyImage(device, image, nullptr);
    vkCheck(result, ("vkAllocateMemory for " + name).c_str());
  }
  result = vkBindImageMemory(device, image, *memory, 0);
  if (result != VK_SUCCESS) {
    vkFreeMemory(device, *memory, nullptr);
    *memory = VK_NULL_HANDLE;
    vkDestroyImage(device, image, nullptr);
    vkCheck(result, "vkBindImageMemory");
  }
  return image;
}

VkImageView createImageView(const Context& context, VkImage image, VkFormat format,
                            const std::string& name) {
  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  vkCheck(vkCreateImageView(context.device(), &viewInfo, nullptr, &view), "vkCreateImageView");
  context.setName(view, VK_OBJECT_TYPE_IMAGE_VIEW, name + " view");
  return view;
}

StorageImage::StorageImage(const Context& context, uint32_t width, uint32_t height, VkFormat format,
                           VkImageUsageFlags extraUsage, const std::string& name)
    : device_(context.device()), width_(width), height_(height) {
  image_ = createImage2D(context, width, height, format, VK_IMAGE_USAGE_STORAGE_BIT | extraUsage,
                         name, &memory_);
  try {
    view_ = createImageView(context, image_, format, name);
    context.submitAndWait([&](VkCommandBuffer commands) {
      imageLayoutBarrier(commands, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                         VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT);
    });
  } catch (...) {  // the destructor does not run for a constructor that throws
    destroyImage(device_, view_, image_, memory_);
    throw;
  }
}

StorageImage::~StorageImage() {
  destroyImage(device_, view_, image_, memory_);
}

void uploadImage2D(const Context& context, VkImage image, uint32_t width, uint32_t height,
                   const void* bytes, VkImageLayout finalLayout, VkPipelineStageFlags nextStages,
                   VkAccessFlags nextAccess) {
  const VkDeviceSize size = VkDeviceSize(width) * height * 4;
  Buffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload,
                 "image upload staging");
  staging.write(bytes, size);
  context.submitAndWait([&](VkCommandBuffer commands) {
    imageLayoutBarrier(commands, image, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(commands, staging.handle(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    imageLayoutBarrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, nextStages,
                       nextAccess);
  });
}

std::vector<glm::vec4> readTexels(const Context& context, const StorageImage& image,
                                  bool halfFloats) {
  const VkDeviceSize texelBytes = halfFloats ? 8 : 16;
  const size_t texelCount = size_t(image.width()) * image.height();
  Buffer staging(context, texelBytes * texelCount, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 MemoryUse::Readback, "texel readback");
  context.submitAndWait([&](VkCommandBuffer commands) {
    imageLayoutBarrier(commands, image.image(), VK_IMAGE_LAYOUT_GENERAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.width(), image.height(), 1};
    vkCmdCopyImageToBuffer(commands, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           staging.handle(), 1, &region);
    imageLayoutBarrier(commands, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  });
  std::vector<glm::vec4> texels(texelCount);
  if (halfFloats) {
    std::vector<uint64_t> packed(texelCount);
    staging.read(packed.data(), packed.size() * sizeof(uint64_t));
    for (size_t i = 0; i < texelCount; ++i) texels[i] = glm::unpackHalf4x16(packed[i]);
  } else {
    staging.read(texels.data(), texels.size() * sizeof(glm::vec4));
  }
  return texels;
}

}  // namespace render
