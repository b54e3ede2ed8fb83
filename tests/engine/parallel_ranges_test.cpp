// core/parallel_ranges.hpp: ranges cover [0, n) once, in range order, and an
// exception thrown on any worker reaches the caller after every worker has
// finished (none escapes a thread, which would end the process).
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "core/parallel_ranges.hpp"

namespace {

TEST(ParallelRanges, IndexedRangesCoverTheLoopOnceInOrder) {
  for (std::int64_t n : {1, 2, 7, 4097, 8195, 100000})
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      const unsigned count = eoir::parallel_range_count(n, threads, 1000);
      std::vector<std::pair<std::int64_t, std::int64_t>> ranges(count, {-1, -1});
      eoir::parallel_indexed_ranges(
          n, threads, [&](unsigned t, std::int64_t b, std::int64_t e) { ranges[t] = {b, e}; }, 1000);
      std::int64_t next = 0;
      for (const auto& r : ranges) {
        EXPECT_EQ(r.first, next) << n << " " << threads;
        next = r.second;
      }
      EXPECT_EQ(next, n) << n << " " << threads;
    }
}

TEST(ParallelRanges, AWorkersExceptionReachesTheCaller) {
  for (unsigned threads : {1u, 2u, 4u}) {
    std::atomic<int> finished{0};
    EXPECT_THROW(eoir::parallel_ranges(
                     1 << 16, threads,
                     [&](std::int64_t b, std::int64_t) {
                       if (b > 0 || threads == 1) throw std::runtime_error("range failed");
                       ++finished;
                     },
                     1),
                 std::runtime_error)
        << threads;
    EXPECT_EQ(finished.load(), threads == 1 ? 0 : 1) << threads;
  }
}

}  // namespace
