#pragma once
// Where exposure probes trace from: sample points on a sensor's surface, or on the player.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/probes.hpp"
#include "scene/scene_desc.hpp"

namespace game {

struct SurfaceSample {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // the triangle's face normal
};

// `count` points spread over a mesh's surface in proportion to triangle area (stratified on
// the cumulative area, R2 points inside each triangle): deterministic, in the mesh's space.
std::vector<SurfaceSample> surfaceSamples(const scene::MeshData& mesh, uint32_t count);

// The samples placed by `objectToWorld` that face the light's centre (a sun: its direction),
// lifted 1 mm off the surface. A sensor's exposure is the lit share of its side facing the
// light; a sensor facing away has no points and reads 0.
std::vector<scene::ExposurePoint> sensorExposurePoints(const std::vector<SurfaceSample>& samples,
                                                       const glm::mat4& objectToWorld,
                                                       const scene::LightDesc& light);

// 64 points over the player's body (a 0.3 m radius, 1.8 m capsule standing on `feet`): 16
// heights by 4 places across the line to the light; two-sided, so the player's exposure is
// the share of the body the light can see.
std::vector<scene::ExposurePoint> playerExposurePoints(const glm::vec3& feet,
                                                       const scene::LightDesc& light);

}  // namespace game
