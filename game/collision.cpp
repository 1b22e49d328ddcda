#include "game/collision.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scene/box_transform.hpp"

namespace game {

Aabb transformAabb(const Aabb& box, const glm::mat4& transform) {
  return scene::transformBox(box, transform);
}

namespace {

Aabb triangleBox(const glm::vec3* t) {
  return {glm::min(t[0], glm::min(t[1], t[2])), glm::max(t[0], glm::max(t[1], t[2]))};
}

// Slab test: the entry distance of the ray into the box, if it enters within [0, maxT].
std::optional<float> rayEntersBox(const Aabb& box, const glm::vec3& origin,
                                  const glm::vec3& inverseDirection, float maxT) {
  const glm::vec3 t0 = (box.min - origin) * inverseDirection;
  const glm::vec3 t1 = (box.max - origin) * inverseDirection;
  const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
  const float enter = std::max({near.x, near.y, near.z, 0.0f});
  const float leave = std::min({far.x, far.y, far.z, maxT});
  if (enter > leave) return std::nullopt;  // NaN (0 × inf on a face plane) also lands here
  return enter;
}

// Möller–Trumbore, two-sided.
std::optional<float> rayTriangle(const glm::vec3& origin, const glm::vec3& direction,
                                 const glm::vec3* t) {
  const glm::vec3 edge1 = t[1] - t[0], edge2 = t[2] - t[0];
  const glm::vec3 p = glm::cross(direction, edge2);
  const float det = glm::dot(edge1, p);
  if (std::abs(det) < 1e-12f) return std::nullopt;
  const float invDet = 1.0f / det;
  const glm::vec3 s = origin - t[0];
  const float u = glm::dot(s, p) * invDet;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const glm::vec3 q = glm::cross(s, edge1);
  const float v = glm::dot(direction, q) * invDet;
  if (v < 0.0f || u + v > 1.0f) return std::nullopt;
  return glm::dot(edge2, q) * invDet;
}

// Closest points between segments [p1, q1] and [p2, q2] (Ericson, Real-Time Collision Detection
// 5.1.9).
std::pair<glm::vec3, glm::vec3> closestSegmentSegment(const glm::vec3& p1, const glm::vec3& q1,
                                                      const glm::vec3& p2, const glm::vec3& q2) {
  const glm::vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  constexpr float tiny = 1e-12f;
  float s = 0.0f, t = 0.0f;
  if (a <= tiny && e <= tiny) return {p1, p2};
  if (a <= tiny) {
    t = std::clamp(f / e, 0.0f, 1.0f);
  } else {
    const float c = glm::dot(d1, r);
    if (e <= tiny) {
      s = std::clamp(-c / a, 0.0f, 1.0f);
    } else {
      const float b = glm::dot(d1, d2);
      const float denom = a * e - b * b;
      s = denom > tiny ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0.0f) {
        t = 0.0f;
        s = std::clamp(-c / a, 0.0f, 1.0f);
      } else if (t > 1.0f) {
        t = 1.0f;
        s = std::clamp((b - c) / a, 0.0f, 1.0f);
      }
    }
  }
  return {p1 + d1 * s, p2 + d2 * t};
}

}  // namespace

// Ericson 5.1.5: by the Voronoi regions of the triangle's vertices, edges and face.
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.0f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The minimum is at a segment end against the face, at an edge against the segment, or where
// the segment pierces the face (distance 0).
std::pair<glm::vec3, glm::vec3> closestSegmentTriangle(const glm::vec3& p, const glm::vec3& q,
                                                       const glm::vec3& a, const glm::vec3& b,
                                                       const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float dp = glm::dot(p - a, n), dq = glm::dot(q - a, n);
  if ((dp <= 0.0f) != (dq <= 0.0f) || (dp == 0.0f && dq == 0.0f && glm::dot(n, n) > 0.0f)) {
    const float t = dp == dq ? 0.0f : dp / (dp - dq);
    const glm::vec3 x = p + (q - p) * t;
    if (glm::dot(glm::cross(b - a, x - a), n) >= 0.0f &&
        glm::dot(glm::cross(c - b, x - b), n) >= 0.0f &&
        glm::dot(glm::cross(a - c, x - c), n) >= 0.0f)
      return {x, x};
  }
  std::pair<glm::vec3, glm::vec3> best{p, closestPointOnTriangle(p, a, b, c)};
  float bestDistance2 = glm::dot(best.first - best.second, best.first - best.second);
  const auto consider = [&](const std::pair<glm::vec3, glm::vec3>& candidate) {
    const glm::vec3 d = candidate.first - candidate.second;
    if (glm::dot(d, d) < bestDistance2) {
      bestDistance2 = glm::dot(d, d);
      best = candidate;
    }
  };
  consider({q, closestPointOnTriangle(q, a, b, c)});
  consider(closestSegmentSegment(p, q, a, b));
  consider(closestSegmentSegment(p, q, b, c));
  consider(closestSegmentSegment(p, q, c, a));
  return best;
}

