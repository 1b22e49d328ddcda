// Frame-time percentiles as bench and play print them: nearest rank.
#include <vector>

#include <gtest/gtest.h>

#include "render/frame_time_percentiles.hpp"

namespace {

TEST(FrameTimePercentiles, nearest_rank_of_one_to_a_hundred) {
  std::vector<double> times;
  for (int i = 100; i >= 1; --i) times.push_back(i);  // order does not matter
  const render::FrameTimePercentiles result = render::frameTimePercentiles(times);
  EXPECT_EQ(result.p50, 50.0);
  EXPECT_EQ(result.p95, 95.0);
  EXPECT_EQ(result.p99, 99.0);
  EXPECT_EQ(result.worst, 100.0);
  EXPECT_EQ(result.text(), "p50 50.00  p95 95.00  p99 99.00  worst 100.00 ms");
}

TEST(FrameTimePercentiles, one_hitch_in_a_short_run_is_the_tail) {
  const render::FrameTimePercentiles result =
      render::frameTimePercentiles({16.0, 17.0, 16.5, 80.0, 16.2});
  EXPECT_EQ(result.p50, 16.5);
  EXPECT_EQ(result.p95, 80.0);  // ceil(0.95 * 5) = 5th of 5
  EXPECT_EQ(result.worst, 80.0);
  EXPECT_EQ(render::frameTimePercentiles({}).worst, 0.0);
}

}  // namespace
