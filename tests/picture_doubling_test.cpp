#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "render/picture_doubling.hpp"

namespace {

struct Picture {
  uint32_t width, height;
  std::vector<uint8_t> rgba;
};

Picture randomPicture(uint32_t width, uint32_t height, uint32_t seed) {
  std::mt19937 random(seed);
  Picture picture{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
  for (uint8_t& byte : picture.rgba) byte = uint8_t(random() & 0xff);
  return picture;
}

// What a linear, clamp-to-edge sampler stretching the picture over twice its size computes for
// output pixel (x, y) and channel c, in bytes (not rounded).
double sampledTwice(const Picture& picture, uint32_t x, uint32_t y, uint32_t channel) {
  // The output pixel's centre in the source's texel space, less half a texel.
  const double u = (x + 0.5) / 2.0 - 0.5, v = (y + 0.5) / 2.0 - 0.5;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const double fu = u - u0, fv = v - v0;
  auto texel = [&](double tx, double ty) {
    const int64_t cx = std::clamp<int64_t>(int64_t(tx), 0, picture.width - 1);
    const int64_t cy = std::clamp<int64_t>(int64_t(ty), 0, picture.height - 1);
    return double(picture.rgba[(size_t(cy) * picture.width + size_t(cx)) * 4 + channel]);
  };
  return (1 - fu) * (1 - fv) * texel(u0, v0) + fu * (1 - fv) * texel(u0 + 1, v0) +
         (1 - fu) * fv * texel(u0, v0 + 1) + fu * fv * texel(u0 + 1, v0 + 1);
}

}  // namespace

// Every output pixel is the sampler's value rounded to the nearest byte, for sizes that take
// the vector loops, their scalar tails (odd widths) and the clamp at every edge; red and blue
// swapped for a B8G8R8A8 window; alpha 255.
TEST(PictureDoubling, doubling_gives_a_linear_samplers_values_rounded) {
  for (const auto& [width, height] :
       {std::pair<uint32_t, uint32_t>{1, 1}, {2, 1}, {3, 5}, {4, 2}, {7, 3}, {17, 9}, {64, 36}}) {
    const Picture picture = randomPicture(width, height, width * 131 + height);
    for (bool swapRedBlue : {false, true}) {
      const size_t rowBytes = size_t(width) * 8;
      std::vector<uint8_t> doubled(rowBytes * height * 2);
      render::doublePicture(picture.rgba.data(), width, height, doubled.data(), rowBytes,
                            swapRedBlue);
      for (uint32_t y = 0; y < 2 * height; ++y) {
        for (uint32_t x = 0; x < 2 * width; ++x) {
          const uint8_t* pixel = doubled.data() + y * rowBytes + x * 4;
          for (uint32_t channel = 0; channel < 3; ++channel) {
            const uint32_t target = swapRedBlue && channel != 1 ? 2 - channel : channel;
            const double expected = std::floor(sampledTwice(picture, x, y, channel) + 0.5);
            ASSERT_EQ(pixel[target], uint8_t(expected))
                << width << "x" << height << " at (" << x << ", " << y << ") channel " << channel
                << (swapRedBlue ? " swapped" : "");
          }
          ASSERT_EQ(pixel[3], 255);
        }
      }
    }
  }
}

// A target wider than the doubled picture: each row starts targetRowBytes after the last, and
// the bytes past a row's end stay as they were.
TEST(PictureDoubling, rows_land_a_stride_apart_and_leave_the_rest) {
  const Picture picture = randomPicture(5, 3, 7);
  const size_t rowBytes = 5 * 8, stride = rowBytes + 12;
  std::vector<uint8_t> packed(rowBytes * 6), strided(stride * 6, 0xab);
  render::doublePicture(picture.rgba.data(), 5, 3, packed.data(), rowBytes, false);
  render::doublePicture(picture.rgba.data(), 5, 3, strided.data(), stride, false);
  for (size_t row = 0; row < 6; ++row) {
    EXPECT_TRUE(std::equal(packed.begin() + row * rowBytes, packed.begin() + (row + 1) * rowBytes,
                           strided.begin() + row * stride));
    EXPECT_TRUE(std::all_of(strided.begin() + row * stride + rowBytes,
                            strided.begin() + (row + 1) * stride,
                            [](uint8_t byte) { return byte == 0xab; }));
  }
}

// Bands doubled separately (as two threads do) give the whole picture's rows, each band reading
// the rows beyond its edges.
TEST(PictureDoubling, bands_doubled_apart_give_the_whole_picture) {
  const Picture picture = randomPicture(9, 7, 5);
  const size_t rowBytes = 9 * 8;
  std::vector<uint8_t> whole(rowBytes * 14), banded(rowBytes * 14);
  render::doublePicture(picture.rgba.data(), 9, 7, whole.data(), rowBytes, true);
  std::vector<uint16_t> scratch(render::doublingScratchSize(9));
  for (uint32_t split = 0; split <= 7; ++split) {
    std::fill(banded.begin(), banded.end(), uint8_t(0));
    render::doublePictureRows(picture.rgba.data(), 9, 7, split, 7, banded.data(), rowBytes, true,
                              scratch);
    render::doublePictureRows(picture.rgba.data(), 9, 7, 0, split, banded.data(), rowBytes, true,
                              scratch);
    EXPECT_EQ(banded, whole) << "split at source row " << split;
  }
}

TEST(PictureDoubling, a_copy_keeps_each_pixel_with_its_channels_in_the_windows_order) {
  const Picture picture = randomPicture(3, 2, 11);
  for (bool swapRedBlue : {false, true}) {
    std::vector<uint8_t> copied(3 * 2 * 4);
    render::copyPicture(picture.rgba.data(), 3, 2, copied.data(), 3 * 4, swapRedBlue);
    for (size_t pixel = 0; pixel < 6; ++pixel) {
      const uint8_t* from = picture.rgba.data() + pixel * 4;
      const uint8_t* to = copied.data() + pixel * 4;
      EXPECT_EQ(to[0], swapRedBlue ? from[2] : from[0]);
      EXPECT_EQ(to[1], from[1]);
      EXPECT_EQ(to[2], swapRedBlue ? from[0] : from[2]);
      EXPECT_EQ(to[3], 255);
    }
  }
}
