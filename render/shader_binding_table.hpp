#pragma once
// Where each group's handle sits in the shader binding table. Computed from the device's
// properties (lavapipe: handle 32, alignment 16, base 32; NVIDIA: 32/32/64), never hard-coded.
#include <cstdint>

namespace render {

struct SbtRegion {
  uint64_t offset = 0;  // from the table's (base-aligned) start
  uint64_t stride = 0;
  uint64_t size = 0;
};

struct SbtLayout {
  SbtRegion raygen;  // exactly one record; its size equals its stride
  SbtRegion miss;
  SbtRegion hit;
  SbtRegion probeRaygen;  // the exposure probes' ray-gen, after the hit groups (size 0: none)
  uint64_t totalSize = 0;
};

struct SbtProperties {
  uint32_t handleSize = 0;
  uint32_t handleAlignment = 0;
  uint32_t baseAlignment = 0;
};

SbtLayout computeSbtLayout(const SbtProperties& properties, uint32_t missCount, uint32_t hitCount,
                           bool probeRaygen = false);

}  // namespace render
