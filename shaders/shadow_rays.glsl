// Shadow rays and the glass rays that tint them; shared by the camera and probe ray-gen
// shaders. Needs HAS_GLASS and LIGHT_ROUTES defined and the scene bindings.
//
// lavapipe compiles each traceRayEXT call, once functions are inlined, into the whole BVH
// traversal with every hit and miss shader of the pipeline inside it, so a shader takes as
// much longer to compile as it has such calls. Every shadow ray of a ray-gen shader goes
// through the one loop in pathTransmittance, and its callers call it from one place.
#ifndef ALPHA_MASK
#define ALPHA_MASK 0
#endif
// Opaque rays skip any-hit shaders; with alpha-masked materials the alpha test must run.
#if ALPHA_MASK
#define SURFACE_RAY_FLAGS gl_RayFlagsNoneEXT
#else
#define SURFACE_RAY_FLAGS gl_RayFlagsOpaqueEXT
#endif
// A shadow ray's: hitT below 0 where nothing blocked it; where the hit shader ran (a blocker's
// distance wanted), the first caster the ray met (not necessarily the nearest).
layout(location = PAYLOAD_SHADOW) rayPayloadEXT SurfaceHit blocker;
#if HAS_GLASS
layout(location = PAYLOAD_GLASS) rayPayloadEXT GlassPath glass;
#endif

uint raysTraced = 0u;
// What blocks shadow rays: opaque casters and the player's body (not for the player's own
// exposure probes, whose points are on it).
uint shadowCasterMask = MASK_SHADOW_CASTER | MASK_BODY;

// Transmittance of the glass between origin and origin + direction * tMax.
vec3 glassTransmittance(vec3 origin, vec3 direction, float tMax, uint mask) {
#if HAS_GLASS
  glass.opticalDepth = uvec3(0u);
  glass.rememberedCount = 0u;
  traceRayEXT(sceneTlas, gl_RayFlagsSkipClosestHitShaderEXT, mask, 0, 1, MISS_GLASS, origin, 0.0,
              direction, tMax, PAYLOAD_GLASS);
  ++raysTraced;
  return exp2(-vec3(glass.opticalDepth) / OPTICAL_DEPTH_SCALE);
#else
  return vec3(1.0);
#endif
}

// The way a shadow ray takes to its light: straight, one segment, or along a light route
// (light_routes.glsl) unfolded at each mirror face, a segment up to each face and one after.
#if LIGHT_ROUTES
#define SHADOW_PATH_SEGMENTS (MAX_ROUTE_MIRRORS + 1)
#else
#define SHADOW_PATH_SEGMENTS 1
#endif
struct ShadowPath {
  vec3 starts[SHADOW_PATH_SEGMENTS];
  vec3 directions[SHADOW_PATH_SEGMENTS];
  float lengths[SHADOW_PATH_SEGMENTS];
  uint segments;  // 0: nothing to trace
};

ShadowPath straightPath(vec3 origin, vec3 direction, float distance) {
  ShadowPath path;
  path.starts[0] = origin;
  path.directions[0] = direction;
  path.lengths[0] = distance;
  path.segments = 1u;
  return path;
}

// How much of a light gets along `path`: 0 where something opaque is in the way, else the
// transmittance of the glass on every segment. With `findBlocker` the hit shader runs for the
// caster a blocked ray met, and blockerDistance is its distance (else below 0).
vec3 pathTransmittance(ShadowPath path, bool findBlocker, out float blockerDistance) {
  blockerDistance = -1.0;
  vec3 transmittance = vec3(1.0);
  for (uint i = 0u; i < path.segments; ++i) {
    blocker.hitT = 0.0;  // what a blocked ray leaves where the hit shader is skipped
    traceRayEXT(sceneTlas,
                SURFACE_RAY_FLAGS | gl_RayFlagsTerminateOnFirstHitEXT |
                    (findBlocker ? 0u : gl_RayFlagsSkipClosestHitShaderEXT),
                shadowCasterMask, 0, 1, MISS_SURFACE, path.starts[i], 0.0, path.directions[i],
                path.lengths[i], PAYLOAD_SHADOW);
    ++raysTraced;
    if (blocker.hitT >= 0.0) {
      if (findBlocker) blockerDistance = blocker.hitT;
      return vec3(0.0);
    }
    transmittance *= glassTransmittance(path.starts[i], path.directions[i], path.lengths[i],
                                        MASK_GLASS_SHADOW);
    if (all(equal(transmittance, vec3(0.0)))) break;
  }
  return transmittance;
}
