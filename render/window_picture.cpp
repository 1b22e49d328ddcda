#include "render/window_picture.hpp"

#include "render/context.hpp"
#include "render/ray_tracing_pipeline.hpp"
#include "render/shader_compiler.hpp"
#include "render/vulkan_error.hpp"

namespace render {
namespace {

// Both fragment shaders' push constants: window_picture.frag's placement (its origin and
// texture coordinates per pixel) or solid_fill.frag's colour.
constexpr uint32_t kPushConstantBytes = 4 * sizeof(float);

void setArea(VkCommandBuffer commands, VkRect2D area) {
  const VkViewport viewport{float(area.offset.x),
                            float(area.offset.y),
                            float(area.extent.width),
                            float(area.extent.height),
                            0.0f,
                            1.0f};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &area);
}

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
    picturePipeline_ =
        createPipeline(compiler, renderPass, "window_picture.frag", "window picture");
    fillPipeline_ = createPipeline(compiler, renderPass, "solid_fill.frag", "window fill");
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

VkPipeline WindowPicture::createPipeline(ShaderCompiler& compiler, VkRenderPass renderPass,
                                         const char* fragmentShader, const char* name) const {
  const VkDevice device = context_.device();
  const std::array<VkShaderModule, 2> modules = {
      createShaderModule(context_, compiler.compile("fullscreen.vert").spirv, "fullscreen"),
      createShaderModule(context_, compiler.compile(fragmentShader).spirv, name)};
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  for (size_t i = 0; i < stages.size(); ++i) {
    stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewportState{
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewportState.viewportCount = 1;  // both set with each draw
  viewportState.scissorCount = 1;
  const std::array<VkDynamicState, 2> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                       VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = uint32_t(dynamicStates.size());
  dynamic.pDynamicStates = dynamicStates.data();
  VkPipelineRasterizationStateCreateInfo rasterization{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rasterization.polygonMode = VK_POLYGON_MODE_FILL;
  rasterization.cullMode = VK_CULL_MODE_NONE;
  rasterization.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState blendAttachment{};  // no blending: written as it is
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewportState;
  info.pRasterizationState = &rasterization;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  info.renderPass = renderPass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result =
      vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  for (VkShaderModule module : modules) vkDestroyShaderModule(device, module, nullptr);
  vkCheck(result, "vkCreateGraphicsPipelines");
  context_.setName(pipeline, VK_OBJECT_TYPE_PIPELINE, name);
  return pipeline;
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
  setArea(commands, area);
  vkCmdDraw(commands, 3, 1, 0, 0);  // fullscreen.vert's triangle over the viewport
}

void WindowPicture::fill(VkCommandBuffer commands, VkRect2D area,
                         const std::array<float, 4>& colour) const {
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, fillPipeline_);
  vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, kPushConstantBytes,
                     colour.data());
  setArea(commands, area);
  vkCmdDraw(commands, 3, 1, 0, 0);
}

}  // namespace render
