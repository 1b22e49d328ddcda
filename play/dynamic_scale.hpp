#pragma once
// The dynamic render scale: holds a frame rate by tracing fewer pixels when frames run long
// (render::Renderer::setPictureSize) and more again when there is room. Probe frames keep the
// full render size, so it changes what the player sees, never what the rules read.
#include <cstdint>
#include <vector>

namespace play {

struct PictureSize {
  uint32_t width = 0;
  uint32_t height = 0;
  bool operator==(const PictureSize&) const = default;
};

class DynamicScale {
 public:
  // 32 fps: frames of a few milliseconds more (a probe frame, the X server's copy) then leave
  // 30 fps on average.
  static constexpr double kTargetMilliseconds = 1000.0 / 32.0;
  static constexpr float kMinScale = 0.5f;  // of the render size's width and height
  // Decisions are taken on the mean of this many frames, without the longest.
  static constexpr uint32_t kFramesPerDecision = 8;
  // Frames after a level starts that are not measured (pipeline compiles, first uploads).
  static constexpr uint32_t kWarmUpFrames = 6;

  // The full render size; the scale starts at 1.
  DynamicScale(uint32_t renderWidth, uint32_t renderHeight);

  // One shown frame's time (milliseconds, the whole loop less the wait for the display that
  // vsync adds). Returns true when the picture size changed.
  bool frameFinished(double milliseconds);

  float scale() const { return scale_; }
  PictureSize size() const;  // the render size times scale(), each side at least 16 pixels

 private:
  uint32_t renderWidth_;
  uint32_t renderHeight_;
  float scale_ = 1.0f;
  uint32_t framesSeen_ = 0;
  std::vector<double> window_;
};

}  // namespace play
