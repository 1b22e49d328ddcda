// Tests for the built-in primitives' texture coordinates. (Counts, winding and normals are
// tested in level_loader_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "game/primitives.hpp"

namespace {

void expectUvsInUnitSquare(const scene::MeshData& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec2 uv = mesh.vertices[i].uv;
    EXPECT_TRUE(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)
        << mesh.name << " vertex " << i << " has uv (" << uv.x << ", " << uv.y << ")";
  }
}

// Image rows run downwards (v grows down), so a texture that reads correctly on a front face
// turns counter-clockwise corners clockwise in (u, v): every triangle's signed UV area is
// negative. A positive one would show the texture mirrored.
void expectTextureUnmirrored(const scene::MeshData& mesh) {
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec2 a = mesh.vertices.at(mesh.indices[i]).uv;
    const glm::vec2 b = mesh.vertices.at(mesh.indices[i + 1]).uv;
    const glm::vec2 c = mesh.vertices.at(mesh.indices[i + 2]).uv;
    const glm::vec2 ab = b - a, ac = c - a;
    EXPECT_LT(ab.x * ac.y - ab.y * ac.x, 0.0f) << mesh.name << " triangle " << i / 3;
  }
}

TEST(PrimitiveUvs, box_faces_each_hold_the_whole_texture) {
  const scene::MeshData box = game::primitives::box({2, 4, 6});
  ASSERT_EQ(box.vertices.size(), 24u);
  expectUvsInUnitSquare(box);
  expectTextureUnmirrored(box);
  for (std::size_t face = 0; face < 6; ++face) {
    const auto* corners = &box.vertices[face * 4];
    EXPECT_EQ(corners[0].uv, glm::vec2(0, 1)) << "face " << face;
    EXPECT_EQ(corners[1].uv, glm::vec2(1, 1)) << "face " << face;
    EXPECT_EQ(corners[2].uv, glm::vec2(1, 0)) << "face " << face;
    EXPECT_EQ(corners[3].uv, glm::vec2(0, 0)) << "face " << face;
  }
  // The +Z face, seen from +Z: the image's top-left corner is at the top left (-X, +Y).
  EXPECT_EQ(box.vertices[16 + 3].position, glm::vec3(-1, 2, 3));
}

TEST(PrimitiveUvs, sphere_u_runs_around_and_v_from_the_top) {
  const uint32_t segments = 12, rings = 6;
  const scene::MeshData sphere = game::primitives::sphere(2.0f, segments, rings);
  expectUvsInUnitSquare(sphere);
  expectTextureUnmirrored(sphere);
  for (uint32_t ring = 0; ring <= rings; ++ring) {
    for (uint32_t segment = 0; segment <= segments; ++segment) {
      const scene::Vertex& vertex = sphere.vertices.at(ring * (segments + 1) + segment);
      EXPECT_FLOAT_EQ(vertex.uv.x, static_cast<float>(segment) / segments);
      EXPECT_FLOAT_EQ(vertex.uv.y, static_cast<float>(ring) / rings);
    }
  }
  EXPECT_FLOAT_EQ(sphere.vertices.front().position.y, 2.0f);  // v = 0 at the north pole
  EXPECT_FLOAT_EQ(sphere.vertices.back().position.y, -2.0f);  // v = 1 at the south pole
}

TEST(PrimitiveUvs, plane_u_follows_x_and_v_follows_z) {
  const scene::MeshData plane = game::primitives::plane(4.0f, 2.0f);
  expectUvsInUnitSquare(plane);
  expectTextureUnmirrored(plane);
  for (const scene::Vertex& vertex : plane.vertices) {
    EXPECT_FLOAT_EQ(vertex.uv.x, vertex.position.x / 4.0f + 0.5f);
    EXPECT_FLOAT_EQ(vertex.uv.y, vertex.position.z / 2.0f + 0.5f);
  }
}

TEST(PrimitiveUvs, cylinder_sides_wrap_and_caps_lie_flat) {
  const uint32_t segments = 8;
  const float radius = 1.0f, height = 3.0f;
  const scene::MeshData cylinder = game::primitives::cylinder(radius, height, segments);
  expectUvsInUnitSquare(cylinder);
  expectTextureUnmirrored(cylinder);
  const uint32_t sideVertices = 2 * (segments + 1);
  for (uint32_t i = 0; i < sideVertices; ++i) {
    const scene::Vertex& vertex = cylinder.vertices[i];
    EXPECT_FLOAT_EQ(vertex.uv.x, static_cast<float>(i / 2) / segments) << "side vertex " << i;
    EXPECT_EQ(vertex.uv.y, vertex.position.y > 0 ? 0.0f : 1.0f) << "side vertex " << i;
  }
  for (std::size_t i = sideVertices; i < cylinder.vertices.size(); ++i) {
    const scene::Vertex& vertex = cylinder.vertices[i];
    const float expectedV = vertex.normal.y > 0 ? 0.5f + vertex.position.z / (2 * radius)
                                                : 0.5f - vertex.position.z / (2 * radius);
    EXPECT_NEAR(vertex.uv.x, 0.5f + vertex.position.x / (2 * radius), 1e-6f) << "cap vertex " << i;
    EXPECT_NEAR(vertex.uv.y, expectedV, 1e-6f) << "cap vertex " << i;
  }
}

}  // namespace
