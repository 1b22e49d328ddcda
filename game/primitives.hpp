#pragma once
// Built-in meshes. All are centered on the origin, have outward normals, counter-clockwise
// front faces seen from outside, and UVs in [0, 1] that show a texture unmirrored from outside
// ((0, 0) is the image's top-left corner).
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace game::primitives {

// An axis-aligned box with flat faces: 24 vertices, 36 indices. Each face holds the whole
// texture, upright on the sides; on the top, the image's top edge is at -Z.
scene::MeshData box(const glm::vec3& size);

// A UV sphere with smooth normals; `segments` around Y (>= 3), `rings` from pole to pole (>= 2).
// (rings + 1) * (segments + 1) vertices, 6 * segments * (rings - 1) indices.
// u runs once around from +Z towards +X, v from the north pole (0) to the south pole (1).
scene::MeshData sphere(float radius, uint32_t segments = 32, uint32_t rings = 16);

// A single quad facing +Y: `width` along X, `depth` along Z. 4 vertices, 6 indices.
// u runs from 0 to 1 along +X, v from 0 to 1 along +Z.
scene::MeshData plane(float width, float depth);

// A capped cylinder along Y with smooth sides and flat caps.
// 4 * (segments + 1) vertices, 12 * segments indices. Sides: u once around as on the sphere,
// v from the top (0) down; caps: the texture laid flat, as on the box's top and bottom.
scene::MeshData cylinder(float radius, float height, uint32_t segments = 32);

}  // namespace game::primitives
