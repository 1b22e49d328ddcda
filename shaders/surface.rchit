#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "scene_bindings.glsl"
#include "ray_payloads.glsl"

// Reports where and what the ray hit; the ray-gen shader does the shading.
layout(location = PAYLOAD_SURFACE) rayPayloadInEXT SurfaceHit hit;
hitAttributeEXT vec2 barycentrics;

vec3 fetchVec3(uint vertex, uint component) {
  uint base = vertex * VERTEX_FLOATS + component;
  return vec3(vertexFloats[base], vertexFloats[base + 1], vertexFloats[base + 2]);
}

void main() {
  uvec4 geometry = instances[gl_InstanceCustomIndexEXT].geometry;
  uint firstIndex = geometry.x + 3u * uint(gl_PrimitiveID);
  uint v0 = indices[firstIndex] + geometry.y;
  uint v1 = indices[firstIndex + 1u] + geometry.y;
  uint v2 = indices[firstIndex + 2u] + geometry.y;
  vec3 weights = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);

  vec3 p0 = fetchVec3(v0, 0u);
  vec3 objectGeometric = cross(fetchVec3(v1, 0u) - p0, fetchVec3(v2, 0u) - p0);
  vec3 objectShading = fetchVec3(v0, 3u) * weights.x + fetchVec3(v1, 3u) * weights.y +
                       fetchVec3(v2, 3u) * weights.z;
  // Normals transform by the inverse transpose: row-vector times world-to-object.
  vec3 geometric = vec3(objectGeometric * gl_WorldToObjectEXT);
  vec3 shading = vec3(objectShading * gl_WorldToObjectEXT);
  float geometricLength = length(geometric);
  float shadingLength = length(shading);
  // Degenerate triangles or zero normals fall back to whichever normal exists.
  geometric = geometricLength > 0.0 ? geometric / geometricLength : -gl_WorldRayDirectionEXT;
  shading = shadingLength > 0.0 ? shading / shadingLength : geometric;

  hit.shadingNormal = shading;
  hit.hitT = gl_HitTEXT;
  hit.geometricNormal = geometric;
  hit.material = geometry.z;
}
