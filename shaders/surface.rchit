#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_EXT_nonuniform_qualifier : require
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "scene_bindings.glsl"
#include "ray_payloads.glsl"
#include "vertex_fetch.glsl"

// Reports where and what the ray hit, with textures applied; the ray-gen shader shades.
layout(location = PAYLOAD_SURFACE) rayPayloadInEXT SurfaceHit hit;
hitAttributeEXT vec2 barycentrics;

// Tangent-space normal map -> object-space normal, with a per-triangle tangent frame from the
// positions and UVs. +Y in the map points towards the top of the image (decreasing v), as in
// glTF.
vec3 applyNormalMap(vec3 normal, vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2,
                    vec2 uv, uint texture) {
  vec3 edge1 = p1 - p0, edge2 = p2 - p0;
  vec2 duv1 = uv1 - uv0, duv2 = uv2 - uv0;
  float determinant = duv1.x * duv2.y - duv2.x * duv1.y;
  float normalLength = length(normal);
  if (abs(determinant) < 1e-12 || normalLength == 0.0) return normal;
  vec3 alongU = (edge1 * duv2.y - edge2 * duv1.y) / determinant;
  vec3 alongV = (edge2 * duv1.x - edge1 * duv2.x) / determinant;
  vec3 n = normal / normalLength;
  vec3 tangent = alongU - n * dot(n, alongU);
  if (dot(tangent, tangent) < 1e-20) return normal;
  tangent = normalize(tangent);
  vec3 up = normalize(cross(n, tangent));
  if (dot(up, -alongV) < 0.0) up = -up;  // mirrored UVs
  vec3 mapped = textureLod(textures[nonuniformEXT(texture)], uv, 0.0).xyz * 2.0 - 1.0;
  return tangent * mapped.x + up * mapped.y + n * mapped.z;
}

void main() {
  uvec4 geometry = instances[gl_InstanceCustomIndexEXT].geometry;
  uvec3 corners = triangleVertices(geometry, uint(gl_PrimitiveID));
  uint v0 = corners.x, v1 = corners.y, v2 = corners.z;
  vec3 weights = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);
  uint materialIndex = triangleMaterial(geometry, uint(gl_PrimitiveID));
  GpuMaterial material = materials[materialIndex];

  vec3 p0 = fetchVec3(v0, 0u), p1 = fetchVec3(v1, 0u), p2 = fetchVec3(v2, 0u);
  vec2 uv0 = fetchUv(v0), uv1 = fetchUv(v1), uv2 = fetchUv(v2);
  vec2 uv = uv0 * weights.x + uv1 * weights.y + uv2 * weights.z;
  vec3 objectGeometric = cross(p1 - p0, p2 - p0);
  vec3 objectShading = fetchVec3(v0, 3u) * weights.x + fetchVec3(v1, 3u) * weights.y +
                       fetchVec3(v2, 3u) * weights.z;
  if (material.kindTextures.z > 0u) {
    objectShading = applyNormalMap(objectShading, p0, p1, p2, uv0, uv1, uv2, uv,
                                   material.kindTextures.z - 1u);
  }
  // Vertex colours (white unless a glTF model gave COLOR_0) multiply the base colour.
  vec3 albedo = material.baseColorSpecular.rgb *
                (fetchColor(v0).rgb * weights.x + fetchColor(v1).rgb * weights.y +
                 fetchColor(v2).rgb * weights.z);
  if (material.kindTextures.y > 0u) {
    albedo *= textureLod(textures[nonuniformEXT(material.kindTextures.y - 1u)], uv, 0.0).rgb;
  }

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
  hit.material = materialIndex;
  hit.albedo = albedo;
  hit.instance = uint(gl_InstanceCustomIndexEXT);
}
