// core/parallel_ranges.hpp: ranges cover [0, n) once, in range order, chunks
// cover it once, and an exception thrown on any worker reaches the caller
// after every worker has finished (none escapes a thread, which would end the
// process). core/worker_pool.hpp: workers are kept between loops; a loop
// nested in a worker, loops from two host threads at once and a loop in a
// forked child all run to the end.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
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

TEST(ParallelRanges, ChunksCoverTheLoopOnce) {
  for (std::int64_t n : {1, 7, 64, 1001})
    for (unsigned threads : {1u, 2u, 5u})
      for (std::int64_t chunk : {1, 4, 16}) {
        std::vector<std::atomic<int>> visits(static_cast<std::size_t>(n));
        std::atomic<bool> thread_in_range{true};
        const unsigned count = eoir::parallel_range_count(n, threads, chunk);
        eoir::parallel_chunks(n, threads, chunk, [&](unsigned t, std::int64_t b, std::int64_t e) {
          if (t >= count || e - b > chunk || b % chunk != 0) thread_in_range = false;
          for (std::int64_t i = b; i < e; ++i) ++visits[static_cast<std::size_t>(i)];
        });
        EXPECT_TRUE(thread_in_range) << n << " " << threads << " " << chunk;
        for (const auto& v : visits) ASSERT_EQ(v.load(), 1) << n << " " << threads << " " << chunk;
      }
}

// Every worker runs; the second loop's workers are the first loop's threads.
TEST(WorkerPool, KeepsItsThreadsBetweenLoops) {
  std::set<std::thread::id> first, second;
  std::mutex m;
  for (auto* ids : {&first, &second})
    eoir::run_workers(3, [&](unsigned) {
      std::lock_guard<std::mutex> lock(m);
      ids->insert(std::this_thread::get_id());
    });
  EXPECT_EQ(first.size(), 3u);
  EXPECT_EQ(first, second);
}

TEST(WorkerPool, NestedAndConcurrentLoopsFinish) {
  std::atomic<int> inner{0};
  const auto nested = [&] {
    eoir::run_workers(2, [&](unsigned) { eoir::run_workers(2, [&](unsigned) { ++inner; }); });
  };
  std::thread other(nested);
  nested();
  other.join();
  EXPECT_EQ(inner.load(), 8);
}

TEST(WorkerPool, AForkedChildRunsLoops) {
  eoir::run_workers(2, [](unsigned) {});  // the parent's pool exists
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(20);  // a child waiting on the parent's threads would hang: end it instead
    std::atomic<int> ran{0};
    eoir::run_workers(2, [&](unsigned) { ++ran; });
    _exit(ran.load() == 2 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

}  // namespace
