#include "render/light_routes.hpp"

#include <algorithm>
#include <cmath>

namespace render {
namespace {

struct PartialRoute {
  gpu::GpuLightRoute route{};
  uint32_t lastFace = 0;  // the face nearest the lit point so far
};

float signedDistance(const MirrorFace& face, const glm::vec3& point) {
  return glm::dot(face.normal, point - face.centre);
}

// The largest signed distance of any corner of `face` from `plane`'s plane.
float farthestCorner(const MirrorFace& face, const MirrorFace& plane) {
  return signedDistance(plane, face.centre) + std::abs(glm::dot(plane.normal, face.halfU)) +
         std::abs(glm::dot(plane.normal, face.halfV));
}

// Whether some of the (image) light is on the face's reflecting side.
bool lightInFront(const gpu::GpuLight& light, const MirrorFace& face) {
  const auto type = static_cast<uint32_t>(light.positionType.w);
  if (type == LIGHT_DIRECTIONAL)
    return glm::dot(glm::vec3(light.directionEnabled), face.normal) < 0.0f;
  float reach = light.radianceRadius.w;
  if (type == LIGHT_RECTANGLE) reach = 0.5f * glm::length(glm::vec2(light.extent));
  return signedDistance(face, glm::vec3(light.positionType)) > -reach;
}

// Whether some point of `next` can see the (image) light through `through`'s rectangle: the
// corners of `next` projected towards the light onto `through`'s plane must not all fall on one
// side outside it (widened by the light's extent). Corners whose way to the light does not
// cross the plane leave the answer yes.
bool seesLightThrough(const MirrorFace& next, const MirrorFace& through,
                      const gpu::GpuLight& light) {
  const auto type = static_cast<uint32_t>(light.positionType.w);
  float reach = light.radianceRadius.w;
  if (type == LIGHT_RECTANGLE) reach = 0.5f * glm::length(glm::vec2(light.extent));
  if (type == LIGHT_DIRECTIONAL) reach = 0.0f;
  const glm::vec3 u = glm::normalize(through.halfU), v = glm::normalize(through.halfV);
  const glm::vec2 half(glm::length(through.halfU) + reach, glm::length(through.halfV) + reach);
  glm::vec2 low(INFINITY), high(-INFINITY);
  for (const float su : {-1.0f, 1.0f}) {
    for (const float sv : {-1.0f, 1.0f}) {
      const glm::vec3 corner = next.centre + su * next.halfU + sv * next.halfV;
      const glm::vec3 towards = type == LIGHT_DIRECTIONAL ? -glm::vec3(light.directionEnabled)
                                                          : glm::vec3(light.positionType) - corner;
      const float along = glm::dot(through.normal, towards);
      if (along == 0.0f) return true;
      const float t = -signedDistance(through, corner) / along;
      if (!(t > 0.0f) || (type != LIGHT_DIRECTIONAL && !(t < 1.0f))) return true;
      const glm::vec3 onPlane = corner + towards * t - through.centre;
      const glm::vec2 at(glm::dot(onPlane, u), glm::dot(onPlane, v));
      low = glm::min(low, at);
      high = glm::max(high, at);
    }
  }
  return high.x >= -half.x && low.x <= half.x && high.y >= -half.y && low.y <= half.y;
}

glm::vec3 reflectPoint(const MirrorFace& face, const glm::vec3& point) {
  return point - 2.0f * signedDistance(face, point) * face.normal;
}

glm::vec3 reflectDirection(const MirrorFace& face, const glm::vec3& direction) {
  return direction - 2.0f * glm::dot(direction, face.normal) * face.normal;
}

gpu::GpuRouteMirror gpuMirror(const MirrorFace& face) {
  const float offset = glm::dot(face.normal, face.centre);
  return {glm::vec4(face.normal, offset), glm::vec4(face.centre, 0.0f),
          glm::vec4(face.halfU, glm::length(face.halfU)),
          glm::vec4(face.halfV, glm::length(face.halfV))};
}

// The route extended by one face nearer the lit point: the image mirrored in it, the face put
// first (the shaders walk from the lit point).
PartialRoute extended(const PartialRoute& partial, const MirrorFace& face, uint32_t faceIndex) {
  PartialRoute next = partial;
  gpu::GpuLightRoute& route = next.route;
  gpu::GpuLight& image = route.image;
  image.positionType =
      glm::vec4(reflectPoint(face, glm::vec3(image.positionType)), image.positionType.w);
  image.directionEnabled = glm::vec4(reflectDirection(face, glm::vec3(image.directionEnabled)),
                                     image.directionEnabled.w);
  image.radianceRadius =
      glm::vec4(glm::vec3(image.radianceRadius) * face.tint, image.radianceRadius.w);
  route.imageTangent = glm::vec4(reflectDirection(face, glm::vec3(route.imageTangent)), 0.0f);
  route.tint = glm::vec4(glm::vec3(route.tint) * face.tint, 0.0f);
  const uint32_t count = route.lightMirrors.y;
  for (uint32_t i = count; i > 0; --i) route.mirrors[i] = route.mirrors[i - 1];
  route.mirrors[0] = gpuMirror(face);
  route.lightMirrors.y = count + 1;
  next.lastFace = faceIndex;
  return next;
}

}  // namespace

glm::vec3 rectangleTangent(const glm::vec3& n) {
  // As basisAround in shaders/sampling.glsl.
  const float s = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (s + n.z);
  return {1.0f + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x};
}

std::vector<gpu::GpuLightRoute> findLightRoutes(std::span<const MirrorFace> faces,
                                                std::span<const gpu::GpuLight> lights,
                                                uint32_t maxMirrors) {
  std::vector<gpu::GpuLightRoute> routes;
  std::vector<PartialRoute> generation;
  for (uint32_t light = 0; light < lights.size(); ++light) {
    if (lights[light].directionEnabled.w == 0.0f) continue;  // switched off: no slot taken
    PartialRoute start;
    start.route.image = lights[light];
    // Only a light seen has motion (the upscaler's); an image's stays zero, so a light's
    // motion alone does not change the routes.
    start.route.image.previousPosition = glm::vec4(0.0f);
    start.route.lightMirrors = glm::uvec4(light, 0, 0, 0);
    start.route.tint = glm::vec4(1.0f);
    start.route.imageTangent =
        glm::vec4(rectangleTangent(glm::vec3(lights[light].directionEnabled)), 0.0f);
    generation.push_back(start);
  }
  const uint32_t longest = std::min<uint32_t>(maxMirrors, MAX_ROUTE_MIRRORS);
  for (uint32_t length = 1; length <= longest && !generation.empty(); ++length) {
    std::vector<PartialRoute> next;
    for (const PartialRoute& partial : generation) {
      for (uint32_t f = 0; f < faces.size(); ++f) {
        const MirrorFace& face = faces[f];
        if (!lightInFront(partial.route.image, face)) continue;
        if (length > 1) {
          const MirrorFace& previous = faces[partial.lastFace];
          if (f == partial.lastFace || farthestCorner(face, previous) <= 0.0f ||
              farthestCorner(previous, face) <= 0.0f ||
              !seesLightThrough(face, previous, partial.route.image))
            continue;
        }
        next.push_back(extended(partial, face, f));
        routes.push_back(next.back().route);
        if (routes.size() == MAX_LIGHT_ROUTES) return routes;
      }
    }
    generation = std::move(next);
  }
  return routes;
}

}  // namespace render
