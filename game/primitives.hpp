#pragma once
// Built-in meshes. All are centered on the origin, have outward normals and counter-clockwise
// front faces seen from outside.
#include <cstdint>

#include <glm/glm.hpp>

#include "render/scene_desc.hpp"

namespace game::primitives {

// An axis-aligned box with flat faces: 24 vertices, 36 indices.
render::MeshData box(const glm::vec3& size);

// A UV sphere with smooth normals; `segments` around Y (>= 3), `rings` from pole to pole (>= 2).
// (rings + 1) * (segments + 1) vertices, 6 * segments * (rings - 1) indices.
render::MeshData sphere(float radius, uint32_t segments = 32, uint32_t rings = 16);

// A single quad facing +Y: `width` along X, `depth` along Z. 4 vertices, 6 indices.
render::MeshData plane(float width, float depth);

// A capped cylinder along Y with smooth sides and flat caps.
// 4 * (segments + 1) vertices, 12 * segments indices.
render::MeshData cylinder(float radius, float height, uint32_t segments = 32);

}  // namespace game::primitives
