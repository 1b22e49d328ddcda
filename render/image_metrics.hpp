#pragma once
// Error measures between two images of the same size (values in [0, 1], one channel).
#include <cstdint>
#include <vector>

namespace render {

double rootMeanSquareError(const std::vector<float>& expected, const std::vector<float>& actual);

// Mean structural similarity over 8x8 windows (stride 4), with the usual constants for data
// in [0, 1] (C1 = 0.01^2, C2 = 0.03^2). 1 for identical images.
double structuralSimilarity(const std::vector<float>& expected, const std::vector<float>& actual,
                            uint32_t width, uint32_t height);

}  // namespace render
