#pragma once
// The Vulkan instance, the chosen ray tracing device, its queue and the extension entry points.
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace render {

struct ContextOptions {
  bool validate = false;       // Khronos validation layer with synchronization validation
  bool echoValidation = true;  // also print validation messages to stderr
  std::string deviceSelector;  // "" = best, else an index or part of the device name
  // Extensions a device must have besides the ray tracing ones (tests use a fake one to
  // exercise the "missing extension" message).
  std::vector<std::string> extraDeviceExtensions;
  // Instance extensions a window system needs for its surface (glfwGetRequiredInstanceExtensions).
  std::vector<std::string> extraInstanceExtensions;
  // Presenting to a window: requires and enables VK_KHR_swapchain on the device.
  bool presentation = false;
};

struct DeviceInfo {
  uint32_t index = 0;
  std::string name;
  std::string driver;  // driver name and info, e.g. "llvmpipe: Mesa 25.0.7 (LLVM 15.0.6)"
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t apiVersion = 0;
  std::vector<std::string> missingExtensions;  // empty when it can run Sightline
};

const char* deviceTypeName(VkPhysicalDeviceType type);

// What to tell a user whose device lacks ray tracing: the missing extensions and how to get
// them (lavapipe before Mesa 24.1 has none).
std::string describeMissingRayTracing(const DeviceInfo& device);

// Entry points of the extensions the loader does not export.
struct RayTracingFunctions {
  PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR getBuildSizes = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureAddress = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmdBuild = nullptr;
  PFN_vkCmdCopyAccelerationStructureKHR cmdCopy = nullptr;
  PFN_vkCmdWriteAccelerationStructuresPropertiesKHR cmdWriteProperties = nullptr;
  PFN_vkCreateRayTracingPipelinesKHR createPipelines = nullptr;
  PFN_vkGetRayTracingShaderGroupHandlesKHR getGroupHandles = nullptr;
  PFN_vkCmdTraceRaysKHR cmdTraceRays = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;  // null without debug utils
};

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Every device the loader reports, with what each lacks.
  static std::vector<DeviceInfo> listDevices(const std::vector<std::string>& extraExtensions = {});

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  VkCommandPool commandPool() const { return commandPool_; }
  // A primary command buffer from the pool (freed by its owner with vkFreeCommandBuffers).
  VkCommandBuffer allocateCommandBuffer() const;
  const DeviceInfo& deviceInfo() const { return deviceInfo_; }
  const RayTracingFunctions& rt() const { return rt_; }
  const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& rayTracingProperties() const {
    return rayTracingProperties_;
  }
  const VkPhysicalDeviceAccelerationStructurePropertiesKHR& accelerationStructureProperties()
      const {
    return accelerationStructureProperties_;
  }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  bool isCpuDevice() const { return deviceInfo_.type == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  bool validationEnabled() const { return validationEnabled_; }
  bool timestampsSupported() const { return timestampsSupported_; }
  // Subgroup add and elect in ray-gen shaders (NVIDIA: yes; lavapipe 25: compute and fragment
  // only): the ray-gen shader then sums its counters per subgroup before the atomics.
  bool raygenSubgroupArithmetic() const { return raygenSubgroupArithmetic_; }

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                          VkMemoryPropertyFlags preferred = 0) const;

  // Debug name shown by the validation layer and tools; no-op without debug utils.
  void setName(VkObjectType type, uint64_t handle, const std::string& name) const;
  template <typename Handle>
  void setName(Handle handle, VkObjectType type, const std::string& name) const {
    setName(type, reinterpret_cast<uint64_t>(handle), name);
  }

  // Records with `record`, submits and waits: for setup work, not per frame.
  template <typename Record>
  void submitAndWait(Record&& record) const {
    VkCommandBuffer commands = beginOneTimeCommands();
    record(commands);
    endOneTimeCommands(commands);
  }

  // Destroys the device and the instance now rather than in the destructor (nothing may use the
  // context afterwards). The validation layer reports objects still alive while this runs, so
  // validationMessages() after close() covers the whole run, leaks at exit included.
  void close();

  // Validation messages seen so far (warnings and errors).
  std::vector<std::string> validationMessages() const;
  size_t validationMessageCount() const;
  void clearValidationMessages();

 private:
  void destroy();
  VkCommandBuffer beginOneTimeCommands() const;
  void endOneTimeCommands(VkCommandBuffer commands) const;
  static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);

  ContextOptions options_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool validationEnabled_ = false;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  DeviceInfo deviceInfo_;
  bool timestampsSupported_ = false;
  bool raygenSubgroupArithmetic_ = false;
  RayTracingFunctions rt_;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rayTracingProperties_{};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR accelerationStructureProperties_{};
  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;
};

}  // namespace render
