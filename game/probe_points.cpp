#include "game/probe_points.hpp"

#include <algorithm>
#include <cmath>

namespace game {
namespace {

constexpr float kLift = 0.001f;  // off the surface, so a point does not shadow itself

// Unit direction from `point` towards the light (the light's centre, or against a sun).
glm::vec3 towardsLight(const scene::LightDesc& light, const glm::vec3& point) {
  if (light.type == scene::LightType::Directional) {
    const float length = glm::length(light.direction);
    return length > 0.0f ? -light.direction / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  const glm::vec3 offset = light.position - point;
  const float length = glm::length(offset);
  return length > 0.0f ? offset / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

std::vector<SurfaceSample> surfaceSamples(const scene::MeshData& mesh, uint32_t count) {
  std::vector<double> cumulativeArea;
  double total = 0.0;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
    total += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    cumulativeArea.push_back(total);
  }
  std::vector<SurfaceSample> samples;
  if (total <= 0.0) return samples;
  constexpr double kR2a = 0.7548776662466927, kR2b = 0.5698402909980532;
  for (uint32_t s = 0; s < count; ++s) {
    const double target = (double(s) + 0.5) / double(count) * total;
    const size_t triangle =
        size_t(std::lower_bound(cumulativeArea.begin(), cumulativeArea.end(), target) -
               cumulativeArea.begin());
    const size_t base = std::min(triangle, cumulativeArea.size() - 1) * 3;
    const glm::vec3 a = mesh.vertices[mesh.indices[base]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[base + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[base + 2]].position;
    double u = std::fmod(0.5 + kR2a * s, 1.0), v = std::fmod(0.5 + kR2b * s, 1.0);
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;  // fold into the triangle
    const glm::vec3 normal = glm::cross(b - a, c - a);
    samples.push_back({a + float(u) * (b - a) + float(v) * (c - a), glm::normalize(normal)});
  }
  return samples;
}

std::vector<scene::ExposurePoint> sensorExposurePoints(const std::vector<SurfaceSample>& samples,
                                                       const glm::mat4& objectToWorld,
                                                       const scene::LightDesc& light) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(objectToWorld)));
  std::vector<scene::ExposurePoint> points;
  for (const SurfaceSample& sample : samples) {
    const glm::vec3 position = glm::vec3(objectToWorld * glm::vec4(sample.position, 1.0f));
    const glm::vec3 normal = glm::normalize(normalMatrix * sample.normal);
    if (glm::dot(normal, towardsLight(light, position)) <= 0.0f) continue;
    points.push_back({position + normal * kLift, normal, true});
  }
  return points;
}

std::vector<scene::ExposurePoint> playerExposurePoints(const glm::vec3& feet,
                                                       const scene::LightDesc& light) {
  const glm::vec3 centre = feet + glm::vec3(0.0f, 0.9f, 0.0f);
  glm::vec3 toLight = towardsLight(light, centre);
  // Across the line to the light: horizontal, unless the light is straight above or below.
  glm::vec3 across = glm::cross(toLight, glm::vec3(0.0f, 1.0f, 0.0f));
  across = glm::length(across) > 1e-4f ? glm::normalize(across) : glm::vec3(1.0f, 0.0f, 0.0f);
  std::vector<scene::ExposurePoint> points;
  for (int height = 0; height < 16; ++height) {
    for (int place = 0; place < 4; ++place) {
      const float y = 0.05f + 1.7f * (float(height) + 0.5f) / 16.0f;
      const float side = -0.225f + 0.15f * float(place);
      points.push_back({feet + glm::vec3(0.0f, y, 0.0f) + across * side, toLight, false});
    }
  }
  return points;
}

}  // namespace game
