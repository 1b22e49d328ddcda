#include "render/image_io.hpp"

#include <algorithm>
#include <cstdlib>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "render/vulkan_error.hpp"

namespace render {

void writePng(const std::filesystem::path& path, const Rgba8Image& image) {
  if (image.pixels.size() != size_t(image.width) * image.height * 4)
    throw RenderError(path.string() + ": image data does not match its size");
  if (path.has_parent_path()) {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
  }
  const int stride = static_cast<int>(image.width * 4);
  if (!stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height),
                      4, image.pixels.data(), stride)) {
    throw RenderError(path.string() + ": cannot write PNG");
  }
}

Rgba8Image readPng(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!data) {
    throw RenderError(path.string() + ": cannot read PNG (" +
                      std::string(stbi_failure_reason() ? stbi_failure_reason() : "unknown") + ")");
  }
  Rgba8Image image;
  image.width = static_cast<uint32_t>(width);
  image.height = static_cast<uint32_t>(height);
  image.pixels.assign(data, data + size_t(width) * height * 4);
  stbi_image_free(data);
  return image;
}

ImageDifference compareImages(const Rgba8Image& expected, const Rgba8Image& actual,
                              int channelTolerance) {
  if (expected.width != actual.width || expected.height != actual.height) {
    throw RenderError("image sizes differ: expected " + std::to_string(expected.width) + "x" +
                      std::to_string(expected.height) + ", got " + std::to_string(actual.width) +
                      "x" + std::to_string(actual.height));
  }
  ImageDifference result;
  result.totalPixels = uint64_t(expected.width) * expected.height;
  result.visualization = expected;
  for (uint64_t pixel = 0; pixel < result.totalPixels; ++pixel) {
    int largest = 0;
    for (int channel = 0; channel < 4; ++channel) {
      const size_t at = pixel * 4 + channel;
      largest = std::max(largest, std::abs(int(expected.pixels[at]) - int(actual.pixels[at])));
    }
    result.largestChannelDifference = std::max(result.largestChannelDifference, largest);
    uint8_t* shown = &result.visualization.pixels[pixel * 4];
    if (largest > channelTolerance) {
      ++result.differingPixels;
      shown[0] = 255, shown[1] = 0, shown[2] = 0, shown[3] = 255;
    } else {
      for (int channel = 0; channel < 3; ++channel) shown[channel] = uint8_t(shown[channel] / 4);
      shown[3] = 255;
    }
  }
  return result;
}

}  // namespace render
