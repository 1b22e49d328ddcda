#include "render/context.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "render/vulkan_error.hpp"

namespace render {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
const std::vector<const char*> kRayTracingExtensions = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::vector<std::string> deviceExtensionNames(VkPhysicalDevice physicalDevice) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &count, extensions.data());
  std::vector<std::string> names;
  for (const auto& extension : extensions) names.emplace_back(extension.extensionName);
  return names;
}

DeviceInfo describeDevice(VkPhysicalDevice physicalDevice, uint32_t index,
                          const std::vector<std::string>& extraExtensions) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
  DeviceInfo info;
  info.index = index;
  info.name = properties.properties.deviceName;
  info.driver = std::string(driver.driverName) + ": " + driver.driverInfo;
  info.type = properties.properties.deviceType;
  info.apiVersion = properties.properties.apiVersion;

  const std::vector<std::string> available = deviceExtensionNames(physicalDevice);
  auto require = [&](const std::string& name) {
    if (std::find(available.begin(), available.end(), name) == available.end())
      info.missingExtensions.push_back(name);
  };
  for (const char* name : kRayTracingExtensions) require(name);
  for (const std::string& name : extraExtensions) require(name);
  if (VK_API_VERSION_MINOR(info.apiVersion) < 2 && VK_API_VERSION_MAJOR(info.apiVersion) == 1)
    info.missingExtensions.push_back("Vulkan 1.2");
  return info;
}

int deviceTypeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

