#include <gtest/gtest.h>

#include "render/image_metrics.hpp"

TEST(ImageMetrics, rmse_of_a_constant_offset_is_the_offset) {
  const std::vector<float> a(64, 0.25f), b(64, 0.5f);
  EXPECT_DOUBLE_EQ(render::rootMeanSquareError(a, a), 0.0);
  EXPECT_NEAR(render::rootMeanSquareError(a, b), 0.25, 1e-9);
}

TEST(ImageMetrics, ssim_is_one_for_identical_and_lower_for_noisy_images) {
  std::vector<float> gradient(16 * 16), noisy(16 * 16);
  for (size_t i = 0; i < gradient.size(); ++i) {
    gradient[i] = float(i % 16) / 15.0f;
    noisy[i] = gradient[i] + ((i * 7919) % 5 == 0 ? 0.3f : -0.05f);
  }
  EXPECT_NEAR(render::structuralSimilarity(gradient, gradient, 16, 16), 1.0, 1e-12);
  const double similarity = render::structuralSimilarity(gradient, noisy, 16, 16);
  EXPECT_LT(similarity, 0.95);
  EXPECT_GT(similarity, 0.0);
}

TEST(ImageMetrics, mismatched_sizes_are_refused) {
  EXPECT_THROW(render::rootMeanSquareError({0.0f}, {0.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(render::structuralSimilarity(std::vector<float>(4), std::vector<float>(4), 2, 2),
               std::invalid_argument);
}
