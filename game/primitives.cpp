#include "game/primitives.hpp"

#include <cmath>
#include <numbers>

namespace game::primitives {

namespace {

uint32_t nextIndex(const scene::MeshData& mesh) {
  return static_cast<uint32_t>(mesh.vertices.size());
}

void addTriangle(scene::MeshData& mesh, uint32_t a, uint32_t b, uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// One flat quad; `right` x `up` must equal `normal` so the corners run counter-clockwise.
// The whole texture covers it, upright and unmirrored when seen from the front: image rows run
// top to bottom, so v grows against `up`.
void addQuad(scene::MeshData& mesh, const glm::vec3& center, const glm::vec3& right,
             const glm::vec3& up, const glm::vec3& normal) {
  const uint32_t first = nextIndex(mesh);
  mesh.vertices.push_back({center - right - up, normal, {0.0f, 1.0f}});
  mesh.vertices.push_back({center + right - up, normal, {1.0f, 1.0f}});
  mesh.vertices.push_back({center + right + up, normal, {1.0f, 0.0f}});
  mesh.vertices.push_back({center - right + up, normal, {0.0f, 0.0f}});
  addTriangle(mesh, first, first + 1, first + 2);
  addTriangle(mesh, first, first + 2, first + 3);
}

// A point on the unit circle in the XZ plane; angle 0 is +Z and angles grow towards +X, which
// makes walking by increasing angle counter-clockwise when seen from +Y.
glm::vec3 aroundY(float angle) {
  return {std::sin(angle), 0.0f, std::cos(angle)};
}

}  // namespace

scene::MeshData box(const glm::vec3& size) {
  scene::MeshData mesh;
  mesh.name = "box";
  const glm::vec3 half = size * 0.5f;
  const glm::vec3 x{half.x, 0, 0}, y{0, half.y, 0}, z{0, 0, half.z};
  addQuad(mesh, x, -z, y, {1, 0, 0});
  addQuad(mesh, -x, z, y, {-1, 0, 0});
  addQuad(mesh, y, x, -z, {0, 1, 0});
  addQuad(mesh, -y, x, z, {0, -1, 0});
  addQuad(mesh, z, x, y, {0, 0, 1});
  addQuad(mesh, -z, -x, y, {0, 0, -1});
  return mesh;
}

scene::MeshData sphere(float radius, uint32_t segments, uint32_t rings) {
  scene::MeshData mesh;
  mesh.name = "sphere";
  const float pi = std::numbers::pi_v<float>;
  // Rows run from the north pole (ring 0) to the south pole; the seam column is duplicated so
  // every row has segments + 1 vertices and u can run from 0 to 1 without wrapping.
  for (uint32_t ring = 0; ring <= rings; ++ring) {
    const float v = static_cast<float>(ring) / static_cast<float>(rings);
    const float polar = pi * v;
    for (uint32_t segment = 0; segment <= segments; ++segment) {
      const float u = static_cast<float>(segment) / static_cast<float>(segments);
      const float azimuth = 2.0f * pi * u;
      const glm::vec3 normal =
          aroundY(azimuth) * std::sin(polar) + glm::vec3(0, std::cos(polar), 0);
      mesh.vertices.push_back({normal * radius, normal, {u, v}});
    }
  }
  const uint32_t rowLength = segments + 1;
  for (uint32_t ring = 0; ring < rings; ++ring) {
    for (uint32_t segment = 0; segment < segments; ++segment) {
      const uint32_t upperLeft = ring * rowLength + segment;
      const uint32_t lowerLeft = upperLeft + rowLength;
      // The bands touching a pole would get one degenerate triangle per segment; skip it.
      if (ring != 0) addTriangle(mesh, upperLeft, lowerLeft, upperLeft + 1);
      if (ring != rings - 1) addTriangle(mesh, upperLeft + 1, lowerLeft, lowerLeft + 1);
    }
  }
  return mesh;
}

scene::MeshData plane(float width, float depth) {
  scene::MeshData mesh;
  mesh.name = "plane";
  addQuad(mesh, glm::vec3(0.0f), {width * 0.5f, 0, 0}, {0, 0, -depth * 0.5f}, {0, 1, 0});
  return mesh;
}

scene::MeshData cylinder(float radius, float height, uint32_t segments) {
  scene::MeshData mesh;
  mesh.name = "cylinder";
  const float pi = std::numbers::pi_v<float>;
  const float halfHeight = height * 0.5f;
  auto angleOf = [&](uint32_t segment) {
    return 2.0f * pi * static_cast<float>(segment) / static_cast<float>(segments);
  };

  // Side: a bottom/top vertex pair per column, seam duplicated; u runs around, v down.
  for (uint32_t segment = 0; segment <= segments; ++segment) {
    const glm::vec3 normal = aroundY(angleOf(segment));
    const float u = static_cast<float>(segment) / static_cast<float>(segments);
    mesh.vertices.push_back({normal * radius - glm::vec3(0, halfHeight, 0), normal, {u, 1.0f}});
    mesh.vertices.push_back({normal * radius + glm::vec3(0, halfHeight, 0), normal, {u, 0.0f}});
  }
  for (uint32_t segment = 0; segment < segments; ++segment) {
    const uint32_t bottom = 2 * segment, top = bottom + 1;
    const uint32_t nextBottom = bottom + 2, nextTop = bottom + 3;
    addTriangle(mesh, bottom, nextBottom, nextTop);
    addTriangle(mesh, bottom, nextTop, top);
  }

  // Caps: a center vertex and their own ring, so their normals stay flat. The texture is laid
  // flat over each cap as on a box face: u along +X, v along +Z on top and along -Z below, so
  // neither cap shows it mirrored.
  for (const float side : {1.0f, -1.0f}) {
    const glm::vec3 normal{0, side, 0};
    const uint32_t center = nextIndex(mesh);
    mesh.vertices.push_back({normal * halfHeight, normal, {0.5f, 0.5f}});
    for (uint32_t segment = 0; segment < segments; ++segment) {
      const glm::vec3 rim = aroundY(angleOf(segment));
      const glm::vec2 uv{0.5f + 0.5f * rim.x, 0.5f + 0.5f * side * rim.z};
      mesh.vertices.push_back({rim * radius + normal * halfHeight, normal, uv});
    }
    for (uint32_t segment = 0; segment < segments; ++segment) {
      const uint32_t current = center + 1 + segment;
      const uint32_t next = center + 1 + (segment + 1) % segments;
      // Increasing angle is counter-clockwise seen from +Y, so the bottom cap runs backwards.
      if (side > 0) {
        addTriangle(mesh, center, current, next);
      } else {
        addTriangle(mesh, center, next, current);
      }
    }
  }
  return mesh;
}

}  // namespace game::primitives
