// find_access (plugin_host/cli/access.hpp): stepping and bisection to the
// millisecond on a synthetic predicate, without the engine.
#include <gtest/gtest.h>

#include <vector>

#include "access.hpp"

using eoir::cli::AccessResult;
using eoir::cli::find_access;

namespace {
std::vector<int64_t> grid(int64_t t0, int64_t t1, int64_t dt) {
  std::vector<int64_t> t;
  for (int64_t x = t0; x <= t1; x += dt) t.push_back(x);
  if (t.back() < t1) t.push_back(t1);
  return t;
}
}  // namespace

TEST(Access, BoundariesToTheMillisecondAndClipping) {
  // Inside on [0, 12345] (clipped at the start), [100001, 250000] and
  // [590000, 600000] (clipped at the stop); steps of 60 s.
  const auto inside = [](int64_t t) {
    return t <= 12345 || (t >= 100001 && t <= 250000) || t >= 590000;
  };
  const AccessResult r = find_access(grid(0, 600000, 60000), inside);
  ASSERT_EQ(r.intervals.size(), 3u);
  EXPECT_EQ(r.intervals[0].start_ms, 0);
  EXPECT_EQ(r.intervals[0].stop_ms, 12345);
  EXPECT_EQ(r.intervals[1].start_ms, 100001);
  EXPECT_EQ(r.intervals[1].stop_ms, 250000);
  EXPECT_EQ(r.intervals[2].start_ms, 590000);
  EXPECT_EQ(r.intervals[2].stop_ms, 600000);
  // 11 samples plus at most 16 bisections (60000 ms -> 1 ms) per boundary.
  EXPECT_LE(r.evaluations, 11u + 4u * 16u);
}

TEST(Access, NeverAndAlways) {
  EXPECT_TRUE(find_access(grid(0, 1000, 100), [](int64_t) { return false; }).intervals.empty());
  const AccessResult all = find_access(grid(0, 1050, 100), [](int64_t) { return true; });
  ASSERT_EQ(all.intervals.size(), 1u);
  EXPECT_EQ(all.intervals[0].start_ms, 0);
  EXPECT_EQ(all.intervals[0].stop_ms, 1050);
  EXPECT_EQ(all.evaluations, 12u);
}

TEST(Access, ProgressAndBadGrid) {
  std::size_t sampled = 0, refined = 0;
  find_access(grid(0, 1000, 100), [](int64_t t) { return t > 333; },
              [&](const char* phase, std::size_t, std::size_t) { (phase[0] == 's' ? sampled : refined)++; });
  EXPECT_EQ(sampled, 11u);
  EXPECT_EQ(refined, 1u);
  EXPECT_THROW(find_access({0, 10, 10}, [](int64_t) { return true; }), std::invalid_argument);
}
