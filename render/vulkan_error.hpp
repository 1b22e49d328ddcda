#pragma once
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace render {

// Any failure of the renderer: one sentence a user can act on.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

const char* vkResultName(VkResult result);

// Throws RenderError naming the call when a Vulkan call does not succeed; for a lost device or
// exhausted memory the message also says what that means and what the user can do. `call` is
// the function's name, optionally followed by a space and what it was for.
void vkCheck(VkResult result, const char* call);

// ----- Fault injection: a test switch in the real call path (docs/ROBUSTNESS.md) -----
// SIGHTLINE_FAULT=<call>[:<nth>] makes the nth (default: first) successful call of <call> fail:
// vkQueueSubmit, vkWaitForFences and vkQueueWaitIdle with VK_ERROR_DEVICE_LOST after the call
// ran (the driver reporting a loss), vkAllocateMemory with VK_ERROR_OUT_OF_DEVICE_MEMORY instead
// of the call (nothing allocated). Read once, by the first Context; unset, vkCheck costs one
// extra branch. Throws RenderError when the value names no such call or a bad count.
void readFaultInjectionSetting();

// For calls counted before they are made (vkAllocateMemory): the error to return instead of
// making the call, or VK_SUCCESS to make it.
VkResult injectedFaultBefore(const char* call);

}  // namespace render
