#include "play/dynamic_scale.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace play {
namespace {
// Below this share of the target the picture grows again. The band between it and the target
// is where the scale rests: a frame costs a fixed part (present, input, the upscale's resolve)
// plus the traced pixels, so one step changes the time by less than the band is wide.
constexpr double kGrowBelow = 0.88;
constexpr float kShrinkStepMin = 0.7f;  // a step takes at most 30 % off each side
constexpr float kShrinkStepMax = 0.97f;
constexpr float kGrowStepMax = 1.06f;  // growing is gentler: too far means a slow frame
constexpr float kScaleGrid = 64.0f;    // scales are multiples of 1/64: no creeping sizes
constexpr uint32_t kMinSide = 16;

// The frame rate a player sees is frames over time, so the mean decides; the longest frame of a
// window is left out (a one-off hitch: a level's first compile, a window manager's pause).
double meanWithoutLongest(const std::vector<double>& values) {
  const double longest = *std::max_element(values.begin(), values.end());
  return (std::accumulate(values.begin(), values.end(), 0.0) - longest) / double(values.size() - 1);
}
}  // namespace

DynamicScale::DynamicScale(uint32_t renderWidth, uint32_t renderHeight)
    : renderWidth_(renderWidth), renderHeight_(renderHeight) {
  window_.reserve(kFramesPerDecision);
}

bool DynamicScale::frameFinished(double milliseconds) {
  if (++framesSeen_ <= kWarmUpFrames) return false;
  window_.push_back(milliseconds);
  if (window_.size() < kFramesPerDecision) return false;
  const double typical = meanWithoutLongest(window_);
  window_.clear();
  float next = scale_;
  // The traced part of a frame goes with the pixels, the scale's square.
  const float fit = float(std::sqrt(kTargetMilliseconds / typical));
  if (typical > kTargetMilliseconds)
    next = scale_ * std::clamp(fit, kShrinkStepMin, kShrinkStepMax);
  else if (typical < kGrowBelow * kTargetMilliseconds)
    next = scale_ * std::min(fit * float(std::sqrt(kGrowBelow)), kGrowStepMax);
  next = std::clamp(std::round(next * kScaleGrid) / kScaleGrid, kMinScale, 1.0f);
  const PictureSize before = size();
  scale_ = next;
  return size() != before;
}

PictureSize DynamicScale::size() const {
  auto side = [this](uint32_t full) {
    return std::min(full, std::max(kMinSide, uint32_t(std::lround(float(full) * scale_))));
  };
  return {side(renderWidth_), side(renderHeight_)};
}

}  // namespace play
