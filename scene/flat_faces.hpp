#pragma once
// The flat faces of a mesh, for routing light by mirrors: triangles grouped by oriented plane,
// each group described by its bounding rectangle in the plane. Box and plane meshes give exact
// rectangles; a curved mesh (more planes than a box has) gives none.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace scene {

struct FlatFace {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit, the side it reflects towards
  glm::vec3 centre{0.0f};              // of the bounding rectangle, on the plane
  glm::vec3 halfU{0.0f};               // half the rectangle along its first side
  glm::vec3 halfV{0.0f};               // half along the second
};

// More oriented planes than this and a mesh counts as curved.
inline constexpr size_t kMostFlatFaces = 6;

// Faces smaller than this share of the largest (a thin mirror's edges) are left out. A mesh of
// one plane (a quad) reflects on both sides; a mesh of several is a solid whose faces reflect
// outwards.
inline std::vector<FlatFace> flatFaces(const MeshData& mesh) {
  struct Group {
    glm::vec3 normal;
    float offset;
    float area = 0.0f;
    glm::vec3 firstEdge{0.0f};
    std::vector<glm::vec3> points;
  };
  std::vector<Group> groups;
  float extent = 0.0f;
  for (const Vertex& vertex : mesh.vertices)
    extent = std::max({extent, std::abs(vertex.position.x), std::abs(vertex.position.y),
                       std::abs(vertex.position.z)});
  const float offsetTolerance = 1e-4f * std::max(extent, 1e-3f);
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float twiceArea = glm::length(cross);
    if (!(twiceArea > 0.0f)) continue;
    const glm::vec3 normal = cross / twiceArea;
    const float offset = glm::dot(normal, a);
    auto same = [&](const Group& group) {
      return glm::dot(group.normal, normal) > 0.9999f &&
             std::abs(group.offset - offset) <= offsetTolerance;
    };
    auto found = std::find_if(groups.begin(), groups.end(), same);
    if (found == groups.end()) {
      if (groups.size() == kMostFlatFaces) return {};  // curved
      // The shortest edge: of a rectangle's triangles, a side and not the diagonal.
      glm::vec3 edge = b - a;
      for (const glm::vec3& other : {c - b, a - c})
        if (glm::dot(other, other) > 0.0f && glm::dot(other, other) < glm::dot(edge, edge))
          edge = other;
      groups.push_back({normal, offset, 0.0f, glm::normalize(edge), {}});
      found = groups.end() - 1;
    }
    found->area += 0.5f * twiceArea;
    found->points.insert(found->points.end(), {a, b, c});
  }
  float largest = 0.0f;
  for (const Group& group : groups) largest = std::max(largest, group.area);
  std::vector<FlatFace> faces;
  for (const Group& group : groups) {
    if (group.area < 0.1f * largest) continue;
    const glm::vec3 u = group.firstEdge;
    const glm::vec3 v = glm::cross(group.normal, u);
    glm::vec2 low(INFINITY), high(-INFINITY);
    for (const glm::vec3& point : group.points) {
      const glm::vec2 along(glm::dot(point, u), glm::dot(point, v));
      low = glm::min(low, along);
      high = glm::max(high, along);
    }
    const glm::vec2 middle = 0.5f * (low + high), half = 0.5f * (high - low);
    FlatFace face;
    face.normal = group.normal;
    face.centre = group.normal * group.offset + u * middle.x + v * middle.y;
    face.halfU = u * half.x;
    face.halfV = v * half.y;
    faces.push_back(face);
  }
  if (groups.size() == 1 && !faces.empty()) {
    FlatFace back = faces.front();
    back.normal = -back.normal;
    faces.push_back(back);
  }
  return faces;
}

}  // namespace scene
