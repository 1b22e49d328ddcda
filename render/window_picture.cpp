#include "render/window_picture.hpp"

#include "render/context.hpp"
#include "render/fullscreen_pipeline.hpp"
#include "render/vulkan_error.hpp"

namespace render {
namespace {

// Both fragment shaders' push constants: window_picture.frag's placement (its origin and
// texture coordinates per pixel) or solid_fill.frag's colour.
constexpr uint32_t kPushConstantBytes = 4 * sizeof(float);

}  // namespace

WindowPicture::WindowPicture(const Context& context, ShaderCompiler& compiler,
                             VkRenderPass renderPass, VkFilter filter)
    : context_(context) {
  const VkDevice device = context.device();
  try {
    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = samplerInfo.minFilter = filter;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    vkCheck(vkCreateSampler(device, &samplerInfo, nullptr, &sampler_), "vkCreateSampler");

    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                               VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo setLayoutInfo{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setLayoutInfo.bindingCount = 1;
    setLayoutInfo.pBindings = &binding;
    vkCheck(vkCreateDescriptorSetLayout(device, &setLayoutInfo, nullptr, &setLayout_),
            "vkCreateDescriptorSetLayout");
    const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &poolSize;
    vkCheck(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocateInfo.descriptorPool = pool_;
    allocateInfo.descriptorSetCount = 1;
    allocateInfo.pSetLayouts = &setLayout_;
    vkCheck(vkAllocateDescriptorSets(device, &allocateInfo, &set_), "vkAllocateDescriptorSets");

    const VkPushConstantRange pushConstants{VK_SHADER_STAGE_FRAGMENT_BIT, 0, kPushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &pushConstants;
    vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_),
            "vkCreatePipelineLayout");
    picturePipeline_ = createFullscreenPipeline(context, compiler, layout_, renderPass, 1,
                                                "window_picture.frag", {}, "window picture");
    fillPipeline_ = createFullscreenPipeline(context, compiler, layout_, renderPass, 1,
                                             "solid_fill.frag", {}, "window fill");
  } catch (...) {
    release();
    throw;
  }
}

WindowPicture::~WindowPicture() {
  release();
}

void WindowPicture::release() {
  const VkDevice device = context_.device();
  if (fillPipeline_) vkDestroyPipeline(device, fillPipeline_, nullptr);
  if (picturePipeline_) vkDestroyPipeline(device, picturePipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);  // frees set_
  if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
  if (sampler_) vkDestroySampler(device, sampler_, nullptr);
  fillPipeline_ = picturePipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
  sampler_ = VK_NULL_HANDLE;
}

void WindowPicture::setPicture(VkImageView view) {
  const VkDescriptorImageInfo image{sampler_, view, VK_IMAGE_LAYOUT_GENERAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

void WindowPicture::drawPicture(VkCommandBuffer commands, VkRect2D area, uint32_t shownWidth,
                                uint32_t shownHeight, uint32_t pictureWidth,
                                uint32_t pictureHeight) const {
  const std::array<float, 4> placement = {
      float(area.offset.x), float(area.offset.y),
      float(shownWidth) / float(pictureWidth) / float(area.extent.width),
      float(shownHeight) / float(pictureHeight) / float(area.extent.height)};
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, picturePipeline_);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                          nullptr);
  vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, kPushConstantBytes,
                     placement.data());
  setDrawArea(commands, area);
  vkCmdDraw(commands, 3, 1, 0, 0);  // fullscreen.vert's triangle over the viewport
}

void WindowPicture::fill(VkCommandBuffer commands, VkRect2D area,
                         const std::array<float, 4>& colour) const {
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, fillPipeline_);
  vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, kPushConstantBytes,
                     colour.data());
  setDrawArea(commands, area);
  vkCmdDraw(commands, 3, 1, 0, 0);
}

}  // namespace render
