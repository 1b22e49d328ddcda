#pragma once
// Pipeline barriers as one-line calls: a global memory barrier, and an image layout transition
// of a single-mip colour image.
#include <vulkan/vulkan.h>

namespace render {

void memoryBarrier(VkCommandBuffer commands, VkPipelineStageFlags srcStages,
                   VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                   VkAccessFlags dstAccess);

void imageLayoutBarrier(VkCommandBuffer commands, VkImage image, VkImageLayout from,
                        VkImageLayout to, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                        VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

}  // namespace render
