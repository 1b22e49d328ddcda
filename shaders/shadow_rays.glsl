// Shadow rays and the glass rays that tint them; shared by the camera and probe ray-gen
// shaders. Needs HAS_GLASS defined and the scene bindings.
#ifndef ALPHA_MASK
#define ALPHA_MASK 0
#endif
// Opaque rays skip any-hit shaders; with alpha-masked materials the alpha test must run.
#if ALPHA_MASK
#define SURFACE_RAY_FLAGS gl_RayFlagsNoneEXT
#else
#define SURFACE_RAY_FLAGS gl_RayFlagsOpaqueEXT
#endif
layout(location = PAYLOAD_SHADOW) rayPayloadEXT float visibility;
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
  traceRayEXT(glassTlas, gl_RayFlagsSkipClosestHitShaderEXT, mask, 0, 1, MISS_GLASS, origin, 0.0,
              direction, tMax, PAYLOAD_GLASS);
  ++raysTraced;
  return exp2(-vec3(glass.opticalDepth) / OPTICAL_DEPTH_SCALE);
#else
  return vec3(1.0);
#endif
}

// Shadow rays towards a directional light also meet the casters of directional shadows alone
// ("casts_shadow": "directional": a roof or dome that keeps the sun out of an interior); the
// rays towards the lamps inside need not test them.
bool isDirectional(GpuLight light) { return uint(light.positionType.w) == LIGHT_DIRECTIONAL; }

uint shadowRayMask(bool directional) {
  return shadowCasterMask | (directional ? MASK_SHADOW_DIRECTIONAL : 0u);
}

uint glassShadowRayMask(bool directional) {
  return MASK_GLASS_SHADOW | (directional ? MASK_GLASS_SHADOW_DIRECTIONAL : 0u);
}

// How much of a light gets from `origin` along `toLight`: 0 behind an opaque caster, else the
// transmittance of the glass in between. `directional`: the light is (isDirectional).
vec3 shadowTransmittance(vec3 origin, vec3 toLight, float distanceToLight, bool directional) {
  visibility = 0.0;
  traceRayEXT(sceneTlas,
              SURFACE_RAY_FLAGS | gl_RayFlagsTerminateOnFirstHitEXT |
                  gl_RayFlagsSkipClosestHitShaderEXT,
              shadowRayMask(directional), 0, 1, MISS_SHADOW, origin, 0.0, toLight,
              distanceToLight, PAYLOAD_SHADOW);
  ++raysTraced;
  if (visibility == 0.0) return vec3(0.0);
  return glassTransmittance(origin, toLight, distanceToLight, glassShadowRayMask(directional));
}
