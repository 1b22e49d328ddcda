#include "render/acceleration_structure.hpp"

#include <algorithm>
#include <utility>

#include "render/barriers.hpp"
#include "render/bvh_order.hpp"
#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace render {
namespace {

constexpr VkBufferUsageFlags kBuildInputUsage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
constexpr VkBufferUsageFlags kScratchUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

VkAccelerationStructureGeometryKHR triangleGeometry(const TriangleGeometry& mesh) {
  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
  // Opaque unless an instance forces otherwise (glass); a duplicate any-hit call would apply
  // a glass tint twice.
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR | VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
  auto& triangles = geometry.geometry.triangles;
  triangles.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  triangles.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
  triangles.vertexData.deviceAddress = mesh.vertexAddress;
  triangles.vertexStride = mesh.vertexStride;
  triangles.maxVertex = mesh.vertexCount > 0 ? mesh.vertexCount - 1 : 0;
  triangles.indexType = VK_INDEX_TYPE_UINT32;
  triangles.indexData.deviceAddress = mesh.indexAddress;
  return geometry;
}

// Scratch addresses must honour the device's alignment (lavapipe 8, NVIDIA 128).
struct ScratchBuffer {
  Buffer buffer;
  VkDeviceAddress alignedAddress = 0;
};
ScratchBuffer makeScratch(const Context& context, VkDeviceSize size, const std::string& name) {
  const VkDeviceSize alignment = std::max<VkDeviceSize>(
      context.accelerationStructureProperties().minAccelerationStructureScratchOffsetAlignment, 1);
  ScratchBuffer scratch;
  scratch.buffer = Buffer(context, size + alignment, kScratchUsage, MemoryUse::DeviceOnly, name);
  scratch.alignedAddress = alignUp(scratch.buffer.address(), alignment);
  return scratch;
}

VkTransformMatrixKHR toRowMajor3x4(const glm::mat4& objectToWorld) {
  VkTransformMatrixKHR transform{};
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column)
      transform.matrix[row][column] = objectToWorld[column][row];
  return transform;
}

VkAccelerationStructureGeometryKHR instanceGeometry(VkDeviceAddress instances) {
  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.data.deviceAddress = instances;
  return geometry;
}

// Fast to trace, and updatable in place when instances move.
VkAccelerationStructureBuildGeometryInfoKHR topLevelBuildInfo(
    const VkAccelerationStructureGeometryKHR* geometry) {
  VkAccelerationStructureBuildGeometryInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
               VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
  info.geometryCount = 1;
  info.pGeometries = geometry;
  return info;
}

void structureBuildBarrier(VkCommandBuffer commands) {
  memoryBarrier(commands, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                    VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
}

}  // namespace

AccelerationStructure::AccelerationStructure(const Context& context,
                                             VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                                             const std::string& name)
    : context_(&context),
      storage_(context, size,
               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
               MemoryUse::DeviceOnly, name + " storage") {
  VkAccelerationStructureCreateInfoKHR createInfo{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  createInfo.buffer = storage_.handle();
  createInfo.size = size;
  createInfo.type = type;
  vkCheck(
      context.rt().createAccelerationStructure(context.device(), &createInfo, nullptr, &handle_),
      "vkCreateAccelerationStructureKHR");
  context.setName(handle_, VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, name);
  VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  addressInfo.accelerationStructure = handle_;
  address_ = context.rt().getAccelerationStructureAddress(context.device(), &addressInfo);
}

AccelerationStructure::~AccelerationStructure() {
  release();
}

AccelerationStructure::AccelerationStructure(AccelerationStructure&& other) noexcept {
  *this = std::move(other);
}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    storage_ = std::move(other.storage_);
    handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    address_ = std::exchange(other.address_, 0);
  }
  return *this;
}

void AccelerationStructure::release() {
  if (context_ && handle_)
    context_->rt().destroyAccelerationStructure(context_->device(), handle_, nullptr);
  handle_ = VK_NULL_HANDLE;
  storage_ = Buffer();
}

