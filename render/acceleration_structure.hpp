#pragma once
// Bottom-level structures (one per mesh, built once, compacted) and top-level structures over
// instances, all of them or some (built once, then updated in place when instances move).
#include <span>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "render/buffer.hpp"
#include "render/bvh_order.hpp"

namespace render {

class Context;

class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  AccelerationStructure(const Context& context, VkAccelerationStructureTypeKHR type,
                        VkDeviceSize size, const std::string& name);
  ~AccelerationStructure();
  AccelerationStructure(AccelerationStructure&& other) noexcept;
  AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;
  AccelerationStructure(const AccelerationStructure&) = delete;
  AccelerationStructure& operator=(const AccelerationStructure&) = delete;

  VkAccelerationStructureKHR handle() const { return handle_; }
  VkDeviceAddress address() const { return address_; }

 private:
  void release();

  const Context* context_ = nullptr;
  Buffer storage_;
  VkAccelerationStructureKHR handle_ = VK_NULL_HANDLE;
  VkDeviceAddress address_ = 0;
};

struct TriangleGeometry {
  VkDeviceAddress vertexAddress = 0;  // first vertex of this mesh; position is the first vec3
  VkDeviceSize vertexStride = 0;
  uint32_t vertexCount = 0;
  VkDeviceAddress indexAddress = 0;  // uint32 indices, relative to the first vertex
  uint32_t triangleCount = 0;
};

struct BottomLevelStats {
  VkDeviceSize builtBytes = 0;
  VkDeviceSize compactedBytes = 0;
};

// Builds all meshes' structures in one submission, then compacts them.
std::vector<AccelerationStructure> buildBottomLevels(const Context& context,
                                                     std::span<const TriangleGeometry> meshes,
                                                     BottomLevelStats* stats = nullptr);

struct TlasInstance {
  const AccelerationStructure* blas = nullptr;
  glm::mat4 objectToWorld{1.0f};
  uint32_t customIndex = 0;              // gl_InstanceCustomIndexEXT
  uint32_t mask = 0xFF;                  // which rays see it (cull mask bits)
  uint32_t hitGroup = 0;                 // SBT record offset: which hit group its hits run
  VkGeometryInstanceFlagsKHR flags = 0;  // e.g. FORCE_OPAQUE / FORCE_NO_OPAQUE
  LeafBounds bounds;                     // world-space, for the instances' order
};

class TopLevel {
 public:
  TopLevel(const Context& context, std::span<const TlasInstance> instances);

  // Writes new transforms and records an in-place update (the structure's topology stays).
  // The caller makes sure the GPU no longer reads the previous frame's instances.
  void recordUpdate(VkCommandBuffer commands, std::span<const glm::mat4> objectToWorld);

  // Mask 0 (no ray sees it) or the instance's own mask again; the next recordUpdate applies it.
  void setVisible(uint32_t instance, bool visible);

  const AccelerationStructure& structure() const { return structure_; }
  uint32_t instanceCount() const { return instanceCount_; }

 private:
  void writeInstances(std::span<const TlasInstance> instances);
  void record(VkCommandBuffer commands, bool update);
  void upload();  // instances_ to the instance buffer, in order_

  const Context* context_;
  uint32_t instanceCount_ = 0;
  std::vector<VkAccelerationStructureInstanceKHR> instances_;
  // The structure's instance list in an order whose halvings split space (bvh_order.hpp): its
  // entry k is instances_[order_[k]].
  std::vector<uint32_t> order_;
  std::vector<VkAccelerationStructureInstanceKHR> ordered_;  // what upload() writes
  std::vector<uint8_t> masks_;  // each instance's own mask, for when it is shown again
  Buffer instanceBuffer_;
  Buffer scratch_;
  VkDeviceAddress scratchAddress_ = 0;  // aligned for the device
  AccelerationStructure structure_;
};

// A top level over some of the scene's instances, for rays that see only those: its entry k is
// the scene's instance members[k].
class TopLevelSubset {
 public:
  TopLevelSubset(const Context& context, std::span<const TlasInstance> sceneInstances,
                 std::vector<uint32_t> members);

  // As TopLevel::recordUpdate, from the transforms of all the scene's instances.
  void recordUpdate(VkCommandBuffer commands, std::span<const glm::mat4> sceneObjectToWorld);
  // As TopLevel::setVisible, for the scene's instance `instance` (nothing if not a member).
  void setVisible(uint32_t instance, bool visible);

  const AccelerationStructure& structure() const { return level_.structure(); }

 private:
  std::vector<uint32_t> members_;
  TopLevel level_;
};

}  // namespace render
