#pragma once
// What a player feels of a run's frame times: the median and the slow tail (nearest-rank
// percentiles), as bench and play report them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace render {

struct FrameTimePercentiles {
  double p50 = 0.0, p95 = 0.0, p99 = 0.0, worst = 0.0;  // milliseconds

  // "p50 16.1  p95 18.0  p99 25.3  worst 40.2 ms"
  std::string text() const {
    char line[96];
    std::snprintf(line, sizeof line, "p50 %.2f  p95 %.2f  p99 %.2f  worst %.2f ms", p50, p95, p99,
                  worst);
    return line;
  }
};

// Nearest rank: the smallest time at least `percent` of the frames took no longer than.
inline FrameTimePercentiles frameTimePercentiles(std::vector<double> milliseconds) {
  FrameTimePercentiles result;
  if (milliseconds.empty()) return result;
  std::sort(milliseconds.begin(), milliseconds.end());
  auto rank = [&](double percent) {
    const double position = std::ceil(percent / 100.0 * double(milliseconds.size()));
    return milliseconds[std::size_t(std::max(position, 1.0)) - 1];
  };
  result.p50 = rank(50.0);
  result.p95 = rank(95.0);
  result.p99 = rank(99.0);
  result.worst = milliseconds.back();
  return result;
}

}  // namespace render
