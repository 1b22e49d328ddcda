// The blue-noise tiles behind the soft shadows' per-pixel sample numbers.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include <gtest/gtest.h>

#include "render/blue_noise.hpp"
#include "shaders/shared_types.h"

namespace {

constexpr uint32_t kSize = 64;

// The smallest squared distance on the torus between two texels whose ranks lie in
// [first, first + count).
int closestPairOfRun(const std::vector<uint32_t>& ranks, uint32_t first, uint32_t count) {
  std::vector<std::pair<int, int>> texels;
  for (uint32_t i = 0; i < ranks.size(); ++i)
    if (ranks[i] >= first && ranks[i] < first + count) texels.emplace_back(i % kSize, i / kSize);
  int closest = int(kSize * kSize);
  for (size_t a = 0; a < texels.size(); ++a) {
    for (size_t b = a + 1; b < texels.size(); ++b) {
      int dx = std::abs(texels[a].first - texels[b].first);
      int dy = std::abs(texels[a].second - texels[b].second);
      dx = std::min(dx, int(kSize) - dx);
      dy = std::min(dy, int(kSize) - dy);
      closest = std::min(closest, dx * dx + dy * dy);
    }
  }
  return closest;
}

TEST(BlueNoise, ranks_are_a_permutation_of_every_texel) {
  std::vector<uint32_t> ranks = render::blueNoiseRanks(kSize, 7);
  ASSERT_EQ(ranks.size(), size_t(kSize * kSize));
  std::sort(ranks.begin(), ranks.end());
  std::vector<uint32_t> expected(ranks.size());
  std::iota(expected.begin(), expected.end(), 0u);
  EXPECT_EQ(ranks, expected);
}

TEST(BlueNoise, no_two_texels_of_any_sixteenth_of_the_ranks_are_side_by_side) {
  // 256 texels of 4096, four texels apart on average. Drawn at random, about 32 pairs of them
  // would be side by side (a squared distance of 1); in blue noise none are, and at the ends of
  // the ranks, where the points are fewest, none are diagonal neighbours (2) either.
  const std::vector<uint32_t> ranks = render::blueNoiseRanks(kSize, 1);
  for (uint32_t first : {0u, 1000u, 1920u, 2048u, 3000u, 3840u}) {
    const int closest = closestPairOfRun(ranks, first, 256);
    std::printf("ranks %u-%u: closest pair %d (squared texels)\n", first, first + 255, closest);
    EXPECT_GE(closest, first == 0u || first == 3840u ? 4 : 2) << "ranks from " << first;
  }
}

TEST(BlueNoise, the_same_seed_gives_the_same_tile_and_another_seed_another) {
  EXPECT_EQ(render::blueNoiseRanks(kSize, 3), render::blueNoiseRanks(kSize, 3));
  EXPECT_NE(render::blueNoiseRanks(kSize, 3), render::blueNoiseRanks(kSize, 4));
}

TEST(BlueNoise, the_soft_shadows_tiles_pack_three_maps_a_texel) {
  const std::vector<uint32_t>& packed = render::softShadowSampleNoise();
  ASSERT_EQ(packed.size(), size_t(SAMPLE_NOISE_SIZE * SAMPLE_NOISE_SIZE));
  const std::vector<uint32_t> first =
      render::blueNoiseRanks(SAMPLE_NOISE_SIZE, render::kSoftShadowNoiseSeeds[0]);
  const std::vector<uint32_t> third =
      render::blueNoiseRanks(SAMPLE_NOISE_SIZE, render::kSoftShadowNoiseSeeds[2]);
  std::vector<uint32_t> secondField(packed.size());
  for (size_t i = 0; i < packed.size(); ++i) {
    EXPECT_EQ(packed[i] & 0xFFFu, first[i]);
    EXPECT_EQ(packed[i] >> 24, third[i] >> 4);
    secondField[i] = packed[i] >> 12 & 0xFFFu;
  }
  std::sort(secondField.begin(), secondField.end());
  EXPECT_EQ(secondField.front(), 0u);
  EXPECT_EQ(secondField.back(), uint32_t(packed.size() - 1));
  EXPECT_EQ(std::adjacent_find(secondField.begin(), secondField.end()), secondField.end());
}

}  // namespace