TriangleCollider::TriangleCollider(const scene::MeshData& mesh) {
  const size_t count = mesh.indices.size() / 3;
  std::vector<glm::vec3> corners(3 * count);
  for (size_t i = 0; i < 3 * count; ++i) corners[i] = mesh.vertices[mesh.indices[i]].position;
  std::vector<Aabb> boxes(count);
  std::vector<glm::vec3> centroids(count);
  for (size_t i = 0; i < count; ++i) {
    boxes[i] = triangleBox(&corners[3 * i]);
    centroids[i] = (corners[3 * i] + corners[3 * i + 1] + corners[3 * i + 2]) / 3.0f;
  }
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  if (count > 0) {
    nodes_.reserve(2 * count);
    build(order, 0, uint32_t(count), centroids, boxes);
  }
  corners_.reserve(3 * count);
  for (uint32_t triangle : order)
    corners_.insert(corners_.end(), &corners[3 * triangle], &corners[3 * triangle] + 3);
}

uint32_t TriangleCollider::build(std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                                 const std::vector<glm::vec3>& centroids,
                                 const std::vector<Aabb>& boxes) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  Aabb box = boxes[order[begin]];
  Aabb centroidBox{centroids[order[begin]], centroids[order[begin]]};
  for (uint32_t i = begin; i < end; ++i) {
    box.min = glm::min(box.min, boxes[order[i]].min);
    box.max = glm::max(box.max, boxes[order[i]].max);
    centroidBox.min = glm::min(centroidBox.min, centroids[order[i]]);
    centroidBox.max = glm::max(centroidBox.max, centroids[order[i]]);
  }
  constexpr uint32_t leafSize = 4;
  if (end - begin <= leafSize) {
    nodes_[index] = {box, begin, end - begin};
    return index;
  }
  const glm::vec3 extent = centroidBox.max - centroidBox.min;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t middle = begin + (end - begin) / 2;
  // Ties broken by triangle index so the tree does not depend on the sort's whims.
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](uint32_t l, uint32_t r) {
                     return centroids[l][axis] < centroids[r][axis] ||
                            (centroids[l][axis] == centroids[r][axis] && l < r);
                   });
  build(order, begin, middle, centroids, boxes);  // lands at index + 1
  const uint32_t right = build(order, middle, end, centroids, boxes);
  nodes_[index] = {box, right, 0};
  return index;
}

std::optional<std::pair<float, uint32_t>> TriangleCollider::rayCast(const glm::vec3& origin,
                                                                    const glm::vec3& direction,
                                                                    float maxT) const {
  if (nodes_.empty()) return std::nullopt;
  const glm::vec3 inverseDirection = 1.0f / direction;
  std::optional<std::pair<float, uint32_t>> best;
  float limit = maxT;
  uint32_t stack[64];
  uint32_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    if (!rayEntersBox(node.box, origin, inverseDirection, limit)) continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = index + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const std::optional<float> t = rayTriangle(origin, direction, triangle(i));
      // Equal distances keep the lower index, whatever order the nodes came in.
      if (t && *t >= 0.0f && *t <= limit && (!best || *t < limit || i < best->second)) {
        best = {*t, i};
        limit = *t;
      }
    }
  }
  return best;
}

CollisionWorld::CollisionWorld(const Level& level) {
  colliders_.reserve(level.meshes.size());
  for (const scene::MeshData& mesh : level.meshes) colliders_.emplace_back(mesh);
  entities_.resize(level.entities.size());
  for (size_t i = 0; i < level.entities.size(); ++i) {
    entities_[i].collider = level.entities[i].mesh;
    setTransform(uint32_t(i), entityTransform(level.entities[i]));
  }
}

void CollisionWorld::setTransform(uint32_t entity, const glm::mat4& objectToWorld) {
  Placed& placed = entities_[entity];
  placed.transform = objectToWorld;
  placed.inverse = glm::inverse(objectToWorld);
  placed.worldBox = transformAabb(colliders_[placed.collider].bounds(), objectToWorld);
}

