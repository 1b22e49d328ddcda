#pragma once
// A VkBuffer with its own memory: owning, movable, optionally mapped.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace render {

class Context;

enum class MemoryUse {
  DeviceOnly,  // fastest for the GPU; filled by commands
  Upload,      // host-written, GPU-read: device-local and host-visible where the device has it
  Readback,    // GPU-written, host-read: host cached where available
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse memory,
         const std::string& name);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkDeviceAddress address() const { return address_; }  // 0 without SHADER_DEVICE_ADDRESS usage
  void* mapped() const { return mapped_; }              // null for DeviceOnly

  void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  template <typename T>
  void write(std::span<const T> items, VkDeviceSize offset = 0) {
    write(items.data(), items.size_bytes(), offset);
  }
  void read(void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) const;

 private:
  void release();

  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkDeviceAddress address_ = 0;
  void* mapped_ = nullptr;
};

// A device-only storage buffer of `bytesPerPixel` bytes for each pixel of a width x height
// picture, which shaders write a value per pixel to (shaders/pixel_index.glsl) and copies or
// readDeviceBuffer read.
Buffer pixelBuffer(const Context& context, uint32_t width, uint32_t height,
                   VkDeviceSize bytesPerPixel, const std::string& name);

// Copies the whole of `source`, a device buffer that shaders wrote (TRANSFER_SRC usage), into
// `into` (source.size() bytes); submits and waits.
void readDeviceBytes(const Context& context, const Buffer& source, void* into);

// The whole of `source` (as readDeviceBytes) as the values of type T it holds.
template <typename T>
std::vector<T> readDeviceBuffer(const Context& context, const Buffer& source) {
  std::vector<T> values(source.size() / sizeof(T));
  readDeviceBytes(context, source, values.data());
  return values;
}

constexpr VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace render
