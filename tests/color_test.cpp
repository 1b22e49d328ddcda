#include <gtest/gtest.h>

#include "scene/color.hpp"

TEST(Srgb, encodes_known_values) {
  EXPECT_NEAR(scene::linearToSrgb(0.5f), 0.735357f, 1e-6f);
  EXPECT_NEAR(scene::linearToSrgb(0.0031308f), 0.0404499f, 1e-6f);
  EXPECT_FLOAT_EQ(scene::linearToSrgb(0.0f), 0.0f);
  EXPECT_NEAR(scene::linearToSrgb(1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(scene::linearToSrgb(0.001f), 0.01292f, 1e-7f);  // linear segment
}

TEST(Srgb, decodes_known_values) {
  EXPECT_NEAR(scene::srgbToLinear(0.735357f), 0.5f, 1e-6f);
  EXPECT_NEAR(scene::srgbToLinear(0.0404499f), 0.0031308f, 1e-7f);
  EXPECT_NEAR(scene::srgbToLinear(0.5f), 0.2140411f, 1e-6f);
}

TEST(Srgb, round_trips_every_byte) {
  for (int byte = 0; byte < 256; ++byte) {
    const float encoded = float(byte) / 255.0f;
    EXPECT_NEAR(scene::linearToSrgb(scene::srgbToLinear(encoded)), encoded, 1e-5f) << byte;
  }
}