std::optional<RayHit> CollisionWorld::rayCast(const glm::vec3& origin, const glm::vec3& direction,
                                              float maxDistance) const {
  const float length = glm::length(direction);
  if (!(length > 0.0f)) return std::nullopt;
  const glm::vec3 unit = direction / length;
  std::optional<RayHit> best;
  float limit = maxDistance;
  for (uint32_t e = 0; e < entities_.size(); ++e) {
    const Placed& placed = entities_[e];
    if (!placed.solid) continue;
    if (!rayEntersBox(placed.worldBox, origin, 1.0f / unit, limit)) continue;
    // In the entity's space the unnormalised direction keeps t a world distance.
    const glm::vec3 localOrigin = glm::vec3(placed.inverse * glm::vec4(origin, 1.0f));
    const glm::vec3 localDirection = glm::vec3(placed.inverse * glm::vec4(unit, 0.0f));
    const TriangleCollider& collider = colliders_[placed.collider];
    const auto hit = collider.rayCast(localOrigin, localDirection, limit);
    if (!hit || (best && hit->first >= best->distance)) continue;
    const glm::vec3* t = collider.triangle(hit->second);
    glm::vec3 world[3];
    for (int k = 0; k < 3; ++k) world[k] = glm::vec3(placed.transform * glm::vec4(t[k], 1.0f));
    glm::vec3 normal = glm::normalize(glm::cross(world[1] - world[0], world[2] - world[0]));
    if (glm::dot(normal, unit) > 0.0f) normal = -normal;
    best = RayHit{e, hit->first, origin + unit * hit->first, normal};
    limit = hit->first;
  }
  return best;
}

std::optional<CapsuleContact> CollisionWorld::deepestContact(const glm::vec3& feet,
                                                             const CapsuleShape& capsule) const {
  const float r = capsule.radius;
  const glm::vec3 bottom = feet + glm::vec3(0.0f, r, 0.0f);
  const glm::vec3 top = feet + glm::vec3(0.0f, capsule.height - r, 0.0f);
  const Aabb query{feet - glm::vec3(r, 0.0f, r), feet + glm::vec3(r, capsule.height, r)};
  std::optional<CapsuleContact> best;
  for (uint32_t e = 0; e < entities_.size(); ++e) {
    const Placed& placed = entities_[e];
    if (!placed.solid || !placed.worldBox.overlaps(query)) continue;
    const TriangleCollider& collider = colliders_[placed.collider];
    collider.forEachOverlapping(transformAabb(query, placed.inverse), [&](uint32_t i) {
      const glm::vec3* local = collider.triangle(i);
      glm::vec3 t[3];
      for (int k = 0; k < 3; ++k) t[k] = glm::vec3(placed.transform * glm::vec4(local[k], 1.0f));
      const auto [onAxis, onTriangle] = closestSegmentTriangle(bottom, top, t[0], t[1], t[2]);
      const float distance = glm::length(onAxis - onTriangle);
      if (distance >= r) return;
      const glm::vec3 face = glm::cross(t[1] - t[0], t[2] - t[0]);
      if (glm::dot(face, face) == 0.0f) return;  // degenerate: its edges belong to others
      const glm::vec3 n = glm::normalize(face);
      CapsuleContact contact{e, {}, r - distance, onTriangle, n};
      if (distance > 1e-5f) {
        contact.normal = (onAxis - onTriangle) / distance;
        if (glm::dot(n, contact.normal) < 0.0f) contact.faceNormal = -n;
      } else {
        // The axis pierces the face: push towards the side holding more of the capsule, far
        // enough that the other end clears the face by the radius.
        const float dBottom = glm::dot(bottom - t[0], n), dTop = glm::dot(top - t[0], n);
        const bool topSide = std::abs(dTop) >= std::abs(dBottom);
        const float side = (topSide ? dTop : dBottom) >= 0.0f ? 1.0f : -1.0f;
        const float other = topSide ? dBottom : dTop;
        contact.normal = contact.faceNormal = n * side;
        contact.depth = r + std::max(0.0f, -other * side);
      }
      // Deepest wins; ties go to the more upward face, then to the first entity and triangle
      // (a fixed order).
      constexpr float sameDepth = 1e-6f;
      if (!best || contact.depth > best->depth + sameDepth ||
          (contact.depth > best->depth - sameDepth &&
           contact.faceNormal.y > best->faceNormal.y + 1e-6f))
        best = contact;
    });
  }
  return best;
}

}  // namespace game
