// Reading a hit triangle's vertices and material; shared by the hit shaders. Needs the scene
// bindings.

vec3 fetchVec3(uint vertex, uint component) {
  uint base = vertex * VERTEX_FLOATS + component;
  return vec3(vertexFloats[base], vertexFloats[base + 1u], vertexFloats[base + 2u]);
}

vec2 fetchUv(uint vertex) {
  uint base = vertex * VERTEX_FLOATS + 6u;
  return vec2(vertexFloats[base], vertexFloats[base + 1u]);
}

vec2 fetchUv1(uint vertex) {
  uint base = vertex * VERTEX_FLOATS + 12u;
  return vec2(vertexFloats[base], vertexFloats[base + 1u]);
}

vec4 fetchColor(uint vertex) {
  uint base = vertex * VERTEX_FLOATS + 8u;
  return vec4(vertexFloats[base], vertexFloats[base + 1u], vertexFloats[base + 2u],
              vertexFloats[base + 3u]);
}

// The material of triangle `primitive` of an instance (MATERIAL_PER_TRIANGLE: its own).
uint triangleMaterial(uvec4 geometry, uint primitive) {
  uint materialIndex = geometry.z;
  if ((materialIndex & MATERIAL_PER_TRIANGLE) != 0u)
    materialIndex = triangleMaterials[(materialIndex & ~MATERIAL_PER_TRIANGLE) + primitive];
  return materialIndex;
}

// The triangle's three vertex indices, in the shared vertex buffer.
uvec3 triangleVertices(uvec4 geometry, uint primitive) {
  uint firstIndex = geometry.x + 3u * primitive;
  return uvec3(indices[firstIndex], indices[firstIndex + 1u], indices[firstIndex + 2u]) +
         geometry.y;
}

// Material `material`'s texture + 1 of role `role` (0: it has none).
uint textureSlot(uint material, uint role) {
  return materials[material].textureSlots[role >> 2u][role & 3u];
}

// Where role `role` samples, given the point's two UV sets: its set, moved by its transform.
vec2 roleUv(uint material, uint role, vec2 uv0, vec2 uv1) {
  vec3 uv = vec3(((materials[material].kindShading.z >> role) & 1u) != 0u ? uv1 : uv0, 1.0);
  return vec2(dot(materials[material].textureTransforms[2u * role].xyz, uv),
              dot(materials[material].textureTransforms[2u * role + 1u].xyz, uv));
}

// Role `role`'s texel at the point (white when the material has no such texture).
vec4 sampleRole(uint material, uint role, vec2 uv0, vec2 uv1) {
  uint slot = textureSlot(material, role);
  if (slot == 0u) return vec4(1.0);
  return textureLod(textures[nonuniformEXT(slot - 1u)], roleUv(material, role, uv0, uv1), 0.0);
}

// A point of a triangle: its barycentric weights' interpolation of the vertices' UV sets and
// colour.
struct TrianglePoint {
  vec2 uv0;
  vec2 uv1;
  vec4 color;
};

// The second set is read only when one of the material's textures uses it.
TrianglePoint interpolatePoint(uint material, uvec3 corners, vec3 weights) {
  TrianglePoint point;
  point.uv0 = fetchUv(corners.x) * weights.x + fetchUv(corners.y) * weights.y +
              fetchUv(corners.z) * weights.z;
  point.uv1 = point.uv0;
  if (materials[material].kindShading.z != 0u) {
    point.uv1 = fetchUv1(corners.x) * weights.x + fetchUv1(corners.y) * weights.y +
                fetchUv1(corners.z) * weights.z;
  }
  point.color = fetchColor(corners.x) * weights.x + fetchColor(corners.y) * weights.y +
                fetchColor(corners.z) * weights.z;
  return point;
}
