#pragma once
// Static triangle colliders per mesh and a world of placed entities: ray casts (picking) and
// capsule contacts (the player). Pure CPU, deterministic.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "game/level.hpp"

namespace game {

struct Aabb {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool overlaps(const Aabb& other) const {
    return glm::all(glm::lessThanEqual(min, other.max)) &&
           glm::all(glm::lessThanEqual(other.min, max));
  }
  // Faces included.
  bool contains(const glm::vec3& point) const {
    return glm::all(glm::greaterThanEqual(point, min)) && glm::all(glm::lessThanEqual(point, max));
  }
};

// The box around `box` placed by `transform` (its eight corners).
Aabb transformAabb(const Aabb& box, const glm::mat4& transform);

// A mesh's triangles in its own space with a bounding-volume hierarchy (median split), so one
// big glTF mesh costs a few node tests per query instead of a scan of every triangle.
class TriangleCollider {
 public:
  explicit TriangleCollider(const scene::MeshData& mesh);

  const Aabb& bounds() const { return nodes_.empty() ? empty_ : nodes_[0].box; }
  size_t triangleCount() const { return corners_.size() / 3; }
  const glm::vec3* triangle(size_t index) const { return &corners_[3 * index]; }

  // Calls visit(triangle index) for every triangle whose box overlaps `box`.
  template <typename Visit>
  void forEachOverlapping(const Aabb& box, Visit&& visit) const;
  // The nearest hit along origin + t·direction, t in [0, maxT]: {t, triangle index}.
  std::optional<std::pair<float, uint32_t>> rayCast(const glm::vec3& origin,
                                                    const glm::vec3& direction, float maxT) const;

 private:
  struct Node {
    Aabb box;
    uint32_t first = 0;  // leaf: first triangle; inner: index of the right child (left is +1)
    uint32_t count = 0;  // triangles in a leaf; 0 for inner nodes
  };
  uint32_t build(std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                 const std::vector<glm::vec3>& centroids, const std::vector<Aabb>& boxes);

  std::vector<glm::vec3> corners_;  // three per triangle, in BVH leaf order
  std::vector<Node> nodes_;
  Aabb empty_;
};

struct RayHit {
  uint32_t entity = 0;
  float distance = 0.0f;  // along the (normalised) direction
  glm::vec3 point{0.0f};
  glm::vec3 normal{0.0f};  // world space, unit, facing the ray's origin
};

// A vertical capsule standing on `feet`: the segment from feet + radius to feet + height −
// radius, swept by a sphere of `radius`.
struct CapsuleShape {
  float radius = 0.3f;
  float height = 1.8f;
};

// The deepest overlap of a capsule with one triangle.
struct CapsuleContact {
  uint32_t entity = 0;
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit, from the triangle towards the capsule's axis
  float depth = 0.0f;                  // how far along `normal` the capsule must move to be clear
  glm::vec3 point{0.0f};               // on the triangle
  glm::vec3 faceNormal{0.0f, 1.0f, 0.0f};  // the triangle's, unit, on the capsule's side
};

class CollisionWorld {
 public:
  // One collider per mesh; every entity starts at entityTransform(entity).
  explicit CollisionWorld(const Level& level);

  size_t entityCount() const { return entities_.size(); }
  void setTransform(uint32_t entity, const glm::mat4& objectToWorld);
  // A non-solid entity (hidden by level logic) is skipped by ray casts and contacts.
  void setSolid(uint32_t entity, bool solid) { entities_[entity].solid = solid; }
  const glm::mat4& transform(uint32_t entity) const { return entities_[entity].transform; }
  const Aabb& worldBounds(uint32_t entity) const { return entities_[entity].worldBox; }

  // The nearest triangle hit within maxDistance; `direction` need not be normalised.
  std::optional<RayHit> rayCast(const glm::vec3& origin, const glm::vec3& direction,
                                float maxDistance) const;

  // The deepest contact of the capsule on `feet` with any triangle, if it penetrates at all.
  // Equal depths (an edge shared by two faces) go to the more upward-facing face, so the top
  // of a step, not its riser, decides what an edge under the player is.
  std::optional<CapsuleContact> deepestContact(const glm::vec3& feet,
                                               const CapsuleShape& capsule) const;

 private:
  struct Placed {
    uint32_t collider = 0;  // index into colliders_ (= the level's mesh index)
    glm::mat4 transform{1.0f};
    glm::mat4 inverse{1.0f};
    Aabb worldBox;
    bool solid = true;
  };
  std::vector<TriangleCollider> colliders_;
  std::vector<Placed> entities_;
};

// Geometry helpers (exposed for tests).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c);
// Closest points between segment [p, q] and triangle abc: {on segment, on triangle}.
std::pair<glm::vec3, glm::vec3> closestSegmentTriangle(const glm::vec3& p, const glm::vec3& q,
                                                       const glm::vec3& a, const glm::vec3& b,
                                                       const glm::vec3& c);

template <typename Visit>
void TriangleCollider::forEachOverlapping(const Aabb& box, Visit&& visit) const {
  if (nodes_.empty()) return;
  uint32_t stack[64];
  uint32_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.overlaps(box)) continue;
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) visit(i);
    } else {
      const uint32_t self = uint32_t(&node - nodes_.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
}

}  // namespace game
