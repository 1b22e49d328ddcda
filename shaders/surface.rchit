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
                    vec2 uv, uint texture, float scale) {
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
  mapped.xy *= scale;
  return tangent * mapped.x + up * mapped.y + n * mapped.z;
}

void main() {
  uvec4 geometry = instances[gl_InstanceCustomIndexEXT].geometry;
  uvec3 corners = triangleVertices(geometry, uint(gl_PrimitiveID));
  uint v0 = corners.x, v1 = corners.y, v2 = corners.z;
  vec3 weights = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);
  uint materialIndex = triangleMaterial(geometry, uint(gl_PrimitiveID));
  uint material = materialIndex;

  vec3 p0 = fetchVec3(v0, 0u), p1 = fetchVec3(v1, 0u), p2 = fetchVec3(v2, 0u);
  TrianglePoint point = interpolatePoint(material, corners, weights);
  vec3 objectGeometric = cross(p1 - p0, p2 - p0);
  vec3 objectShading = fetchVec3(v0, 3u) * weights.x + fetchVec3(v1, 3u) * weights.y +
                       fetchVec3(v2, 3u) * weights.z;
  uint normalMap = textureSlot(material, TEXTURE_NORMAL);
  if (normalMap > 0u) {
    // The tangent frame follows the normal map's own UVs (its set and transform).
    vec2 uv0 = roleUv(material, TEXTURE_NORMAL, fetchUv(v0), fetchUv1(v0));
    vec2 uv1 = roleUv(material, TEXTURE_NORMAL, fetchUv(v1), fetchUv1(v1));
    vec2 uv2 = roleUv(material, TEXTURE_NORMAL, fetchUv(v2), fetchUv1(v2));
    objectShading = applyNormalMap(objectShading, p0, p1, p2, uv0, uv1, uv2,
                                   roleUv(material, TEXTURE_NORMAL, point.uv0, point.uv1),
                                   normalMap - 1u, materials[material].textureFactors.y);
  }
  // Vertex colours (white unless a glTF model gave COLOR_0) multiply the base colour.
  vec3 albedo = materials[material].baseColorSpecular.rgb * point.color.rgb *
                sampleRole(material, TEXTURE_BASE_COLOR, point.uv0, point.uv1).rgb;
  vec3 emissive = materials[material].emissiveRoughness.rgb;
  float roughness = materials[material].emissiveRoughness.a;
  float metallic = materials[material].mirrorTint.a;
  float occlusion = 1.0;
  if (textureSlot(material, TEXTURE_EMISSIVE) > 0u)
    emissive *= sampleRole(material, TEXTURE_EMISSIVE, point.uv0, point.uv1).rgb;
  if (textureSlot(material, TEXTURE_METALLIC_ROUGHNESS) > 0u) {
    vec4 texel = sampleRole(material, TEXTURE_METALLIC_ROUGHNESS, point.uv0, point.uv1);
    roughness *= texel.g;
    metallic *= texel.b;
  }
  if (textureSlot(material, TEXTURE_OCCLUSION) > 0u) {
    float texel = sampleRole(material, TEXTURE_OCCLUSION, point.uv0, point.uv1).r;
    occlusion = 1.0 + materials[material].textureFactors.z * (texel - 1.0);
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
  hit.emissive = emissive;
  hit.roughness = roughness;
  hit.metallic = metallic;
  hit.occlusion = occlusion;
}
