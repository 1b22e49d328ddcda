#pragma once
// A ray tracing pipeline built from a list of shader groups, and its shader binding table.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/buffer.hpp"
#include "render/shader_binding_table.hpp"

namespace render {

class Context;

struct ShaderCode {
  std::string name;  // e.g. "raygen.rgen"; for debug names and pipeline descriptions
  std::vector<uint32_t> spirv;
};

struct HitGroup {
  std::string name;
  ShaderCode closestHit;  // empty spirv: none
  ShaderCode anyHit;      // empty spirv: none
};

// Groups in SBT order: the raygen shader, the miss shaders (index = trace's missIndex), then
// the hit groups (index = instance SBT offset).
struct RayTracingProgram {
  ShaderCode raygen;
  std::vector<ShaderCode> misses;
  std::vector<HitGroup> hitGroups;
  uint32_t recursionDepth = 1;  // how deep the shaders nest traceRayEXT calls
  ShaderCode probeRaygen;       // a second ray-gen, for exposure probes; empty spirv: none
};

class RayTracingPipeline {
 public:
  // The recursion depth is checked against the device's limit here, the one place that
  // knows both.
  RayTracingPipeline(const Context& context, VkPipelineLayout layout,
                     const RayTracingProgram& program);
  ~RayTracingPipeline();
  RayTracingPipeline(const RayTracingPipeline&) = delete;
  RayTracingPipeline& operator=(const RayTracingPipeline&) = delete;

  VkPipeline handle() const { return pipeline_; }
  void recordTrace(VkCommandBuffer commands, uint32_t width, uint32_t height) const;
  // Launches the probe ray-gen (the program must have one) with the same miss and hit groups.
  void recordProbeTrace(VkCommandBuffer commands, uint32_t width, uint32_t height) const;
  bool hasProbeRaygen() const { return layout_.probeRaygen.size != 0; }
  const SbtLayout& sbtLayout() const { return layout_; }

 private:
  const Context& context_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  Buffer sbt_;
  SbtLayout layout_;
  VkStridedDeviceAddressRegionKHR raygenRegion_{}, missRegion_{}, hitRegion_{}, callableRegion_{};
  VkStridedDeviceAddressRegionKHR probeRaygenRegion_{};
};

VkShaderModule createShaderModule(const Context& context, const std::vector<uint32_t>& spirv,
                                  const std::string& name);

}  // namespace render
