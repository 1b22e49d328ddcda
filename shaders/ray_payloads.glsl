// Payloads between the ray-gen loop and the hit/miss stages.
#define PAYLOAD_SURFACE 0
#define PAYLOAD_SHADOW 1
#define PAYLOAD_GLASS 2
#define PAYLOAD_BLOCKER 3  // a soft shadow ray's, with the hit shader run for the caster it met
#define MISS_SURFACE 0
#define MISS_SHADOW 1
#define MISS_GLASS 2

// Glass optical depth: -log2(transmittance) in units of 1/OPTICAL_DEPTH_SCALE.
#define OPTICAL_DEPTH_SCALE 65536.0
#define MAX_OPTICAL_DEPTH 64.0
#define OPTICAL_DEPTH_CAP 0x40000000u

struct SurfaceHit {
  vec3 shadingNormal;    // world space, unit, normal map applied (not yet facing the viewer)
  float hitT;            // < 0: the ray missed everything
  vec3 geometricNormal;  // world space, unit
  uint material;
  vec3 albedo;           // linear base colour times the colour texture and vertex colour
  uint instance;
  vec3 emissive;         // the material's, times its emissive texture
  float roughness;       // the material's, times its metallic-roughness texture's green
  float metallic;        // the material's, times that texture's blue
  float occlusion;       // what reaches of the ambient light: 1 - strength (1 - texture red)
};

// A ray through an edge shared by two triangles of one surface may report both; hits of the
// same instance at the same distance are one crossing. The last few are remembered to tell.
#define GLASS_REMEMBERED_HITS 8

struct GlassPath {
  uvec3 opticalDepth;  // summed over the front faces crossed
  uint rememberedCount;
  uint rememberedInstance[GLASS_REMEMBERED_HITS];
  float rememberedT[GLASS_REMEMBERED_HITS];
};
