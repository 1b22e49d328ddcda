#include "render/shader_binding_table.hpp"

#include <stdexcept>

namespace render {
namespace {
uint64_t alignTo(uint64_t value, uint64_t alignment) {
  return (value + alignment - 1) / alignment * alignment;
}
}  // namespace

SbtLayout computeSbtLayout(const SbtProperties& properties, uint32_t missCount, uint32_t hitCount,
                           bool probeRaygen) {
  if (properties.handleSize == 0 || properties.handleAlignment == 0 ||
      properties.baseAlignment == 0) {
    throw std::invalid_argument("shader binding table properties must be non-zero");
  }
  const uint64_t recordStride = alignTo(properties.handleSize, properties.handleAlignment);
  SbtLayout layout;
  // The raygen stride must equal its size; aligning it to the base keeps the next region aligned.
  layout.raygen.stride = alignTo(properties.handleSize, properties.baseAlignment);
  layout.raygen.size = layout.raygen.stride;
  layout.raygen.offset = 0;
  layout.miss.offset = alignTo(layout.raygen.offset + layout.raygen.size, properties.baseAlignment);
  layout.miss.stride = recordStride;
  layout.miss.size = alignTo(recordStride * missCount, properties.baseAlignment);
  layout.hit.offset = alignTo(layout.miss.offset + layout.miss.size, properties.baseAlignment);
  layout.hit.stride = recordStride;
  layout.hit.size = alignTo(recordStride * hitCount, properties.baseAlignment);
  layout.totalSize = layout.hit.offset + layout.hit.size;
  if (probeRaygen) {
    layout.probeRaygen.offset = alignTo(layout.totalSize, properties.baseAlignment);
    layout.probeRaygen.stride = layout.raygen.stride;
    layout.probeRaygen.size = layout.raygen.size;
    layout.totalSize = layout.probeRaygen.offset + layout.probeRaygen.size;
  }
  return layout;
}

}  // namespace render
