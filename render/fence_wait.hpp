#pragma once
// Waiting for a fence in slices, with something to do between them: a window answers its
// events while the host waits for a long frame (on a CPU driver, a level's first frames compile
// their pipelines for seconds, and a desktop calls a window that does not answer for 5 s hung).
#include <chrono>
#include <functional>

#include <vulkan/vulkan.h>

namespace render {

// Returns once `fence` is signalled, calling `whileWaiting` after each `slice` it was not
// (empty: one wait). Throws RenderError when the wait fails (a lost device).
void waitForFence(VkDevice device, VkFence fence, std::chrono::milliseconds slice,
                  const std::function<void()>& whileWaiting);

}  // namespace render
