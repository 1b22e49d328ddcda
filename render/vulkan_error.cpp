#include "render/vulkan_error.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string_view>

namespace render {

namespace {

struct FaultPoint {
  const char* call;
  VkResult result;
  bool beforeCall;  // failed in place of the call, because the call would create something
};

constexpr FaultPoint kFaultPoints[] = {
    {"vkQueueSubmit", VK_ERROR_DEVICE_LOST, false},
    {"vkWaitForFences", VK_ERROR_DEVICE_LOST, false},
    {"vkQueueWaitIdle", VK_ERROR_DEVICE_LOST, false},
    {"vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY, true},
};

struct FaultPlan {
  const FaultPoint* point = nullptr;
  uint64_t nth = 1;
  std::string setting;  // the variable's value, for the message
  std::atomic<uint64_t> seen{0};
};

FaultPlan faultPlan;
std::atomic<bool> faultArmed{false};
std::once_flag faultSettingRead;
thread_local bool faultJustInjected = false;  // the next vkCheck failure says it was injected

// "vkAllocateMemory for vertices" -> "vkAllocateMemory".
std::string_view functionName(const char* call) {
  const std::string_view label(call);
  return label.substr(0, label.find(' '));
}

// Counts a call of the armed function; true when it is the one to fail.
bool takeFault(const char* call, bool beforeCall) {
  const FaultPoint& point = *faultPlan.point;
  if (point.beforeCall != beforeCall || functionName(call) != point.call) return false;
  if (faultPlan.seen.fetch_add(1) + 1 != faultPlan.nth) return false;
  faultJustInjected = true;
  return true;
}

// What a failure means for the user and what they can do, or "" for results without advice.
std::string adviceFor(VkResult result) {
  switch (result) {
    case VK_ERROR_DEVICE_LOST:
      return "the GPU device was lost (the driver reset it after a hang or a crash, or the GPU "
             "went away) and nothing more can run on it; run again, and if it keeps happening, "
             "update the graphics driver, try a smaller --size or choose another device with "
             "--device (`sightline devices` lists them)";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
      return "the GPU has no memory left for it; close other programs that use the GPU, use a "
             "smaller --size or choose a device with more memory with --device (`sightline "
             "devices` lists them)";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
      return "the driver ran out of system memory; close other programs or use a smaller --size";
    default:
      return "";
  }
}

}  // namespace

const char* vkResultName(VkResult result) {
  switch (result) {
    case VK_SUCCESS:
      return "VK_SUCCESS";
    case VK_NOT_READY:
      return "VK_NOT_READY";
    case VK_TIMEOUT:
      return "VK_TIMEOUT";
    case VK_INCOMPLETE:
      return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
      return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
      return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED:
      return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST:
      return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT:
      return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
      return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT:
      return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
      return "VK_ERROR_INCOMPATIBLE_DRIVER";
    default:
      return "a VkResult error";
  }
}

void vkCheck(VkResult result, const char* call) {
  if (faultArmed.load(std::memory_order_acquire) && result == VK_SUCCESS && takeFault(call, false))
    result = faultPlan.point->result;
  if (result == VK_SUCCESS) return;
  std::string message = std::string(call) + " failed with " + vkResultName(result) + " (" +
                        std::to_string(static_cast<int>(result)) + ")";
  if (const std::string advice = adviceFor(result); !advice.empty()) message += ": " + advice;
  if (faultJustInjected) {
    faultJustInjected = false;
    message += " [injected by SIGHTLINE_FAULT=" + faultPlan.setting + "]";
  }
  throw RenderError(message);
}

void readFaultInjectionSetting() {
  std::call_once(faultSettingRead, [] {
    const char* value = std::getenv("SIGHTLINE_FAULT");
    if (!value || !*value) return;
    const std::string setting = value;
    std::string calls;
    for (const FaultPoint& point : kFaultPoints)
      calls += (calls.empty() ? "" : ", ") + std::string(point.call);
    const std::string expected = "SIGHTLINE_FAULT=" + setting +
                                 ": expected <call>[:<nth>] with <call> one of " + calls +
                                 " and <nth> a whole number from 1";
    const size_t colon = setting.find(':');
    const std::string name = setting.substr(0, colon);
    const FaultPoint* chosen = nullptr;
    for (const FaultPoint& point : kFaultPoints)
      if (name == point.call) chosen = &point;
    if (!chosen) throw RenderError(expected);
    uint64_t nth = 1;
    if (colon != std::string::npos) {
      const std::string count = setting.substr(colon + 1);
      if (count.empty() || count.size() > 12 ||
          count.find_first_not_of("0123456789") != std::string::npos)
        throw RenderError(expected);
      nth = std::stoull(count);
      if (nth == 0) throw RenderError(expected);
    }
    faultPlan.point = chosen;
    faultPlan.nth = nth;
    faultPlan.setting = setting;
    faultArmed.store(true, std::memory_order_release);
  });
}

VkResult injectedFaultBefore(const char* call) {
  if (faultArmed.load(std::memory_order_acquire) && takeFault(call, true))
    return faultPlan.point->result;
  return VK_SUCCESS;
}

}  // namespace render