// `messengerInfo`, when validating, also receives the messages of vkCreateInstance and
// vkDestroyInstance (such as instance objects left alive).
VkInstance createInstance(bool validate, const std::vector<std::string>& extraExtensions,
                          const VkDebugUtilsMessengerCreateInfoEXT* messengerInfo,
                          bool* debugUtilsEnabled) {
  uint32_t extensionCount = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkEnumerateInstanceExtensionProperties(nullptr, &extensionCount, extensions.data());
  auto hasExtension = [&](const char* name) {
    return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, name) == 0;
    });
  };

  std::vector<const char*> enabledExtensions;
  for (const std::string& name : extraExtensions) {
    if (!hasExtension(name.c_str()))
      throw RenderError("the Vulkan loader lacks the instance extension " + name);
    enabledExtensions.push_back(name.c_str());
  }
  std::vector<const char*> layers;
  *debugUtilsEnabled = false;
  VkValidationFeatureEnableEXT enabledFeatures[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT validationFeatures{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  validationFeatures.enabledValidationFeatureCount = 1;
  validationFeatures.pEnabledValidationFeatures = enabledFeatures;
  const void* next = nullptr;
  if (validate) {
    uint32_t layerCount = 0;
    vkEnumerateInstanceLayerProperties(&layerCount, nullptr);
    std::vector<VkLayerProperties> available(layerCount);
    vkEnumerateInstanceLayerProperties(&layerCount, available.data());
    bool found = std::any_of(available.begin(), available.end(), [](const VkLayerProperties& l) {
      return std::strcmp(l.layerName, kValidationLayer) == 0;
    });
    if (!found) {
      throw RenderError(
          "--validate needs the Khronos validation layer, which is not installed "
          "(Debian: apt-get install vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
    if (!hasExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
      throw RenderError("--validate needs VK_EXT_debug_utils, which the Vulkan loader lacks");
    }
    enabledExtensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // The layer provides VK_EXT_validation_features, which turns synchronization checks on.
    enabledExtensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    validationFeatures.pNext = messengerInfo;
    next = &validationFeatures;
    *debugUtilsEnabled = true;
  }

  VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  application.pApplicationName = "Sightline";
  application.pEngineName = "Sightline";
  application.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo createInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, next};
  createInfo.pApplicationInfo = &application;
  createInfo.enabledLayerCount = static_cast<uint32_t>(layers.size());
  createInfo.ppEnabledLayerNames = layers.data();
  createInfo.enabledExtensionCount = static_cast<uint32_t>(enabledExtensions.size());
  createInfo.ppEnabledExtensionNames = enabledExtensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&createInfo, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw RenderError(
        "the Vulkan loader found no usable driver (VK_ERROR_INCOMPATIBLE_DRIVER): install one "
        "with ray tracing (Debian 12: mesa-vulkan-drivers from bookworm-backports, which "
        "scripts/setup.sh installs); VK_LOADER_DEBUG=error shows why a driver did not load");
  }
  vkCheck(result, "vkCreateInstance");
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  vkCheck(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  vkCheck(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
          "vkEnumeratePhysicalDevices");
  return devices;
}

template <typename Function>
Function loadDeviceFunction(VkDevice device, const char* name) {
  auto function = reinterpret_cast<Function>(vkGetDeviceProcAddr(device, name));
  if (!function) throw RenderError(std::string("the driver does not provide ") + name);
  return function;
}

}  // namespace

const char* deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

std::string describeMissingRayTracing(const DeviceInfo& device) {
  std::ostringstream text;
  text << device.name << " (" << device.driver << ") lacks";
  for (size_t i = 0; i < device.missingExtensions.size(); ++i)
    text << (i == 0 ? " " : ", ") << device.missingExtensions[i];
  // Mesa's driverInfo starts with "Mesa X.Y"; lavapipe gained ray tracing in 24.1.
  const std::string lowerName = lowercase(device.name);
  const size_t mesaAt = device.driver.find("Mesa ");
  if (lowerName.find("llvmpipe") != std::string::npos && mesaAt != std::string::npos) {
    int major = 0, minor = 0;
    if (std::sscanf(device.driver.c_str() + mesaAt, "Mesa %d.%d", &major, &minor) == 2 &&
        (major < 24 || (major == 24 && minor < 1))) {
      text << "; lavapipe from Mesa " << major << "." << minor
           << " has no ray tracing; install Mesa >= 24.1 (Debian 12: mesa-vulkan-drivers from "
              "bookworm-backports, which scripts/setup.sh installs)";
      return text.str();
    }
  }
  text << "; use a driver with Vulkan ray tracing pipelines (Mesa >= 24.1 lavapipe, or a "
          "recent NVIDIA or AMD driver)";
  return text.str();
}

std::vector<DeviceInfo> Context::listDevices(const std::vector<std::string>& extraExtensions) {
  bool debugUtils = false;
  VkInstance instance = createInstance(false, {}, nullptr, &debugUtils);
  std::vector<DeviceInfo> devices;
  try {
    uint32_t index = 0;
    for (VkPhysicalDevice physicalDevice : physicalDevices(instance))
      devices.push_back(describeDevice(physicalDevice, index++, extraExtensions));
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  return devices;
}

Context::Context(const ContextOptions& options) : options_(options) {
  readFaultInjectionSetting();
  bool debugUtils = false;
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Context::onDebugMessage;
  messengerInfo.pUserData = this;
  instance_ = createInstance(options.validate, options.extraInstanceExtensions, &messengerInfo,
                             &debugUtils);
  validationEnabled_ = debugUtils;
  try {
    if (debugUtils) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      vkCheck(create(instance_, &messengerInfo, nullptr, &messenger_),
              "vkCreateDebugUtilsMessengerEXT");
    }

    // Choose: the selected device, else the best-ranked one that has ray tracing.
    const std::vector<VkPhysicalDevice> devices = physicalDevices(instance_);
    std::vector<std::string> requiredExtensions = options.extraDeviceExtensions;
    if (options.presentation) requiredExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i)
      infos.push_back(describeDevice(devices[i], i, requiredExtensions));
    if (infos.empty()) {
      throw RenderError(
          "the Vulkan loader found no device: install a driver with ray tracing (Debian 12: "
          "mesa-vulkan-drivers from bookworm-backports, which scripts/setup.sh installs)");
    }
    std::vector<const DeviceInfo*> candidates;
    if (!options.deviceSelector.empty()) {
      const std::string selector = lowercase(options.deviceSelector);
      const bool isIndex = std::all_of(selector.begin(), selector.end(),
                                       [](unsigned char c) { return std::isdigit(c); });
      for (const DeviceInfo& info : infos) {
        if (isIndex ? std::to_string(info.index) == selector
                    : lowercase(info.name).find(selector) != std::string::npos)
          candidates.push_back(&info);
      }
      if (candidates.empty()) {
        throw RenderError("--device " + options.deviceSelector +
                          " matches no device; `sightline devices` lists them");
      }
    } else {
      for (const DeviceInfo& info : infos) candidates.push_back(&info);
    }
    const DeviceInfo* chosen = nullptr;
    for (const DeviceInfo* info : candidates) {
      if (!info->missingExtensions.empty()) continue;
      if (!chosen || deviceTypeRank(info->type) > deviceTypeRank(chosen->type)) chosen = info;
    }
    if (!chosen) {
      std::string message = "no Vulkan device with ray tracing: ";
      for (size_t i = 0; i < candidates.size(); ++i)
        message += (i ? "; " : "") + describeMissingRayTracing(*candidates[i]);
      throw RenderError(message);
    }
    deviceInfo_ = *chosen;
    physicalDevice_ = devices[chosen->index];

    accelerationStructureProperties_.sType =
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR;
    rayTracingProperties_.sType =
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR;
    rayTracingProperties_.pNext = &accelerationStructureProperties_;
    VkPhysicalDeviceSubgroupProperties subgroupProperties{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    accelerationStructureProperties_.pNext = &subgroupProperties;
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                            &rayTracingProperties_};
    vkGetPhysicalDeviceProperties2(physicalDevice_, &properties2);
    properties_ = properties2.properties;
    const VkSubgroupFeatureFlags neededOperations =
        VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
    raygenSubgroupArithmetic_ =
        (subgroupProperties.supportedStages & VK_SHADER_STAGE_RAYGEN_BIT_KHR) != 0 &&
        (subgroupProperties.supportedOperations & neededOperations) == neededOperations;
    rayTracingProperties_.pNext = nullptr;
    accelerationStructureProperties_.pNext = nullptr;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
    bool foundFamily = false;
    for (uint32_t i = 0; i < familyCount; ++i) {
      if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
          (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
        queueFamily_ = i;
        foundFamily = true;
        break;
      }
    }
    if (!foundFamily) throw RenderError(deviceInfo_.name + " has no graphics+compute queue");
    timestampsSupported_ = families[queueFamily_].timestampValidBits > 0 &&
                           properties_.limits.timestampComputeAndGraphics;

    // Feature chain: Vulkan 1.2 (device addresses) -> acceleration structures -> pipelines.
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipelineFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR structureFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &pipelineFeatures};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                              &structureFeatures};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan12};
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &features);
    if (!vulkan12.bufferDeviceAddress || !structureFeatures.accelerationStructure ||
        !pipelineFeatures.rayTracingPipeline || !vulkan12.runtimeDescriptorArray ||
        !vulkan12.shaderSampledImageArrayNonUniformIndexing ||
        !features.features.shaderStorageImageExtendedFormats) {
      throw RenderError(deviceInfo_.name +
                        " lacks a feature Sightline needs (bufferDeviceAddress, "
                        "accelerationStructure, rayTracingPipeline, runtimeDescriptorArray, "
                        "shaderSampledImageArrayNonUniformIndexing, "
                        "shaderStorageImageExtendedFormats)");
    }
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR enablePipeline{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    enablePipeline.rayTracingPipeline = VK_TRUE;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR enableStructures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &enablePipeline};
    enableStructures.accelerationStructure = VK_TRUE;
    VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                              &enableStructures};
    enable12.bufferDeviceAddress = VK_TRUE;
    enable12.runtimeDescriptorArray = VK_TRUE;  // texture array sized per level
    enable12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    enable12.scalarBlockLayout = vulkan12.scalarBlockLayout;
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &enable12};
    enable.features.shaderInt64 = features.features.shaderInt64;
    enable.features.shaderStorageImageExtendedFormats = VK_TRUE;  // the denoiser's rg32ui images

    std::vector<const char*> extensions(kRayTracingExtensions.begin(), kRayTracingExtensions.end());
    for (const std::string& name : requiredExtensions) extensions.push_back(name.c_str());
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enable};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    deviceInfo.ppEnabledExtensionNames = extensions.data();
    vkCheck(vkCreateDevice(physicalDevice_, &deviceInfo, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    rt_.createAccelerationStructure = loadDeviceFunction<PFN_vkCreateAccelerationStructureKHR>(
        device_, "vkCreateAccelerationStructureKHR");
    rt_.destroyAccelerationStructure = loadDeviceFunction<PFN_vkDestroyAccelerationStructureKHR>(
        device_, "vkDestroyAccelerationStructureKHR");
    rt_.getBuildSizes = loadDeviceFunction<PFN_vkGetAccelerationStructureBuildSizesKHR>(
        device_, "vkGetAccelerationStructureBuildSizesKHR");
    rt_.getAccelerationStructureAddress =
        loadDeviceFunction<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
            device_, "vkGetAccelerationStructureDeviceAddressKHR");
    rt_.cmdBuild = loadDeviceFunction<PFN_vkCmdBuildAccelerationStructuresKHR>(
        device_, "vkCmdBuildAccelerationStructuresKHR");
    rt_.cmdCopy = loadDeviceFunction<PFN_vkCmdCopyAccelerationStructureKHR>(
        device_, "vkCmdCopyAccelerationStructureKHR");
    rt_.cmdWriteProperties = loadDeviceFunction<PFN_vkCmdWriteAccelerationStructuresPropertiesKHR>(
        device_, "vkCmdWriteAccelerationStructuresPropertiesKHR");
    rt_.createPipelines = loadDeviceFunction<PFN_vkCreateRayTracingPipelinesKHR>(
        device_, "vkCreateRayTracingPipelinesKHR");
    rt_.getGroupHandles = loadDeviceFunction<PFN_vkGetRayTracingShaderGroupHandlesKHR>(
        device_, "vkGetRayTracingShaderGroupHandlesKHR");
    rt_.cmdTraceRays = loadDeviceFunction<PFN_vkCmdTraceRaysKHR>(device_, "vkCmdTraceRaysKHR");
    if (debugUtils) {
      rt_.setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
          vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
    }

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily_;
    vkCheck(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
  } catch (...) {
    destroy();
    throw;
  }
}

