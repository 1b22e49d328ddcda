#include "render/fullscreen_pipeline.hpp"

#include <array>
#include <vector>

#include "render/context.hpp"
#include "render/ray_tracing_pipeline.hpp"
#include "render/vulkan_error.hpp"

namespace render {

VkPipeline createFullscreenPipeline(const Context& context, ShaderCompiler& compiler,
                                    VkPipelineLayout layout, VkRenderPass renderPass,
                                    uint32_t colourAttachments, const std::string& fragmentShader,
                                    const ShaderDefines& defines, const std::string& name) {
  const VkDevice device = context.device();
  // Both compiled before either module is made, so that nothing is left when one fails.
  const std::vector<uint32_t> vertexCode = compiler.compile("fullscreen.vert").spirv;
  const std::vector<uint32_t> fragmentCode = compiler.compile(fragmentShader, defines).spirv;
  std::array<VkShaderModule, 2> modules{};
  modules[0] = createShaderModule(context, vertexCode, "fullscreen");
  try {
    modules[1] = createShaderModule(context, fragmentCode, name);
  } catch (...) {
    vkDestroyShaderModule(device, modules[0], nullptr);
    throw;
  }
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
  viewportState.viewportCount = 1;  // both set with each draw: setDrawArea
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
  VkPipelineColorBlendAttachmentState written{};  // no blending: written as computed
  written.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  const std::vector<VkPipelineColorBlendAttachmentState> blendAttachments(colourAttachments,
                                                                          written);
  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = colourAttachments;
  blend.pAttachments = blendAttachments.data();
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
  info.layout = layout;
  info.renderPass = renderPass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result =
      vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  for (VkShaderModule module : modules) vkDestroyShaderModule(device, module, nullptr);
  vkCheck(result, "vkCreateGraphicsPipelines");
  context.setName(pipeline, VK_OBJECT_TYPE_PIPELINE, name);
  return pipeline;
}

void setDrawArea(VkCommandBuffer commands, VkRect2D area) {
  const VkViewport viewport{float(area.offset.x),
                            float(area.offset.y),
                            float(area.extent.width),
                            float(area.extent.height),
                            0.0f,
                            1.0f};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &area);
}

}  // namespace render
