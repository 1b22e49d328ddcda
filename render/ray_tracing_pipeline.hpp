#pragma once
// The ray tracing pipeline (raygen, surface miss, shadow miss, one triangle hit group) and its
// shader binding table.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/buffer.hpp"
#include "render/shader_binding_table.hpp"

namespace render {

class Context;

struct RayTracingShaders {
  std::vector<uint32_t> raygen;
  std::vector<uint32_t> surfaceMiss;
  std::vector<uint32_t> shadowMiss;
  std::vector<uint32_t> surfaceClosestHit;
};

class RayTracingPipeline {
 public:
  // `recursionDepth` is how deep the shaders trace (1: only ray-gen traces); it is checked
  // against the device's limit here, the one place that knows both.
  RayTracingPipeline(const Context& context, VkPipelineLayout layout,
                     const RayTracingShaders& shaders, uint32_t recursionDepth);
  ~RayTracingPipeline();
  RayTracingPipeline(const RayTracingPipeline&) = delete;
  RayTracingPipeline& operator=(const RayTracingPipeline&) = delete;

  VkPipeline handle() const { return pipeline_; }
  void recordTrace(VkCommandBuffer commands, uint32_t width, uint32_t height) const;
  const SbtLayout& sbtLayout() const { return layout_; }

 private:
  const Context& context_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  Buffer sbt_;
  SbtLayout layout_;
  VkStridedDeviceAddressRegionKHR raygenRegion_{}, missRegion_{}, hitRegion_{}, callableRegion_{};
};

VkShaderModule createShaderModule(const Context& context, const std::vector<uint32_t>& spirv,
                                  const char* name);

}  // namespace render
