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

// Throws RenderError naming the call when a Vulkan call does not succeed.
void vkCheck(VkResult result, const char* call);

}  // namespace render
