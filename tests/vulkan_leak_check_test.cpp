// The check behind "no Vulkan object left at exit" (sightline soak --validate, docs/ROBUSTNESS.md):
// with validation on, Context::close() destroys the device and the instance, the layer reports
// every object still alive, and those reports land in validationMessages().
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace {

render::ContextOptions quietValidation() {
  render::ContextOptions options;
  options.validate = true;
  options.echoValidation = false;
  return options;
}

TEST(VulkanLeakCheck, context_close_reports_a_fence_left_alive) {
  render::Context context(quietValidation());
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  render::vkCheck(vkCreateFence(context.device(), &fenceInfo, nullptr, &fence), "vkCreateFence");
  context.setName(fence, VK_OBJECT_TYPE_FENCE, "forgotten fence");
  ASSERT_EQ(context.validationMessageCount(), 0u);

  context.close();  // the fence is still alive: the layer must say so
  const std::vector<std::string> messages = context.validationMessages();
  ASSERT_EQ(messages.size(), 1u) << (messages.empty() ? "" : messages.front());
  EXPECT_NE(messages[0].find("forgotten fence"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("has not been destroyed"), std::string::npos) << messages[0];
  EXPECT_TRUE(context.validationEnabled());
}

TEST(VulkanLeakCheck, context_close_is_silent_when_everything_was_destroyed) {
  render::Context context(quietValidation());
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  render::vkCheck(vkCreateFence(context.device(), &fenceInfo, nullptr, &fence), "vkCreateFence");
  vkDestroyFence(context.device(), fence, nullptr);
  context.close();
  EXPECT_EQ(context.validationMessageCount(), 0u);
}

}  // namespace
