#pragma once
// Blue noise for the soft shadows' sample numbers: tiles whose values are spread evenly over
// every small neighbourhood (as a lattice's are) without the lattice's linear structure.
#include <array>
#include <cstdint>
#include <vector>

namespace render {

// A tileable `size` x `size` blue-noise rank map, rows first: a permutation of 0 .. size² - 1
// in which texels of nearby rank lie far apart on the torus, so the texels holding any run of
// ranks (any range of values) are spread evenly. Ulichney's void-and-cluster method with a
// Gaussian energy of sigma 1.5 texels, from a starting pattern drawn with `seed`; the same
// arguments give the same map on every machine.
std::vector<uint32_t> blueNoiseRanks(uint32_t size, uint64_t seed);

// The seeds of softShadowSampleNoise's three maps, chosen while still views took the blue noise
// too: with 1, 2 and 3 a slab sliding 2 px a frame before a still camera left a shadow trail of
// 3 px in SoftShadowTest, 2 with these (and with 7-9, 10-12 and the lattice). Still views keep
// the lattice now.
constexpr std::array<uint64_t, 3> kSoftShadowNoiseSeeds = {4, 5, 6};

// The soft shadows' per-pixel starts while the camera moves (shaders/sample_noise.glsl): three
// independent SAMPLE_NOISE_SIZE-square blue-noise rank maps packed into one word a texel, the
// first two in 12 bits each (bits 0-11 and 12-23), the third's top 8 bits in bits 24-31.
// Computed once per process.
const std::vector<uint32_t>& softShadowSampleNoise();

}  // namespace render
