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
