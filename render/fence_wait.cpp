#include "render/fence_wait.hpp"

#include <cstdint>

#include "render/vulkan_error.hpp"

namespace render {

void waitForFence(VkDevice device, VkFence fence, std::chrono::milliseconds slice,
                  const std::function<void()>& whileWaiting) {
  if (!whileWaiting) {
    vkCheck(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    return;
  }
  const auto nanoseconds = uint64_t(std::chrono::nanoseconds(slice).count());
  for (;;) {
    const VkResult waited = vkWaitForFences(device, 1, &fence, VK_TRUE, nanoseconds);
    if (waited != VK_TIMEOUT) {
      vkCheck(waited, "vkWaitForFences");
      return;
    }
    whileWaiting();
  }
}

}  // namespace render
