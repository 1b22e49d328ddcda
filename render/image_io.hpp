#pragma once
// RGBA8 images on disk (PNG) and their comparison.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace render {

struct Rgba8Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;  // rows top to bottom, 4 bytes a pixel
};

// Throws RenderError with the path on failure.
void writePng(const std::filesystem::path& path, const Rgba8Image& image);
Rgba8Image readPng(const std::filesystem::path& path);

struct ImageDifference {
  uint64_t differingPixels = 0;  // pixels where some channel differs by more than the tolerance
  uint64_t totalPixels = 0;
  int largestChannelDifference = 0;
  double differingFraction() const {
    return totalPixels ? double(differingPixels) / double(totalPixels) : 0.0;
  }
  Rgba8Image visualization;  // differing pixels red on a dimmed copy of `expected`
};

// Sizes must match (RenderError otherwise). Alpha is compared like the colour channels.
ImageDifference compareImages(const Rgba8Image& expected, const Rgba8Image& actual,
                              int channelTolerance);

}  // namespace render
