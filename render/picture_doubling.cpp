#include "render/picture_doubling.hpp"

#include <bit>
#include <cassert>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace render {
namespace {

// Pixels are handled as 32-bit words and 16-bit lanes in memory order.
static_assert(std::endian::native == std::endian::little, "a little-endian CPU is assumed");
constexpr uint32_t kOpaque = 0xff000000u;  // alpha 255 in a 4-byte pixel

// One source row's weights towards an output row, per channel: 3 x the nearer source row plus
// the farther one (4 x the vertical bilinear value). Written to sums[0, 4 * width) with red
// and blue swapped when asked, and the first and last pixels repeated at sums[-4, 0) and
// sums[4 * width, 4 * width + 4) for the horizontal pass's clamp.
void verticalSums(const uint8_t* nearer, const uint8_t* farther, uint32_t width, bool swapRedBlue,
                  uint16_t* sums) {
  const size_t values = size_t(width) * 4;
  size_t k = 0;
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  for (; k + 16 <= values; k += 16) {
    const __m128i nearBytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(nearer + k));
    const __m128i farBytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(farther + k));
    __m128i low = _mm_unpacklo_epi8(nearBytes, zero);
    __m128i high = _mm_unpackhi_epi8(nearBytes, zero);
    low = _mm_add_epi16(_mm_add_epi16(low, _mm_add_epi16(low, low)),
                        _mm_unpacklo_epi8(farBytes, zero));
    high = _mm_add_epi16(_mm_add_epi16(high, _mm_add_epi16(high, high)),
                         _mm_unpackhi_epi8(farBytes, zero));
    if (swapRedBlue) {  // each pixel's four lanes R G B A -> B G R A
      constexpr int kOrder = _MM_SHUFFLE(3, 0, 1, 2);
      low = _mm_shufflehi_epi16(_mm_shufflelo_epi16(low, kOrder), kOrder);
      high = _mm_shufflehi_epi16(_mm_shufflelo_epi16(high, kOrder), kOrder);
    }
    _mm_storeu_si128(reinterpret_cast<__m128i*>(sums + k), low);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(sums + k + 8), high);
  }
#endif
  for (; k < values; k += 4) {
    for (size_t channel = 0; channel < 4; ++channel) {
      const size_t from = swapRedBlue && channel != 1 && channel != 3 ? 2 - channel : channel;
      sums[k + channel] = uint16_t(3 * nearer[k + from] + farther[k + from]);
    }
  }
  std::memcpy(sums - 4, sums, 4 * sizeof(uint16_t));
  std::memcpy(sums + values, sums + values - 4, 4 * sizeof(uint16_t));
}

// One output row from a row of vertical sums: output pixel 2j weighs source pixels j-1 and j
// 1:3, pixel 2j+1 weighs j and j+1 3:1; 16 x the bilinear value, rounded to a byte.
void horizontalRow(const uint16_t* sums, uint32_t width, uint8_t* target) {
  uint32_t j = 0;
#if defined(__SSE2__)
  const __m128i half = _mm_set1_epi16(8);
  const __m128i opaque = _mm_set1_epi32(int32_t(kOpaque));
  for (; j + 2 <= width; j += 2) {  // two source pixels, four output pixels
    const uint16_t* centre = sums + size_t(j) * 4;
    const __m128i here = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre));
    const __m128i left = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre - 4));
    const __m128i right = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre + 4));
    const __m128i here3 = _mm_add_epi16(here, _mm_add_epi16(here, here));
    const __m128i even = _mm_add_epi16(_mm_add_epi16(left, here3), half);
    const __m128i odd = _mm_add_epi16(_mm_add_epi16(right, here3), half);
    const __m128i first = _mm_srli_epi16(_mm_unpacklo_epi64(even, odd), 4);
    const __m128i second = _mm_srli_epi16(_mm_unpackhi_epi64(even, odd), 4);
    const __m128i pixels = _mm_or_si128(_mm_packus_epi16(first, second), opaque);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(target + size_t(j) * 8), pixels);
  }
#endif
  for (; j < width; ++j) {
    const uint16_t* centre = sums + size_t(j) * 4;
    const uint16_t* left = centre - 4;
    const uint16_t* right = centre + 4;
    uint8_t* out = target + size_t(j) * 8;
    for (size_t channel = 0; channel < 3; ++channel) {
      out[channel] = uint8_t((left[channel] + 3 * centre[channel] + 8) >> 4);
      out[4 + channel] = uint8_t((3 * centre[channel] + right[channel] + 8) >> 4);
    }
    out[3] = out[7] = 255;
  }
}

}  // namespace

size_t doublingScratchSize(uint32_t width) {
  // Two rows of sums (towards the row above and the row below), each with a pixel either side.
  return 2 * size_t(width + 2) * 4;
}

void doublePictureRows(const uint8_t* source, uint32_t width, uint32_t height, uint32_t firstRow,
                       uint32_t endRow, uint8_t* target, size_t targetRowBytes, bool swapRedBlue,
                       std::span<uint16_t> scratch) {
  if (width == 0 || firstRow >= endRow) return;
  assert(scratch.size() >= doublingScratchSize(width));
  const size_t rowBytes = size_t(width) * 4;
  const size_t sumsPerRow = doublingScratchSize(width) / 2;
  uint16_t* upper = scratch.data() + 4;
  uint16_t* lower = scratch.data() + sumsPerRow + 4;
  for (uint32_t row = firstRow; row < endRow; ++row) {
    const uint8_t* here = source + row * rowBytes;
    const uint8_t* above = source + (row > 0 ? row - 1 : 0) * rowBytes;
    const uint8_t* below = source + (row + 1 < height ? row + 1 : row) * rowBytes;
    verticalSums(here, above, width, swapRedBlue, upper);
    verticalSums(here, below, width, swapRedBlue, lower);
    horizontalRow(upper, width, target + size_t(2 * row) * targetRowBytes);
    horizontalRow(lower, width, target + size_t(2 * row + 1) * targetRowBytes);
  }
}

void doublePicture(const uint8_t* source, uint32_t width, uint32_t height, uint8_t* target,
                   size_t targetRowBytes, bool swapRedBlue) {
  std::vector<uint16_t> scratch(doublingScratchSize(width));
  doublePictureRows(source, width, height, 0, height, target, targetRowBytes, swapRedBlue, scratch);
}

void copyPicture(const uint8_t* source, uint32_t width, uint32_t height, uint8_t* target,
                 size_t targetRowBytes, bool swapRedBlue) {
  for (uint32_t row = 0; row < height; ++row) {
    const uint8_t* from = source + size_t(row) * width * 4;
    uint8_t* to = target + size_t(row) * targetRowBytes;
    for (uint32_t x = 0; x < width; ++x) {
      uint32_t pixel = 0;
      std::memcpy(&pixel, from + size_t(x) * 4, 4);
      if (swapRedBlue)
        pixel = (pixel & 0x0000ff00u) | ((pixel >> 16) & 0xffu) | ((pixel & 0xffu) << 16);
      pixel |= kOpaque;
      std::memcpy(to + size_t(x) * 4, &pixel, 4);
    }
  }
}

}  // namespace render
