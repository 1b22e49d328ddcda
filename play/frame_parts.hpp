#pragma once
// Where the window's frames spend their time: each part's milliseconds in every frame, and
// their medians, which `play --quit-after-ticks N` prints when it quits; and where the picture
// part's time goes, each pass's GPU time and the host's wait from submit to fence.
#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace render {
struct FrameStats;
}

namespace play {

enum class FramePart {
  Input,      // window events, key presses, menu choices
  Ticks,      // the world's fixed ticks, with the probe frames they render
  Picture,    // the picture: trace, denoise, tonemap
  Interface,  // the HUD's and menus' ImGui frame
  Present,    // the window's pass (picture, HUD, overlay), a swapchain image's wait, present
};
inline constexpr std::size_t kFrameParts = 5;

class FramePartTimes {
 public:
  // Ends the part under way (if any) and starts `part`.
  void start(FramePart part);
  // Ends the part under way and closes the frame's record.
  void endFrame();
  // "input 0.05 / 0.06  ticks 0.10 / 2.40  picture 21.30 / 22.10  interface 0.40 / 0.41
  // present 3.20 / 3.30 ms (median / mean of 600 frames; 150 probe frames)"
  std::string partsText(unsigned long long probeFrames) const;
  // Records the times of the picture the frame rendered.
  void recordPicture(const render::FrameStats& stats);
  // "picture passes: trace 10.62  denoise 0.02  tonemap and upscale 3.66  submit to fence
  // 15.30 ms (GPU medians, host median; 448 pictures)", or "" before any picture. The GPU
  // medians are 0 where the device has no timestamps.
  std::string pictureText() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::array<double, kFrameParts> current_{};
  std::array<std::vector<double>, kFrameParts> frames_;
  std::vector<double> traceMs_, denoiseMs_, tonemapMs_, submitToFenceMs_;
  int running_ = -1;
  Clock::time_point startedAt_;
};

}  // namespace play
