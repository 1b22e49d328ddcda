// Payloads between the ray-gen loop and the hit/miss stages.
#define PAYLOAD_SURFACE 0
#define PAYLOAD_SHADOW 1
#define MISS_SURFACE 0
#define MISS_SHADOW 1

struct SurfaceHit {
  vec3 shadingNormal;    // world space, unit, normal map applied (not yet facing the viewer)
  float hitT;            // < 0: the ray missed everything
  vec3 geometricNormal;  // world space, unit
  uint material;
  vec3 albedo;           // linear base colour times the colour texture
  uint instance;
};
