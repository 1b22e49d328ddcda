// Low-discrepancy numbers and light sampling for soft shadows.

// R2 sequence (Roberts' generalised golden ratio) in 32-bit fixed point, so frame counts of
// any size stay exact: each pixel's numbers go on along it from a start of the pixel's own.
// Deterministic in pixel, frame and dimension.
const uint R2_A1 = 3242174889u;  // 0.7548776662... * 2^32
const uint R2_A2 = 2447445413u;  // 0.5698402909... * 2^32
const uint GOLDEN = 2654435769u;  // 0.6180339887... * 2^32

float fixedToUnit(uint value) { return float(value >> 8) * (1.0 / 16777216.0); }

vec3 sequenceFrom(uvec3 start, uint frame) {
  return vec3(fixedToUnit(start.x + frame * R2_A1), fixedToUnit(start.y + frame * R2_A2),
              fixedToUnit(start.z + frame * GOLDEN));
}

// Starts that are the same sequence over the pixel's coordinates: a lattice, which spreads the
// samples of any neighbourhood over the light evenly in all three dimensions at once, so that
// the errors of neighbouring pixels cancel where the denoiser averages them.
uvec3 latticeStart(uvec2 pixel) {
  return uvec3(pixel.x * R2_A1 + pixel.y * R2_A2, pixel.x * R2_A2 + pixel.y * R2_A1 + 0x9E3779B9u,
               (pixel.x * 7919u + pixel.y * 104729u) * GOLDEN);
}

// The probes' numbers, over the probe's sample and probe index.
vec3 sampleNumbers(uvec2 pixel, uint frame) { return sequenceFrom(latticeStart(pixel), frame); }

// An orthonormal basis around a unit vector (branch-free construction).
void basisAround(vec3 n, out vec3 tangent, out vec3 bitangent) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  tangent = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  bitangent = vec3(b, s + n.y * n.y * a, -n.y);
}

// Uniform direction in the cone of half-angle acos(cosMax) around `axis` (solid-angle pdf).
vec3 sampleCone(vec3 axis, float cosMax, vec2 u) {
  float cosTheta = 1.0 - u.x * (1.0 - cosMax);
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  float phi = 6.28318530718 * u.y;
  vec3 tangent, bitangent;
  basisAround(axis, tangent, bitangent);
  return normalize(tangent * (cos(phi) * sinTheta) + bitangent * (sin(phi) * sinTheta) +
                   axis * cosTheta);
}

// A point on the light seen from `position`: direction and distance for a shadow ray.
// Spheres and suns are sampled uniformly in the solid angle they subtend; rectangles and disks
// uniformly over their area.
void sampleLight(GpuLight light, vec3 position, vec2 u, out vec3 direction, out float distance) {
  uint type = uint(light.positionType.w);
  vec3 centre = light.positionType.xyz;
  float radius = light.radianceRadius.w;
  if (type == LIGHT_DIRECTIONAL) {
    float halfAngle = 0.5 * light.extent.z;
    direction = sampleCone(-light.directionEnabled.xyz, cos(halfAngle), u);
    distance = 1.0e30;
    return;
  }
  if (type == LIGHT_SPHERE) {
    vec3 toCentre = centre - position;
    float centreDistance = length(toCentre);
    if (centreDistance <= radius * 1.0001) {  // inside: any direction reaches it at once
      direction = toCentre / max(centreDistance, 1e-20);
      distance = 0.0;
      return;
    }
    vec3 axis = toCentre / centreDistance;
    float sinMax = radius / centreDistance;
    direction = sampleCone(axis, sqrt(max(1.0 - sinMax * sinMax, 0.0)), u);
    // Distance to the sphere's near surface along the sampled direction.
    float along = dot(toCentre, direction);
    float across2 = max(centreDistance * centreDistance - along * along, 0.0);
    distance = along - sqrt(max(radius * radius - across2, 0.0));
    return;
  }
  vec3 normal = light.directionEnabled.xyz;
  vec3 tangent, bitangent;
  basisAround(normal, tangent, bitangent);
  vec3 onLight;
  if (type == LIGHT_RECTANGLE) {
    onLight = centre + tangent * ((u.x - 0.5) * light.extent.x) +
              bitangent * ((u.y - 0.5) * light.extent.y);
  } else {  // disk
    float r = radius * sqrt(u.x);
    float phi = 6.28318530718 * u.y;
    onLight = centre + tangent * (r * cos(phi)) + bitangent * (r * sin(phi));
  }
  vec3 offset = onLight - position;
  distance = length(offset);
  direction = offset / max(distance, 1e-20);
}

bool lightHasExtent(GpuLight light) {
  uint type = uint(light.positionType.w);
  if (type == LIGHT_POINT) return false;
  if (type == LIGHT_DIRECTIONAL) return light.extent.z > 0.0;
  return true;
}
