#pragma once
// Light routed by flat mirrors: which sequences of mirror faces each light's light can take,
// and the light's mirror image through each (render/renderer.cpp uploads them every frame).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/gpu_types.hpp"

namespace render {

// A mirror's flat face in render space, with the mirror's reflectance times tint.
struct MirrorFace {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit, the reflecting side
  glm::vec3 centre{0.0f};
  glm::vec3 halfU{0.0f}, halfV{0.0f};  // half the rectangle's sides
  glm::vec3 tint{1.0f};
};

// The routes of every light that is on via up to `maxMirrors` faces (at most MAX_ROUTE_MIRRORS),
// shortest first, then in light and face order, at most MAX_LIGHT_ROUTES. A route is kept when each
// step can happen somewhere on the faces: the light (or its image so far) in front of the next
// face, consecutive faces each partly in front of the other, and some of the next face seeing the
// light through the previous one's rectangle.
std::vector<gpu::GpuLightRoute> findLightRoutes(std::span<const MirrorFace> faces,
                                                std::span<const gpu::GpuLight> lights,
                                                uint32_t maxMirrors);

// The first side of a rectangle light (the tangent the shaders build around its normal).
glm::vec3 rectangleTangent(const glm::vec3& normal);

}  // namespace render
