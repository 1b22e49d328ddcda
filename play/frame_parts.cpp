#include "play/frame_parts.hpp"

#include <cstdio>
#include <numeric>

#include "render/frame_time_percentiles.hpp"
#include "render/renderer.hpp"

namespace play {
namespace {

constexpr std::array<const char*, kFrameParts> kPartNames = {"input", "ticks", "picture",
                                                             "interface", "present"};

}  // namespace

void FramePartTimes::start(FramePart part) {
  const Clock::time_point now = Clock::now();
  if (running_ >= 0)
    current_[std::size_t(running_)] +=
        std::chrono::duration<double, std::milli>(now - startedAt_).count();
  running_ = int(part);
  startedAt_ = now;
}

void FramePartTimes::endFrame() {
  start(FramePart::Input);  // closes the running part
  running_ = -1;
  for (std::size_t part = 0; part < kFrameParts; ++part) {
    frames_[part].push_back(current_[part]);
    current_[part] = 0.0;
  }
}

std::string FramePartTimes::partsText(unsigned long long probeFrames) const {
  std::string text;
  char item[64];
  for (std::size_t part = 0; part < kFrameParts; ++part) {
    const std::vector<double>& times = frames_[part];
    const double mean =
        times.empty() ? 0.0 : std::accumulate(times.begin(), times.end(), 0.0) / times.size();
    std::snprintf(item, sizeof item, "%s%s %.2f / %.2f", part ? "  " : "", kPartNames[part],
                  render::frameTimePercentiles(times).p50, mean);
    text += item;
  }
  std::snprintf(item, sizeof item, " ms (median / mean of %zu frames; %llu probe frames)",
                frames_[0].size(), probeFrames);
  return text + item;
}

void FramePartTimes::recordPicture(const render::FrameStats& stats) {
  traceMs_.push_back(stats.gpu.traceMs);
  denoiseMs_.push_back(stats.gpu.denoiseMs);
  tonemapMs_.push_back(stats.gpu.tonemapMs);
  submitToFenceMs_.push_back(stats.milliseconds);
}

std::string FramePartTimes::pictureText() const {
  if (submitToFenceMs_.empty()) return "";
  auto median = [](const std::vector<double>& times) {
    return render::frameTimePercentiles(times).p50;
  };
  char text[192];
  std::snprintf(text, sizeof text,
                "picture passes: trace %.2f  denoise %.2f  tonemap and upscale %.2f  submit to "
                "fence %.2f ms (GPU medians, host median; %zu pictures)",
                median(traceMs_), median(denoiseMs_), median(tonemapMs_), median(submitToFenceMs_),
                submitToFenceMs_.size());
  return text;
}

}  // namespace play
