#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <vector>

#include "render/bvh_order.hpp"

namespace {

render::LeafBounds box(glm::vec3 low, glm::vec3 high) {
  return {low, high};
}

}  // namespace

TEST(HalvingOrder, is_a_permutation_of_every_leaf) {
  for (const uint32_t count : {0u, 1u, 2u, 3u, 7u, 100u}) {
    std::vector<render::LeafBounds> leaves;
    for (uint32_t i = 0; i < count; ++i) {
      const glm::vec3 at(float((i * 37u) % 11u), float((i * 13u) % 7u), float(i % 3u));
      leaves.push_back(box(at, at + 1.0f));
    }
    std::vector<uint32_t> order = render::halvingOrder(leaves);
    ASSERT_EQ(order.size(), count);
    std::sort(order.begin(), order.end());
    for (uint32_t i = 0; i < count; ++i) EXPECT_EQ(order[i], i) << count;
  }
}

TEST(HalvingOrder, leaves_along_a_line_come_out_sorted_along_it) {
  // Shuffled along x: every halving separates the lower ceil(n/2) from the rest, so the
  // whole list ends up sorted.
  const uint32_t count = 13;
  std::vector<render::LeafBounds> leaves(count);
  std::vector<uint32_t> position(count);
  for (uint32_t i = 0; i < count; ++i) {
    position[i] = (i * 5u) % count;  // 5 and 13 are coprime: a shuffle
    leaves[i] = box(glm::vec3(float(position[i]), 0.0f, 0.0f),
                    glm::vec3(float(position[i]) + 0.5f, 1.0f, 1.0f));
  }
  const std::vector<uint32_t> order = render::halvingOrder(leaves);
  for (uint32_t k = 0; k < count; ++k) EXPECT_EQ(position[order[k]], k);
}

TEST(HalvingOrder, splits_where_the_halves_have_less_surface_not_along_the_longest_spread) {
  // Four slabs: their centres spread more along x (5 and 7) than along y (0.5 and 2), but
  // halving along x leaves two 10 x 2.5 boxes, along y two 12 x 1 ones: less surface.
  const std::vector<render::LeafBounds> leaves = {
      box({0.0f, 0.0f, 0.0f}, {10.0f, 1.0f, 1.0f}),
      box({2.0f, 0.0f, 0.0f}, {12.0f, 1.0f, 1.0f}),
      box({0.0f, 1.5f, 0.0f}, {10.0f, 2.5f, 1.0f}),
      box({2.0f, 1.5f, 0.0f}, {12.0f, 2.5f, 1.0f}),
  };
  const std::vector<uint32_t> order = render::halvingOrder(leaves);
  EXPECT_EQ(std::set<uint32_t>(order.begin(), order.begin() + 2), (std::set<uint32_t>{0u, 1u}));
  EXPECT_EQ(std::set<uint32_t>(order.begin() + 2, order.end()), (std::set<uint32_t>{2u, 3u}));
}

TEST(HalvingOrder, odd_counts_put_the_larger_half_first_as_the_builder_does) {
  // Five leaves on a line: the builder's first child takes three, so the split falls between
  // the third and fourth leaf along x.
  std::vector<render::LeafBounds> leaves;
  for (const float x : {4.0f, 0.0f, 3.0f, 1.0f, 2.0f})
    leaves.push_back(box({x, 0.0f, 0.0f}, {x + 0.5f, 1.0f, 1.0f}));
  const std::vector<uint32_t> order = render::halvingOrder(leaves);
  EXPECT_EQ(order, (std::vector<uint32_t>{1u, 3u, 4u, 2u, 0u}));
}
