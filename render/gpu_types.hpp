#pragma once
// The C++ view of shaders/shared_types.h, with its layout checked.
#include <cstddef>

#include "shaders/shared_types.h"

namespace render::gpu {
static_assert(sizeof(FrameUniforms) == 20 * 16, "FrameUniforms must match the GLSL block");
static_assert(offsetof(FrameUniforms, sizeFrameLights) == 7 * 16);
static_assert(offsetof(FrameUniforms, topLevels) == 18 * 16);
static_assert(sizeof(GpuInstance) == 64);
static_assert(sizeof(GpuMaterial) == 128 + 32 * TEXTURE_ROLES);
static_assert(offsetof(GpuMaterial, kindShading) == 64);
static_assert(offsetof(GpuMaterial, textureTransforms) == 128);
static_assert(offsetof(GpuMaterial, emissiveRoughness) == 16);
static_assert(sizeof(GpuLight) == 80);
static_assert(offsetof(GpuLight, radianceRadius) == 32);
static_assert(sizeof(FrameCounters) == 16);
static_assert(sizeof(ProbeSetup) == 16 * (1 + MAX_FOCUS_PROBES + MAX_EXPOSURE_PROBES));
static_assert(sizeof(ProbePoint) == 32);
static_assert(sizeof(GpuRouteMirror) == 64);
static_assert(sizeof(GpuLightRoute) == 80 + 48 + 64 * MAX_ROUTE_MIRRORS);
static_assert(offsetof(GpuLightRoute, mirrors) == 128);
static_assert(sizeof(LightRoutesHeader) == 16);
static_assert(sizeof(ProbeResults) == 4 * (MAX_FOCUS_PROBES + MAX_EXPOSURE_PROBES));
}  // namespace render::gpu

namespace render::gpu {
// An instance's TLAS visibility mask: glass is seen only by glass rays, everything else by
// surface rays; shadow casters also by the matching shadow rays (those towards directional
// lights only, for a caster of directional shadows alone).
inline constexpr uint32_t instanceMask(bool glass, bool castsShadow, bool playerBody = false,
                                       bool shadowsDirectionalOnly = false) {
  if (playerBody) return MASK_BODY;
  if (glass) {
    if (!castsShadow) return MASK_GLASS;
    return MASK_GLASS |
           (shadowsDirectionalOnly ? MASK_GLASS_SHADOW_DIRECTIONAL : MASK_GLASS_SHADOW);
  }
  if (!castsShadow) return MASK_VISIBLE;
  return MASK_VISIBLE | (shadowsDirectionalOnly ? MASK_SHADOW_DIRECTIONAL : MASK_SHADOW_CASTER);
}

// The masks of a shadow ray and of the glass ray that follows it (shadow_rays.glsl has the same):
// towards a directional light they also meet the casters of directional shadows alone.
inline constexpr uint32_t shadowRayMask(bool directional) {
  return MASK_SHADOW_CASTER | (directional ? MASK_SHADOW_DIRECTIONAL : 0u);
}
inline constexpr uint32_t glassShadowRayMask(bool directional) {
  return MASK_GLASS_SHADOW | (directional ? MASK_GLASS_SHADOW_DIRECTIONAL : 0u);
}
}  // namespace render::gpu
