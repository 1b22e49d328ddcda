#include "render/ray_tracing_pipeline.hpp"

#include <array>
#include <string>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {

VkShaderModule createShaderModule(const Context& context, const std::vector<uint32_t>& spirv,
                                  const char* name) {
  VkShaderModuleCreateInfo createInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  createInfo.codeSize = spirv.size() * sizeof(uint32_t);
  createInfo.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vkCheck(vkCreateShaderModule(context.device(), &createInfo, nullptr, &module),
          "vkCreateShaderModule");
  context.setName(module, VK_OBJECT_TYPE_SHADER_MODULE, name);
  return module;
}

RayTracingPipeline::RayTracingPipeline(const Context& context, VkPipelineLayout layout,
                                       const RayTracingShaders& shaders, uint32_t recursionDepth)
    : context_(context) {
  const auto& properties = context.rayTracingProperties();
  if (recursionDepth > properties.maxRayRecursionDepth) {
    throw RenderError("the level needs ray recursion depth " + std::to_string(recursionDepth) +
                      " but " + context.deviceInfo().name + " allows " +
                      std::to_string(properties.maxRayRecursionDepth));
  }
  enum Stage : uint32_t { Raygen, SurfaceMiss, ShadowMiss, SurfaceHit, StageCount };
  const std::array<const std::vector<uint32_t>*, StageCount> code = {
      &shaders.raygen, &shaders.surfaceMiss, &shaders.shadowMiss, &shaders.surfaceClosestHit};
  const std::array<VkShaderStageFlagBits, StageCount> stageBits = {
      VK_SHADER_STAGE_RAYGEN_BIT_KHR, VK_SHADER_STAGE_MISS_BIT_KHR, VK_SHADER_STAGE_MISS_BIT_KHR,
      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR};
  const std::array<const char*, StageCount> names = {"raygen", "surface miss", "shadow miss",
                                                     "surface closest hit"};
  std::array<VkPipelineShaderStageCreateInfo, StageCount> stages{};
  std::array<VkShaderModule, StageCount> modules{};
  for (uint32_t i = 0; i < StageCount; ++i) {
    modules[i] = createShaderModule(context, *code[i], names[i]);
    stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[i].stage = stageBits[i];
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  // Group order is the SBT order: raygen | surface miss, shadow miss | surface hit.
  std::array<VkRayTracingShaderGroupCreateInfoKHR, StageCount> groups{};
  for (uint32_t i = 0; i < StageCount; ++i) {
    groups[i] = {VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
    groups[i].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
    groups[i].generalShader = i;
    groups[i].closestHitShader = VK_SHADER_UNUSED_KHR;
    groups[i].anyHitShader = VK_SHADER_UNUSED_KHR;
    groups[i].intersectionShader = VK_SHADER_UNUSED_KHR;
  }
  groups[SurfaceHit].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR;
  groups[SurfaceHit].generalShader = VK_SHADER_UNUSED_KHR;
  groups[SurfaceHit].closestHitShader = SurfaceHit;

  VkRayTracingPipelineCreateInfoKHR createInfo{
      VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  createInfo.stageCount = StageCount;
  createInfo.pStages = stages.data();
  createInfo.groupCount = StageCount;
  createInfo.pGroups = groups.data();
  createInfo.maxPipelineRayRecursionDepth = recursionDepth;
  createInfo.layout = layout;
  VkResult result = context.rt().createPipelines(context.device(), VK_NULL_HANDLE, VK_NULL_HANDLE,
                                                 1, &createInfo, nullptr, &pipeline_);
  for (VkShaderModule module : modules) vkDestroyShaderModule(context.device(), module, nullptr);
  vkCheck(result, "vkCreateRayTracingPipelinesKHR");
  context.setName(pipeline_, VK_OBJECT_TYPE_PIPELINE, "ray tracing pipeline");

  const SbtProperties sbtProperties{properties.shaderGroupHandleSize,
                                    properties.shaderGroupHandleAlignment,
                                    properties.shaderGroupBaseAlignment};
  layout_ = computeSbtLayout(sbtProperties, 2, 1);
  const uint32_t handleSize = properties.shaderGroupHandleSize;
  std::vector<uint8_t> handles(static_cast<size_t>(StageCount) * handleSize);
  vkCheck(context.rt().getGroupHandles(context.device(), pipeline_, 0, StageCount, handles.size(),
                                       handles.data()),
          "vkGetRayTracingShaderGroupHandlesKHR");
  // Over-allocate so the table's start can be aligned to the base alignment.
  const VkDeviceSize baseAlignment = properties.shaderGroupBaseAlignment;
  sbt_ = Buffer(
      context, layout_.totalSize + baseAlignment,
      VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      MemoryUse::Upload, "shader binding table");
  const VkDeviceAddress base = alignUp(sbt_.address(), baseAlignment);
  const VkDeviceSize baseOffset = base - sbt_.address();
  auto writeHandle = [&](uint32_t group, uint64_t offset) {
    sbt_.write(handles.data() + static_cast<size_t>(group) * handleSize, handleSize,
               baseOffset + offset);
  };
  writeHandle(Raygen, layout_.raygen.offset);
  writeHandle(SurfaceMiss, layout_.miss.offset);
  writeHandle(ShadowMiss, layout_.miss.offset + layout_.miss.stride);
  writeHandle(SurfaceHit, layout_.hit.offset);
  raygenRegion_ = {base + layout_.raygen.offset, layout_.raygen.stride, layout_.raygen.size};
  missRegion_ = {base + layout_.miss.offset, layout_.miss.stride, layout_.miss.size};
  hitRegion_ = {base + layout_.hit.offset, layout_.hit.stride, layout_.hit.size};
}

RayTracingPipeline::~RayTracingPipeline() {
  if (pipeline_) vkDestroyPipeline(context_.device(), pipeline_, nullptr);
}

void RayTracingPipeline::recordTrace(VkCommandBuffer commands, uint32_t width,
                                     uint32_t height) const {
  context_.rt().cmdTraceRays(commands, &raygenRegion_, &missRegion_, &hitRegion_, &callableRegion_,
                             width, height, 1);
}

}  // namespace render