std::vector<AccelerationStructure> buildBottomLevels(const Context& context,
                                                     std::span<const TriangleGeometry> meshes,
                                                     BottomLevelStats* stats) {
  const uint32_t count = static_cast<uint32_t>(meshes.size());
  std::vector<AccelerationStructure> built;
  if (count == 0) return built;
  std::vector<VkAccelerationStructureGeometryKHR> geometries;
  std::vector<VkAccelerationStructureBuildGeometryInfoKHR> buildInfos(count);
  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(count);
  geometries.reserve(count);
  VkDeviceSize scratchTotal = 0;
  std::vector<VkDeviceSize> scratchOffsets(count);
  const VkDeviceSize scratchAlignment = std::max<VkDeviceSize>(
      context.accelerationStructureProperties().minAccelerationStructureScratchOffsetAlignment, 1);
  for (uint32_t i = 0; i < count; ++i) {
    geometries.push_back(triangleGeometry(meshes[i]));
    auto& info = buildInfos[i];
    info.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR;
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                 VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = &geometries.back();
    ranges[i].primitiveCount = meshes[i].triangleCount;

    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    context.rt().getBuildSizes(context.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                               &info, &meshes[i].triangleCount, &sizes);
    built.emplace_back(context, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                       sizes.accelerationStructureSize, "blas " + std::to_string(i));
    info.dstAccelerationStructure = built.back().handle();
    scratchOffsets[i] = scratchTotal;
    scratchTotal += alignUp(sizes.buildScratchSize, scratchAlignment);
    if (stats) stats->builtBytes += sizes.accelerationStructureSize;
  }
  ScratchBuffer scratch = makeScratch(context, scratchTotal, "blas scratch");
  for (uint32_t i = 0; i < count; ++i)
    buildInfos[i].scratchData.deviceAddress = scratch.alignedAddress + scratchOffsets[i];

  VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  queryInfo.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  queryInfo.queryCount = count;
  VkQueryPool queries = VK_NULL_HANDLE;
  vkCheck(vkCreateQueryPool(context.device(), &queryInfo, nullptr, &queries), "vkCreateQueryPool");
  std::vector<VkAccelerationStructureKHR> handles;
  for (const auto& structure : built) handles.push_back(structure.handle());
  std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> rangePointers;
  for (const auto& range : ranges) rangePointers.push_back(&range);

  std::vector<VkDeviceSize> compactedSizes(count);
  try {
    context.submitAndWait([&](VkCommandBuffer commands) {
      vkCmdResetQueryPool(commands, queries, 0, count);
      context.rt().cmdBuild(commands, count, buildInfos.data(), rangePointers.data());
      structureBuildBarrier(commands);
      context.rt().cmdWriteProperties(commands, count, handles.data(),
                                      VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
                                      queries, 0);
    });
    vkCheck(vkGetQueryPoolResults(context.device(), queries, 0, count, count * sizeof(VkDeviceSize),
                                  compactedSizes.data(), sizeof(VkDeviceSize),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
  } catch (...) {
    vkDestroyQueryPool(context.device(), queries, nullptr);
    throw;
  }
  vkDestroyQueryPool(context.device(), queries, nullptr);

  std::vector<AccelerationStructure> compacted;
  for (uint32_t i = 0; i < count; ++i) {
    compacted.emplace_back(context, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                           compactedSizes[i], "blas " + std::to_string(i) + " compacted");
    if (stats) stats->compactedBytes += compactedSizes[i];
  }
  context.submitAndWait([&](VkCommandBuffer commands) {
    for (uint32_t i = 0; i < count; ++i) {
      VkCopyAccelerationStructureInfoKHR copy{
          VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
      copy.src = built[i].handle();
      copy.dst = compacted[i].handle();
      copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
      context.rt().cmdCopy(commands, &copy);
    }
  });
  return compacted;
}

TopLevel::TopLevel(const Context& context, std::span<const TlasInstance> instances)
    : context_(&context), instanceCount_(static_cast<uint32_t>(instances.size())) {
  const VkDeviceSize instanceBytes =
      std::max<VkDeviceSize>(instances.size(), 1) * sizeof(VkAccelerationStructureInstanceKHR);
  instanceBuffer_ =
      Buffer(context, instanceBytes, kBuildInputUsage, MemoryUse::Upload, "tlas instances");
  writeInstances(instances);

  const VkAccelerationStructureGeometryKHR geometry = instanceGeometry(instanceBuffer_.address());
  const VkAccelerationStructureBuildGeometryInfoKHR info = topLevelBuildInfo(&geometry);
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  context.rt().getBuildSizes(context.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                             &info, &instanceCount_, &sizes);
  structure_ = AccelerationStructure(context, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                     sizes.accelerationStructureSize, "tlas");
  ScratchBuffer scratch = makeScratch(
      context, std::max(sizes.buildScratchSize, sizes.updateScratchSize), "tlas scratch");
  scratch_ = std::move(scratch.buffer);
  scratchAddress_ = scratch.alignedAddress;
  context.submitAndWait([&](VkCommandBuffer commands) { record(commands, false); });
}

void TopLevel::setVisible(uint32_t instance, bool visible) {
  instances_[instance].mask = visible ? masks_[instance] : 0;
}

void TopLevel::writeInstances(std::span<const TlasInstance> instances) {
  instances_.clear();
  masks_.clear();
  std::vector<LeafBounds> bounds;
  for (const TlasInstance& instance : instances) {
    bounds.push_back(instance.bounds);
    masks_.push_back(uint8_t(instance.mask & 0xFF));
    VkAccelerationStructureInstanceKHR record{};
    record.transform = toRowMajor3x4(instance.objectToWorld);
    record.instanceCustomIndex = instance.customIndex & 0xFFFFFF;
    record.mask = instance.mask & 0xFF;
    record.instanceShaderBindingTableRecordOffset = instance.hitGroup;
    record.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR | instance.flags;
    record.accelerationStructureReference = instance.blas->address();
    instances_.push_back(record);
  }
  order_ = halvingOrder(bounds);
  upload();
}

void TopLevel::upload() {
  ordered_.clear();
  for (const uint32_t instance : order_) ordered_.push_back(instances_[instance]);
  if (!ordered_.empty())
    instanceBuffer_.write(ordered_.data(), ordered_.size() * sizeof(ordered_[0]));
}

void TopLevel::recordUpdate(VkCommandBuffer commands, std::span<const glm::mat4> objectToWorld) {
  if (objectToWorld.size() != instances_.size())
    throw RenderError("TopLevel::recordUpdate: instance count changed");
  for (size_t i = 0; i < instances_.size(); ++i)
    instances_[i].transform = toRowMajor3x4(objectToWorld[i]);
  upload();
  record(commands, true);
}

void TopLevel::record(VkCommandBuffer commands, bool update) {
  const VkAccelerationStructureGeometryKHR geometry = instanceGeometry(instanceBuffer_.address());
  VkAccelerationStructureBuildGeometryInfoKHR info = topLevelBuildInfo(&geometry);
  info.mode = update ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR
                     : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.srcAccelerationStructure = update ? structure_.handle() : VK_NULL_HANDLE;
  info.dstAccelerationStructure = structure_.handle();
  info.scratchData.deviceAddress = scratchAddress_;
  VkAccelerationStructureBuildRangeInfoKHR range{};
  range.primitiveCount = instanceCount_;
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  context_->rt().cmdBuild(commands, 1, &info, &ranges);
}

namespace {

std::vector<TlasInstance> membersOf(std::span<const TlasInstance> sceneInstances,
                                    std::span<const uint32_t> members) {
  std::vector<TlasInstance> chosen;
  chosen.reserve(members.size());
  for (const uint32_t member : members) chosen.push_back(sceneInstances[member]);
  return chosen;
}

}  // namespace

TopLevelSubset::TopLevelSubset(const Context& context, std::span<const TlasInstance> sceneInstances,
                               std::vector<uint32_t> members)
    : members_(std::move(members)), level_(context, membersOf(sceneInstances, members_)) {}

void TopLevelSubset::recordUpdate(VkCommandBuffer commands,
                                  std::span<const glm::mat4> sceneObjectToWorld) {
  std::vector<glm::mat4> transforms;
  transforms.reserve(members_.size());
  for (const uint32_t member : members_) transforms.push_back(sceneObjectToWorld[member]);
  level_.recordUpdate(commands, transforms);
}

void TopLevelSubset::setVisible(uint32_t instance, bool visible) {
  const auto member = std::find(members_.begin(), members_.end(), instance);
  if (member != members_.end()) level_.setVisible(uint32_t(member - members_.begin()), visible);
}

}  // namespace render