Context::~Context() {
  destroy();
}

void Context::close() {
  destroy();
}

void Context::destroy() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                 VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags wanted : {required | preferred, required}) {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) &&
          (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted)
        return i;
    }
  }
  throw RenderError(deviceInfo_.name + " has no memory type with the needed properties");
}

void Context::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!rt_.setObjectName) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  rt_.setObjectName(device_, &info);
}

VkCommandBuffer Context::allocateCommandBuffer() const {
  VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocateInfo.commandPool = commandPool_;
  allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocateInfo.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  vkCheck(vkAllocateCommandBuffers(device_, &allocateInfo, &commands), "vkAllocateCommandBuffers");
  return commands;
}

VkCommandBuffer Context::beginOneTimeCommands() const {
  VkCommandBuffer commands = allocateCommandBuffer();
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(commands, &beginInfo), "vkBeginCommandBuffer");
  return commands;
}

void Context::endOneTimeCommands(VkCommandBuffer commands) const {
  try {
    vkCheck(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    vkCheck(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
    vkCheck(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
  } catch (...) {
    // The buffers the commands use are destroyed while the error unwinds: whatever was submitted
    // must be finished (or the device lost, which returns at once) before that.
    vkDeviceWaitIdle(device_);
    vkFreeCommandBuffers(device_, commandPool_, 1, &commands);
    throw;
  }
  vkFreeCommandBuffers(device_, commandPool_, 1, &commands);
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onDebugMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  auto* context = static_cast<Context*>(self);
  std::string message = std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT
                                        ? "validation error: "
                                        : "validation warning: ") +
                        (data->pMessage ? data->pMessage : "");
  if (context->options_.echoValidation) std::fprintf(stderr, "%s\n", message.c_str());
  std::lock_guard lock(context->messagesMutex_);
  context->messages_.push_back(std::move(message));
  return VK_FALSE;
}

std::vector<std::string> Context::validationMessages() const {
  std::lock_guard lock(messagesMutex_);
  return messages_;
}

size_t Context::validationMessageCount() const {
  std::lock_guard lock(messagesMutex_);
  return messages_.size();
}

void Context::clearValidationMessages() {
  std::lock_guard lock(messagesMutex_);
  messages_.clear();
}

}  // namespace render
