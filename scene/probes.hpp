#pragma once
// What the game asks the ray-gen shaders to measure for its rules, and what they count back:
// focus regions counted per pixel, and exposure sample points traced towards a light.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace scene {

struct FocusProbeDesc {
  uint32_t instance = 0;         // the scene instance that must be seen
  glm::vec2 region{0.2f, 0.2f};  // centred box, fractions of the image width and height
};

struct ExposurePoint {
  glm::vec3 position{0.0f};  // world space, already offset off its surface
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  bool oneSided = true;  // count the light only on the normal's side
};

// What an exposure probe counts: the luminance of what reaches the points (glass and mirror
// tints included), or for a colour sensor how far the light (its colour times the tints) is of
// that colour: the channel less the larger of the other two, so white light does not count.
enum class ExposureChannel : uint32_t { Luminance = 0, Red = 1, Green = 2, Blue = 3 };

struct ExposureProbeDesc {
  uint32_t light = 0;
  ExposureChannel channel = ExposureChannel::Luminance;
  bool onPlayerBody = false;          // the points are on the player's body, whose rays skip it
  std::vector<ExposurePoint> points;  // at most EXPOSURE_SAMPLES (64)
};

struct ProbeRequest {
  std::vector<FocusProbeDesc> focus;        // at most MAX_FOCUS_PROBES (16)
  std::vector<ExposureProbeDesc> exposure;  // at most MAX_EXPOSURE_PROBES (16)
};

// One frame's results, parallel to the request's vectors.
struct ProbeCounts {
  std::vector<uint32_t> focusPixels;             // region pixels whose path ended on the instance
  std::vector<uint32_t> focusRegionPixels;       // pixels in the region
  std::vector<uint32_t> exposureFixed;           // sum of visibility * exposureOne over the points
  std::vector<uint32_t> exposurePoints;          // points traced
  static constexpr uint32_t exposureOne = 1024;  // EXPOSURE_ONE

  float focusCoverage(size_t probe) const {
    return focusRegionPixels[probe] ? float(focusPixels[probe]) / float(focusRegionPixels[probe])
                                    : 0.0f;
  }
  float exposure(size_t probe) const {
    return exposurePoints[probe]
               ? float(exposureFixed[probe]) / float(uint64_t(exposurePoints[probe]) * exposureOne)
               : 0.0f;
  }
};

// The pixel box of a focus region in a width x height image: round(fraction x size) pixels
// (at least one), centred (the odd pixel goes to the right and bottom).
struct PixelBox {
  uint32_t x0, y0, x1, y1;  // x1, y1 one past
  uint32_t pixels() const { return (x1 - x0) * (y1 - y0); }
};
inline PixelBox focusPixelBox(glm::vec2 region, uint32_t width, uint32_t height) {
  auto span = [](float fraction, uint32_t size) {
    return std::clamp(uint32_t(std::lround(double(fraction) * size)), 1u, size);
  };
  const uint32_t boxWidth = span(region.x, width), boxHeight = span(region.y, height);
  const uint32_t x0 = (width - boxWidth) / 2, y0 = (height - boxHeight) / 2;
  return {x0, y0, x0 + boxWidth, y0 + boxHeight};
}

}  // namespace scene
