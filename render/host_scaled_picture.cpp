#include "render/host_scaled_picture.hpp"

#include <algorithm>
#include <system_error>
#include <thread>

#include "render/barriers.hpp"
#include "render/context.hpp"
#include "render/picture_doubling.hpp"
#include "render/renderer.hpp"
#include "render/vulkan_error.hpp"

namespace render {

HostScaledPicture::HostScaledPicture(const Context& context) : context_(context) {
  try {
    readCommands_ = context.allocateCommandBuffer();
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    vkCheck(vkCreateFence(context.device(), &fenceInfo, nullptr, &readDone_), "vkCreateFence");
  } catch (...) {
    release();
    throw;
  }
}

HostScaledPicture::~HostScaledPicture() {
  release();
}

void HostScaledPicture::release() {
  // readAndScale() waits for its own submit, and the presenter for the uploads it submitted.
  const VkDevice device = context_.device();
  if (readDone_) vkDestroyFence(device, readDone_, nullptr);
  readDone_ = VK_NULL_HANDLE;
  if (readCommands_) vkFreeCommandBuffers(device, context_.commandPool(), 1, &readCommands_);
  readCommands_ = VK_NULL_HANDLE;
}

uint32_t HostScaledPicture::factorFor(const Renderer& renderer, VkExtent2D window,
                                      VkFormat format) {
  // The picture's bytes go into the image as they are: four 8-bit channels (an _SRGB image
  // takes them as encoded already, which is what they are).
  switch (format) {
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
      break;
    default:
      return 0;
  }
  const uint32_t width = renderer.outputWidth(), height = renderer.outputHeight();
  if (renderer.shownWidth() != width || renderer.shownHeight() != height) return 0;
  auto near = [](uint32_t scaled, uint32_t side) {
    return (scaled > side ? scaled - side : side - scaled) <= kSlackPixels;
  };
  for (uint32_t factor : {2u, 1u})
    if (near(factor * width, window.width) && near(factor * height, window.height)) return factor;
  return 0;
}

VkRect2D HostScaledPicture::placement(VkExtent2D window) const {
  return {{(int32_t(window.width) - int32_t(scaledSize_.width)) / 2,
           (int32_t(window.height) - int32_t(scaledSize_.height)) / 2},
          scaledSize_};
}

void HostScaledPicture::readAndScale(const Renderer& renderer, uint32_t factor, VkFormat format) {
  const uint32_t width = renderer.outputWidth(), height = renderer.outputHeight();
  const VkDeviceSize pictureBytes = VkDeviceSize(width) * height * 4;
  if (readBack_.size() != pictureBytes) {
    readBack_ = Buffer(context_, pictureBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       MemoryUse::Readback, "window picture read back");
  }
  scaledSize_ = {factor * width, factor * height};
  const VkDeviceSize scaledBytes = VkDeviceSize(scaledSize_.width) * scaledSize_.height * 4;
  if (scaledPixels_.size() != scaledBytes) {
    scaledPixels_ = Buffer(context_, scaledBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                           MemoryUse::Upload, "window picture scaled");
  }

  vkCheck(vkResetCommandBuffer(readCommands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(readCommands_, &beginInfo), "vkBeginCommandBuffer");
  // The renderer's passes wrote the picture in earlier submits, and leave it in GENERAL.
  const VkImage image = renderer.outputImage();
  imageLayoutBarrier(readCommands_, image, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                     VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(readCommands_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         readBack_.handle(), 1, &region);
  memoryBarrier(readCommands_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  // Back to GENERAL, and the renderer's next passes write it only after this copy has read it.
  imageLayoutBarrier(readCommands_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                     VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  vkCheck(vkEndCommandBuffer(readCommands_), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &readCommands_;
  vkCheck(vkQueueSubmit(context_.queue(), 1, &submit, readDone_), "vkQueueSubmit");
  vkCheck(vkWaitForFences(context_.device(), 1, &readDone_, VK_TRUE, UINT64_MAX),
          "vkWaitForFences");
  vkCheck(vkResetFences(context_.device(), 1, &readDone_), "vkResetFences");

  const auto* source = static_cast<const uint8_t*>(readBack_.mapped());
  auto* target = static_cast<uint8_t*>(scaledPixels_.mapped());
  const bool swapRedBlue = isBlueFirst(format);
  const size_t targetRowBytes = size_t(scaledSize_.width) * 4;
  if (factor == 2) {
    // In two bands, the lower one on a thread of its own: the driver's threads are idle until
    // the upload is submitted (the present 0.35 ms shorter on a 2-core Xeon, 640x360 doubled).
    const uint32_t half = height / 2;
    upperBandScratch_.resize(doublingScratchSize(width));
    lowerBandScratch_.resize(doublingScratchSize(width));
    auto lower = [&] {
      doublePictureRows(source, width, height, half, height, target, targetRowBytes, swapRedBlue,
                        lowerBandScratch_);
    };
    std::jthread lowerBand;  // joined on leaving, however that happens
    try {
      lowerBand = std::jthread(lower);
    } catch (const std::system_error&) {  // no thread to be had: this one does both bands
      lower();
    }
    doublePictureRows(source, width, height, 0, half, target, targetRowBytes, swapRedBlue,
                      upperBandScratch_);
  } else {
    copyPicture(source, width, height, target, targetRowBytes, swapRedBlue);
  }
}

void HostScaledPicture::recordUpload(VkCommandBuffer commands, VkImage target,
                                     VkExtent2D window) const {
  // The acquire's semaphore is waited for at the transfer stage, where this transition starts.
  imageLayoutBarrier(commands, target, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  // The part of the picture inside the window, and where it goes there.
  const VkRect2D placed = placement(window);
  const uint32_t skipX = uint32_t(std::max(-placed.offset.x, 0));
  const uint32_t skipY = uint32_t(std::max(-placed.offset.y, 0));
  const int32_t toX = std::max(placed.offset.x, 0), toY = std::max(placed.offset.y, 0);
  const uint32_t width = std::min(scaledSize_.width - skipX, window.width - uint32_t(toX));
  const uint32_t height = std::min(scaledSize_.height - skipY, window.height - uint32_t(toY));
  if (width < window.width || height < window.height) {  // a black edge where it does not reach
    const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
    const VkImageSubresourceRange everything{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1,
                         &everything);
    memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  }
  VkBufferImageCopy region{};
  region.bufferOffset = (VkDeviceSize(skipY) * scaledSize_.width + skipX) * 4;
  region.bufferRowLength = scaledSize_.width;
  region.bufferImageHeight = scaledSize_.height;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageOffset = {toX, toY, 0};
  region.imageExtent = {width, height, 1};
  vkCmdCopyBufferToImage(commands, scaledPixels_.handle(), target,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  imageLayoutBarrier(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

}  // namespace render
