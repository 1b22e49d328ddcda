#include "render/bvh_order.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>

namespace render {
namespace {

float surfaceArea(const LeafBounds& box) {
  const glm::vec3 extent = glm::max(box.max - box.min, glm::vec3(0.0f));
  return extent.x * extent.y + extent.y * extent.z + extent.z * extent.x;
}

LeafBounds boundsOf(std::span<const LeafBounds> leaves, std::span<const uint32_t> indices) {
  LeafBounds box{glm::vec3(std::numeric_limits<float>::max()),
                 glm::vec3(-std::numeric_limits<float>::max())};
  for (const uint32_t index : indices) {
    box.min = glm::min(box.min, leaves[index].min);
    box.max = glm::max(box.max, leaves[index].max);
  }
  return box;
}

// Puts the ceil(n/2) leaves whose centres lie lowest along `axis` first (ties broken by index,
// so which leaves those are does not depend on the standard library); linear time.
void splitAlong(std::span<const LeafBounds> leaves, std::span<uint32_t> indices, size_t leftCount,
                int axis) {
  std::nth_element(indices.begin(), indices.begin() + std::ptrdiff_t(leftCount), indices.end(),
                   [&](uint32_t a, uint32_t b) {
                     const float ca = leaves[a].min[axis] + leaves[a].max[axis];
                     const float cb = leaves[b].min[axis] + leaves[b].max[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
}

void orderRange(std::span<const LeafBounds> leaves, std::span<uint32_t> indices) {
  const size_t count = indices.size();
  if (count <= 2) {
    // A node's two leaves: in order along the axis that separates their centres most.
    if (count == 2) {
      const glm::vec3 apart = glm::abs((leaves[indices[1]].min + leaves[indices[1]].max) -
                                       (leaves[indices[0]].min + leaves[indices[0]].max));
      const int axis = apart.x >= apart.y && apart.x >= apart.z ? 0 : apart.y >= apart.z ? 1 : 2;
      splitAlong(leaves, indices, 1, axis);
    }
    return;
  }
  const size_t leftCount = (count + 1) / 2;  // the builder's first child takes ceil(n/2)
  int bestAxis = 0;
  float bestCost = std::numeric_limits<float>::max();
  for (int axis = 0; axis < 3; ++axis) {
    splitAlong(leaves, indices, leftCount, axis);
    const float cost =
        surfaceArea(boundsOf(leaves, indices.first(leftCount))) * float(leftCount) +
        surfaceArea(boundsOf(leaves, indices.subspan(leftCount))) * float(count - leftCount);
    if (cost < bestCost) {
      bestCost = cost;
      bestAxis = axis;
    }
  }
  splitAlong(leaves, indices, leftCount, bestAxis);
  orderRange(leaves, indices.first(leftCount));
  orderRange(leaves, indices.subspan(leftCount));
}

}  // namespace

std::vector<uint32_t> halvingOrder(std::span<const LeafBounds> leaves) {
  std::vector<uint32_t> order(leaves.size());
  std::iota(order.begin(), order.end(), 0u);
  orderRange(leaves, order);
  return order;
}

}  // namespace render
