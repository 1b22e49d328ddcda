// Light routed by flat mirrors (GpuLightRoute in shared_types.h): a point lit via a route sees
// the light's mirror image, and the straight ray towards a point on the image, unfolded at
// each face, is the path the light takes. Needs shadow_rays.glsl and sampling.glsl.
layout(set = 0, binding = BINDING_LIGHT_ROUTES, std430) readonly buffer LightRouteBlock {
  LightRoutesHeader lightRoutes;
  GpuLightRoute routes[];
};

// Routes are read from the buffer by index, field by field: a route is 304 bytes, and copying
// whole ones for each pixel and route costs a CPU driver more than the tests themselves.

// Where the ray meets the plane of face `i` of `route`, if it does before `distance`, from the
// reflecting side and within the face's rectangle widened by `margin`.
bool crossesFace(uint route, uint i, vec3 origin, vec3 direction, float distance, float margin,
                 out float t) {
  t = 0.0;
  vec4 plane = routes[route].mirrors[i].plane;
  float facing = dot(direction, plane.xyz);
  if (facing >= 0.0) return false;
  t = (plane.w - dot(plane.xyz, origin)) / facing;
  if (!(t > 0.0 && t < distance)) return false;
  vec3 offset = origin + direction * t - routes[route].mirrors[i].centre.xyz;
  vec4 halfU = routes[route].mirrors[i].halfU;
  vec4 halfV = routes[route].mirrors[i].halfV;
  return abs(dot(offset, halfU.xyz)) <= halfU.w * (halfU.w + margin) &&
         abs(dot(offset, halfV.xyz)) <= halfV.w * (halfV.w + margin);
}

// How far a sampled point on the image light can be from its centre: the ray towards it crosses
// a face at most this far (plus the sun's angle times the distance) from the central ray.
float imageReach(GpuLight image) {
  uint type = uint(image.positionType.w);
  if (type == LIGHT_RECTANGLE) return 0.5 * length(image.extent.xy);
  if (type == LIGHT_SPHERE || type == LIGHT_DISK) return image.radianceRadius.w;
  return 0.0;
}

// Whether a point at `position` is in front of the route's first face: the cheap test that
// rejects most of the scene before anything else is read.
bool facesRoute(uint route, vec3 position) {
  vec4 plane = routes[route].mirrors[0].plane;
  return dot(plane.xyz, position) > plane.w;
}

// Whether the ray towards the image's centre crosses every face of the route, each widened by
// what sampling the light's extent can add: where the route can light a point at all.
bool routeCanReach(uint route, vec3 origin, vec3 direction, float distance) {
  GpuLight image = routes[route].image;
  float reach = imageReach(image);
  float angle = uint(image.positionType.w) == LIGHT_DIRECTIONAL ? 0.5 * image.extent.z : 0.0;
  float travelled = 0.0;
  uint count = routes[route].lightMirrors.y;
  for (uint i = 0u; i < count; ++i) {
    float t;
    if (!crossesFace(route, i, origin, direction, distance,
                     reach + angle * travelled * 1.01 + 1e-6, t))
      return false;
    origin += direction * t;
    direction = reflect(direction, routes[route].mirrors[i].plane.xyz);
    distance -= t;
    travelled += t;
  }
  return true;
}

// What arrives along the route from `origin` towards a point `distance` away on the image
// (unfolded): 0 when the ray misses a face or something opaque is in the way, else the glass
// transmittance of every stretch. The mirrors' tints are the caller's (the route's tint).
vec3 routeTransmittance(uint route, vec3 origin, vec3 direction, float distance) {
  vec3 starts[MAX_ROUTE_MIRRORS + 1];
  vec3 directions[MAX_ROUTE_MIRRORS + 1];
  float lengths[MAX_ROUTE_MIRRORS + 1];
  uint count = routes[route].lightMirrors.y;
  // A directional light's image in a flat mirror is directional too.
  bool directional = isDirectional(routes[route].image);
  // Geometry first, which rejects most points without tracing anything.
  for (uint i = 0u; i < count; ++i) {
    float t;
    if (!crossesFace(route, i, origin, direction, distance, 0.0, t)) return vec3(0.0);
    vec3 normal = routes[route].mirrors[i].plane.xyz;
    starts[i] = origin;
    directions[i] = direction;
    lengths[i] = t * 0.9999;  // stop short of the mirror itself
    vec3 onFace = origin + direction * t;
    float step = max(max(abs(onFace.x), abs(onFace.y)), max(abs(onFace.z), t)) / 65536.0;
    origin = onFace + normal * max(step, 1e-30);
    direction = reflect(direction, normal);
    distance -= t;
  }
  starts[count] = origin;
  directions[count] = direction;
  lengths[count] = distance;
  vec3 transmittance = vec3(1.0);
  for (uint i = 0u; i <= count; ++i) {
    transmittance *= shadowTransmittance(starts[i], directions[i], lengths[i], directional);
    if (all(equal(transmittance, vec3(0.0)))) break;
  }
  return transmittance;
}

// A point on the route's image light seen from `position` (sampleLight with the image's own
// rectangle sides, which mirroring turned).
void sampleRouteLight(uint route, vec3 position, vec2 u, out vec3 direction, out float distance) {
  GpuLight image = routes[route].image;
  if (uint(image.positionType.w) != LIGHT_RECTANGLE) {
    sampleLight(image, position, u, direction, distance);
    return;
  }
  vec3 normal = image.directionEnabled.xyz;
  vec3 tangent = routes[route].imageTangent.xyz;
  vec3 bitangent = cross(normal, tangent);
  vec3 onLight = image.positionType.xyz + tangent * ((u.x - 0.5) * image.extent.x) +
                 bitangent * ((u.y - 0.5) * image.extent.y);
  vec3 offset = onLight - position;
  distance = length(offset);
  direction = offset / max(distance, 1e-20);
}
