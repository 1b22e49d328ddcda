#include "render/image_metrics.hpp"

#include <cmath>
#include <stdexcept>

namespace render {

double rootMeanSquareError(const std::vector<float>& expected, const std::vector<float>& actual) {
  if (expected.size() != actual.size() || expected.empty())
    throw std::invalid_argument("rootMeanSquareError: images differ in size or are empty");
  double sum = 0.0;
  for (size_t i = 0; i < expected.size(); ++i) {
    const double difference = double(expected[i]) - double(actual[i]);
    sum += difference * difference;
  }
  return std::sqrt(sum / double(expected.size()));
}

double structuralSimilarity(const std::vector<float>& expected, const std::vector<float>& actual,
                            uint32_t width, uint32_t height) {
  if (expected.size() != actual.size() || expected.size() != size_t(width) * height)
    throw std::invalid_argument("structuralSimilarity: images differ in size");
  constexpr uint32_t kWindow = 8, kStride = 4;
  constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  if (width < kWindow || height < kWindow)
    throw std::invalid_argument("structuralSimilarity: images smaller than the 8x8 window");
  double total = 0.0;
  uint32_t windows = 0;
  for (uint32_t top = 0; top + kWindow <= height; top += kStride) {
    for (uint32_t left = 0; left + kWindow <= width; left += kStride) {
      double meanA = 0, meanB = 0;
      for (uint32_t y = top; y < top + kWindow; ++y)
        for (uint32_t x = left; x < left + kWindow; ++x) {
          meanA += expected[size_t(y) * width + x];
          meanB += actual[size_t(y) * width + x];
        }
      const double n = kWindow * kWindow;
      meanA /= n, meanB /= n;
      double varianceA = 0, varianceB = 0, covariance = 0;
      for (uint32_t y = top; y < top + kWindow; ++y)
        for (uint32_t x = left; x < left + kWindow; ++x) {
          const double a = expected[size_t(y) * width + x] - meanA;
          const double b = actual[size_t(y) * width + x] - meanB;
          varianceA += a * a, varianceB += b * b, covariance += a * b;
        }
      varianceA /= n - 1, varianceB /= n - 1, covariance /= n - 1;
      total += ((2 * meanA * meanB + c1) * (2 * covariance + c2)) /
               ((meanA * meanA + meanB * meanB + c1) * (varianceA + varianceB + c2));
      ++windows;
    }
  }
  return total / windows;
}

}  // namespace render
