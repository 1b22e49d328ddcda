#pragma once
// Camera-relative render space: world coordinates minus the camera's position, taken in double
// on the CPU. Floats near the camera keep their full precision wherever the level lies (at
// 1e5 m a world float is only good to 7.8 mm, and ray offsets scaled to it are metres long).
// The TLAS, lights and probe points are in render space; the camera sits at its origin.
#include <cmath>

#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace render {

// The camera's view in render space: it sits at the origin looking along `forward`; `right`
// and `up` span the image plane at distance 1 (scaled by the field of view and the aspect), so
// a pixel's ray is forward + ndc.x * right - ndc.y * up.
struct CameraBasis {
  glm::vec3 forward, right, up;
};

inline CameraBasis cameraBasis(const scene::CameraDesc& camera, float aspect) {
  const float yaw = glm::radians(camera.yawDegrees);
  const float pitch = glm::radians(camera.pitchDegrees);
  const glm::vec3 forward(-std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                          -std::cos(yaw) * std::cos(pitch));
  glm::vec3 right = glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f));
  // Looking straight up or down: keep the yaw's right vector.
  right = glm::length(right) > 1e-6f ? glm::normalize(right)
                                     : glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw));
  const glm::vec3 up = glm::cross(right, forward);
  const float tanHalf = std::tan(glm::radians(camera.verticalFovDegrees) * 0.5f);
  return {forward, right * tanHalf * aspect, up * tanHalf};
}

inline glm::vec3 toRenderSpace(const glm::vec3& worldPoint, const glm::dvec3& origin) {
  return glm::vec3(glm::dvec3(worldPoint) - origin);
}

// The same placement with its translation made relative to `origin`.
inline glm::mat4 toRenderSpace(const glm::mat4& objectToWorld, const glm::dvec3& origin) {
  glm::mat4 result = objectToWorld;
  result[3] = glm::vec4(toRenderSpace(glm::vec3(objectToWorld[3]), origin), objectToWorld[3].w);
  return result;
}

// Where a point of render space (around `origin`) on an instance was one frame ago, as a
// transform of render space: previous object-to-world times current world-to-object, moved to
// `origin`. Identity exactly when the instance did not move.
inline glm::mat4 motionInRenderSpace(const glm::mat4& previousObjectToWorld,
                                     const glm::mat4& currentObjectToWorld,
                                     const glm::dvec3& origin) {
  if (previousObjectToWorld == currentObjectToWorld) return glm::mat4(1.0f);
  glm::dmat4 toWorld(1.0), toRender(1.0);
  toWorld[3] = glm::dvec4(origin, 1.0);
  toRender[3] = glm::dvec4(-origin, 1.0);
  return glm::mat4(toRender * glm::dmat4(previousObjectToWorld) *
                   glm::inverse(glm::dmat4(currentObjectToWorld)) * toWorld);
}

}  // namespace render
