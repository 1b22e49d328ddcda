#pragma once
// An order for the leaves of a bounding volume hierarchy whose builder halves the list it is
// given, in the order given (Mesa 25.0's lavapipe does: each node's children are the first
// ceil(n/2) leaves and the rest, whatever they are). Ordering the leaves so that each halving
// splits space gives that builder a hierarchy worth traversing; drivers that sort the leaves
// for themselves are unaffected.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace render {

struct LeafBounds {
  glm::vec3 min{0.0f}, max{0.0f};
};

// The leaves' indices, ordered so that each recursive halving of the list (the first ceil(n/2),
// then the rest) separates them by their centres along the axis where the two halves' boxes
// have the least surface area, each weighed by its leaf count (the surface area heuristic).
std::vector<uint32_t> halvingOrder(std::span<const LeafBounds> leaves);

}  // namespace render
