#include "render/ray_tracing_pipeline.hpp"

#include <string>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {

VkShaderModule createShaderModule(const Context& context, const std::vector<uint32_t>& spirv,
                                  const std::string& name) {
  VkShaderModuleCreateInfo createInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  createInfo.codeSize = spirv.size() * sizeof(uint32_t);
  createInfo.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vkCheck(vkCreateShaderModule(context.device(), &createInfo, nullptr, &module),
          "vkCreateShaderModule");
  context.setName(module, VK_OBJECT_TYPE_SHADER_MODULE, name);
  return module;
}

namespace {

// Stages and groups as Vulkan wants them; owns the modules until the pipeline exists.
struct StageList {
  const Context& context;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  std::vector<VkShaderModule> modules;

  uint32_t add(const ShaderCode& code, VkShaderStageFlagBits stage) {
    if (code.spirv.empty()) return VK_SHADER_UNUSED_KHR;
    modules.push_back(createShaderModule(context, code.spirv, code.name));
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage = stage;
    info.module = modules.back();
    info.pName = "main";
    stages.push_back(info);
    return static_cast<uint32_t>(stages.size() - 1);
  }
  ~StageList() {
    for (VkShaderModule module : modules) vkDestroyShaderModule(context.device(), module, nullptr);
  }
};

VkRayTracingShaderGroupCreateInfoKHR generalGroup(uint32_t stage) {
  VkRayTracingShaderGroupCreateInfoKHR group{
      VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
  group.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
  group.generalShader = stage;
  group.closestHitShader = VK_SHADER_UNUSED_KHR;
  group.anyHitShader = VK_SHADER_UNUSED_KHR;
  group.intersectionShader = VK_SHADER_UNUSED_KHR;
  return group;
}

}  // namespace

RayTracingPipeline::RayTracingPipeline(const Context& context, VkPipelineLayout layout,
                                       const RayTracingProgram& program)
    : context_(context) {
  const auto& properties = context.rayTracingProperties();
  if (program.recursionDepth < 1 || program.recursionDepth > properties.maxRayRecursionDepth) {
    throw RenderError("the pipeline needs ray recursion depth " +
                      std::to_string(program.recursionDepth) + " but " + context.deviceInfo().name +
                      " allows 1 to " + std::to_string(properties.maxRayRecursionDepth));
  }
  StageList stages{context, {}, {}};
  std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
  groups.push_back(generalGroup(stages.add(program.raygen, VK_SHADER_STAGE_RAYGEN_BIT_KHR)));
  for (const ShaderCode& miss : program.misses)
    groups.push_back(generalGroup(stages.add(miss, VK_SHADER_STAGE_MISS_BIT_KHR)));
  for (const HitGroup& hitGroup : program.hitGroups) {
    VkRayTracingShaderGroupCreateInfoKHR group = generalGroup(VK_SHADER_UNUSED_KHR);
    group.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR;
    group.closestHitShader = stages.add(hitGroup.closestHit, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR);
    group.anyHitShader = stages.add(hitGroup.anyHit, VK_SHADER_STAGE_ANY_HIT_BIT_KHR);
    groups.push_back(group);
  }
  const bool probeRaygen = !program.probeRaygen.spirv.empty();
  if (probeRaygen)
    groups.push_back(generalGroup(stages.add(program.probeRaygen, VK_SHADER_STAGE_RAYGEN_BIT_KHR)));

  VkRayTracingPipelineCreateInfoKHR createInfo{
      VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  createInfo.stageCount = static_cast<uint32_t>(stages.stages.size());
  createInfo.pStages = stages.stages.data();
  createInfo.groupCount = static_cast<uint32_t>(groups.size());
  createInfo.pGroups = groups.data();
  createInfo.maxPipelineRayRecursionDepth = program.recursionDepth;
  createInfo.layout = layout;
  vkCheck(context.rt().createPipelines(context.device(), VK_NULL_HANDLE, VK_NULL_HANDLE, 1,
                                       &createInfo, nullptr, &pipeline_),
          "vkCreateRayTracingPipelinesKHR");
  context.setName(pipeline_, VK_OBJECT_TYPE_PIPELINE, "ray tracing pipeline");
  // A constructor that throws gets no destructor call: the pipeline must not outlive a failure
  // further down (a lost device, exhausted memory for the binding table).
  struct DestroyPipelineOnThrow {
    VkDevice device;
    VkPipeline* pipeline;
    ~DestroyPipelineOnThrow() {
      if (pipeline) vkDestroyPipeline(device, *pipeline, nullptr);
    }
  } destroyPipelineOnThrow{context.device(), &pipeline_};

  const uint32_t missCount = static_cast<uint32_t>(program.misses.size());
  const uint32_t hitCount = static_cast<uint32_t>(program.hitGroups.size());
  const SbtProperties sbtProperties{properties.shaderGroupHandleSize,
                                    properties.shaderGroupHandleAlignment,
                                    properties.shaderGroupBaseAlignment};
  layout_ = computeSbtLayout(sbtProperties, missCount, hitCount, probeRaygen);
  const uint32_t handleSize = properties.shaderGroupHandleSize;
  std::vector<uint8_t> handles(groups.size() * handleSize);
  vkCheck(context.rt().getGroupHandles(context.device(), pipeline_, 0,
                                       static_cast<uint32_t>(groups.size()), handles.size(),
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
  writeHandle(0, layout_.raygen.offset);
  for (uint32_t i = 0; i < missCount; ++i)
    writeHandle(1 + i, layout_.miss.offset + i * layout_.miss.stride);
  for (uint32_t i = 0; i < hitCount; ++i)
    writeHandle(1 + missCount + i, layout_.hit.offset + i * layout_.hit.stride);
  if (probeRaygen) {
    writeHandle(1 + missCount + hitCount, layout_.probeRaygen.offset);
    probeRaygenRegion_ = {base + layout_.probeRaygen.offset, layout_.probeRaygen.stride,
                          layout_.probeRaygen.size};
  }
  raygenRegion_ = {base + layout_.raygen.offset, layout_.raygen.stride, layout_.raygen.size};
  missRegion_ = {base + layout_.miss.offset, layout_.miss.stride, layout_.miss.size};
  hitRegion_ = {base + layout_.hit.offset, layout_.hit.stride, layout_.hit.size};
  destroyPipelineOnThrow.pipeline = nullptr;
}

RayTracingPipeline::~RayTracingPipeline() {
  if (pipeline_) vkDestroyPipeline(context_.device(), pipeline_, nullptr);
}

void RayTracingPipeline::recordTrace(VkCommandBuffer commands, uint32_t width,
                                     uint32_t height) const {
  context_.rt().cmdTraceRays(commands, &raygenRegion_, &missRegion_, &hitRegion_, &callableRegion_,
                             width, height, 1);
}

void RayTracingPipeline::recordProbeTrace(VkCommandBuffer commands, uint32_t width,
                                          uint32_t height) const {
  if (!hasProbeRaygen()) throw RenderError("recordProbeTrace: the pipeline has no probe ray-gen");
  context_.rt().cmdTraceRays(commands, &probeRaygenRegion_, &missRegion_, &hitRegion_,
                             &callableRegion_, width, height, 1);
}

}  // namespace render
