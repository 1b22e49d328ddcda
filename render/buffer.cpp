#include "render/buffer.hpp"

#include <stdexcept>
#include <utility>

#include "render/barriers.hpp"
#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
               MemoryUse memory, const std::string& name)
    : device_(context.device()), size_(size) {
  VkBufferCreateInfo createInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  createInfo.size = size;
  createInfo.usage = usage;
  createInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vkCheck(vkCreateBuffer(device_, &createInfo, nullptr, &buffer_), "vkCreateBuffer");
  context.setName(buffer_, VK_OBJECT_TYPE_BUFFER, name);

  // Nothing half-made stays behind when a step fails (a lost device, exhausted memory).
  try {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
    VkMemoryPropertyFlags required = 0, preferred = 0;
    switch (memory) {
      case MemoryUse::DeviceOnly:
        preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        break;
      case MemoryUse::Upload:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        break;
      case MemoryUse::Readback:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        break;
    }
    VkMemoryAllocateFlagsInfo flagsInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    const bool wantsAddress = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
    flagsInfo.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                      wantsAddress ? &flagsInfo : nullptr};
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex =
        context.findMemoryType(requirements.memoryTypeBits, required, preferred);
    VkResult result = injectedFaultBefore("vkAllocateMemory");
    if (result == VK_SUCCESS) result = vkAllocateMemory(device_, &allocateInfo, nullptr, &memory_);
    vkCheck(result, ("vkAllocateMemory for " + name).c_str());
    vkCheck(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    if (memory != MemoryUse::DeviceOnly) {
      vkCheck(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    }
    if (wantsAddress) {
      VkBufferDeviceAddressInfo addressInfo{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
      addressInfo.buffer = buffer_;
      address_ = vkGetBufferDeviceAddress(device_, &addressInfo);
    }
  } catch (...) {
    release();
    throw;
  }
}

Buffer::~Buffer() {
  release();
}

Buffer::Buffer(Buffer&& other) noexcept {
  *this = std::move(other);
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    address_ = std::exchange(other.address_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void Buffer::release() {
  if (!device_) return;
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  device_ = VK_NULL_HANDLE;
}

void Buffer::write(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (!mapped_ || offset + bytes > size_) throw RenderError("Buffer::write outside the buffer");
  std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
}

void Buffer::read(void* data, VkDeviceSize bytes, VkDeviceSize offset) const {
  if (!mapped_ || offset + bytes > size_) throw RenderError("Buffer::read outside the buffer");
  std::memcpy(data, static_cast<const char*>(mapped_) + offset, bytes);
}

Buffer pixelBuffer(const Context& context, uint32_t width, uint32_t height,
                   VkDeviceSize bytesPerPixel, const std::string& name) {
  return Buffer(context, VkDeviceSize(width) * height * bytesPerPixel,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                MemoryUse::DeviceOnly, name);
}

void readDeviceBytes(const Context& context, const Buffer& source, void* into) {
  Buffer staging(context, source.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback,
                 "buffer readback");
  context.submitAndWait([&](VkCommandBuffer commands) {
    memoryBarrier(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy copy{0, 0, source.size()};
    vkCmdCopyBuffer(commands, source.handle(), staging.handle(), 1, &copy);
    memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  });
  staging.read(into, source.size());
}

}  // namespace render
