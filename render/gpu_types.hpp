#pragma once
// The C++ view of shaders/shared_types.h, with its layout checked.
#include <cstddef>

#include "shaders/shared_types.h"

namespace render::gpu {
static_assert(sizeof(FrameUniforms) == 14 * 16, "FrameUniforms must match the GLSL block");
static_assert(offsetof(FrameUniforms, sizeFrameLights) == 7 * 16);
static_assert(sizeof(GpuInstance) == 64);
static_assert(sizeof(GpuMaterial) == 80);
static_assert(offsetof(GpuMaterial, kindTextures) == 64);
static_assert(offsetof(GpuMaterial, emissiveRoughness) == 16);
static_assert(sizeof(GpuLight) == 64);
static_assert(offsetof(GpuLight, radianceRadius) == 32);
static_assert(sizeof(FrameCounters) == 16);
}  // namespace render::gpu
