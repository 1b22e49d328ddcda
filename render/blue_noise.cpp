#include "render/blue_noise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "shaders/shared_types.h"

namespace render {
namespace {

constexpr float kSigma = 1.5f;
// The energy's Gaussian is cut off this many texels out (exp(-8): three ten-thousandths).
constexpr int kReach = 6;

uint64_t splitMix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The points of a binary pattern on a torus and each texel's energy: the sum of a Gaussian of
// its distance to every point. The tightest cluster is the point of highest energy, the largest
// void the empty texel of lowest. Each texel's energy is kept where the search for one of the
// two looks (the other holds an infinity), so each search is one pass over an array.
class PatternEnergy {
 public:
  explicit PatternEnergy(uint32_t size)
      : size_(int(size)),
        clusterKey_(size_t(size) * size, -std::numeric_limits<float>::infinity()),
        voidKey_(clusterKey_.size(), 0.0f) {
    for (int dy = -kReach; dy <= kReach; ++dy)
      for (int dx = -kReach; dx <= kReach; ++dx)
        kernel_.push_back(std::exp(-float(dx * dx + dy * dy) / (2.0f * kSigma * kSigma)));
  }

  void add(size_t texel) {
    clusterKey_[texel] = voidKey_[texel];
    voidKey_[texel] = std::numeric_limits<float>::infinity();
    spread(texel, 1.0f);
  }
  void remove(size_t texel) {
    spread(texel, -1.0f);
    voidKey_[texel] = clusterKey_[texel];
    clusterKey_[texel] = -std::numeric_limits<float>::infinity();
  }

  // The first of the texels that tie.
  size_t tightestCluster() const {
    return size_t(std::max_element(clusterKey_.begin(), clusterKey_.end()) - clusterKey_.begin());
  }
  size_t largestVoid() const {
    return size_t(std::min_element(voidKey_.begin(), voidKey_.end()) - voidKey_.begin());
  }

 private:
  // Adds `sign` times the Gaussian around `texel` to every texel's energy (the infinities stay).
  void spread(size_t texel, float sign) {
    const int x = int(texel % size_t(size_)), y = int(texel / size_t(size_));
    size_t k = 0;
    for (int dy = -kReach; dy <= kReach; ++dy) {
      const int row = ((y + dy) % size_ + size_) % size_;
      for (int dx = -kReach; dx <= kReach; ++dx, ++k) {
        const int column = ((x + dx) % size_ + size_) % size_;
        const size_t at = size_t(row) * size_t(size_) + size_t(column);
        clusterKey_[at] += sign * kernel_[k];
        voidKey_[at] += sign * kernel_[k];
      }
    }
  }

  int size_;
  std::vector<float> clusterKey_;  // a point's energy; -infinity at an empty texel
  std::vector<float> voidKey_;     // an empty texel's energy; +infinity at a point
  std::vector<float> kernel_;
};

}  // namespace

std::vector<uint32_t> blueNoiseRanks(uint32_t size, uint64_t seed) {
  if (size < 2 * kReach + 1) throw std::invalid_argument("blue noise tile smaller than its kernel");
  const size_t texels = size_t(size) * size;
  // The starting pattern: a tenth of the texels, drawn at random, then relaxed by moving the
  // point of the tightest cluster into the largest void until that would put it back.
  std::vector<size_t> order(texels);
  std::iota(order.begin(), order.end(), size_t(0));
  uint64_t state = seed;
  for (size_t i = texels - 1; i > 0; --i) std::swap(order[i], order[splitMix64(state) % (i + 1)]);
  const size_t initial = texels / 10;
  PatternEnergy start(size);
  for (size_t i = 0; i < initial; ++i) start.add(order[i]);
  for (size_t move = 0; move < texels; ++move) {
    const size_t cluster = start.tightestCluster();
    start.remove(cluster);
    const size_t emptiest = start.largestVoid();
    start.add(emptiest);
    if (emptiest == cluster) break;
  }

  std::vector<uint32_t> ranks(texels, 0);
  // The ranks below the starting pattern's count go to its points from the top down: each next
  // lower rank to the tightest cluster left, which is then taken out.
  PatternEnergy fewer = start;
  for (size_t rank = initial; rank-- > 0;) {
    const size_t cluster = fewer.tightestCluster();
    fewer.remove(cluster);
    ranks[cluster] = uint32_t(rank);
  }
  // The rest: each next rank fills the largest void. (Past half the texels this is the same as
  // taking the tightest cluster of the empty texels: their energy is the kernel's sum less the
  // points'.)
  PatternEnergy more = start;
  for (size_t rank = initial; rank < texels; ++rank) {
    const size_t emptiest = more.largestVoid();
    more.add(emptiest);
    ranks[emptiest] = uint32_t(rank);
  }
  return ranks;
}

const std::vector<uint32_t>& softShadowSampleNoise() {
  static const std::vector<uint32_t> packed = [] {
    const uint32_t size = SAMPLE_NOISE_SIZE;
    static_assert(SAMPLE_NOISE_SIZE * SAMPLE_NOISE_SIZE <= 4096u, "ranks packed in 12 bits");
    const std::vector<uint32_t> first = blueNoiseRanks(size, kSoftShadowNoiseSeeds[0]),
                                second = blueNoiseRanks(size, kSoftShadowNoiseSeeds[1]),
                                third = blueNoiseRanks(size, kSoftShadowNoiseSeeds[2]);
    std::vector<uint32_t> words(first.size());
    for (size_t i = 0; i < words.size(); ++i)
      words[i] = first[i] | (second[i] << 12) | ((third[i] >> 4) << 24);
    return words;
  }();
  return packed;
}

}  // namespace render
