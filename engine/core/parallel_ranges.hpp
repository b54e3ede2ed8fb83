// Splits [0, n) into contiguous ranges, one per thread, and runs
// fn(begin, end) on each: the calling thread takes the first range. For
// loops whose iterations are independent (each writes its own outputs), so
// the result is the same for any thread count.
#pragma once
#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace eoir {

// threads 0 = all cores; small loops (fewer than min_per_thread iterations a
// thread) run on fewer threads.
template <class F>
void parallel_ranges(std::int64_t n, unsigned threads, F&& fn, std::int64_t min_per_thread = 4096) {
  if (n <= 0) return;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const auto by_size = static_cast<unsigned>(std::max<std::int64_t>(1, n / std::max<std::int64_t>(1, min_per_thread)));
  const unsigned count = std::min(threads, by_size);
  if (count <= 1) {
    fn(std::int64_t{0}, n);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(count - 1);
  for (unsigned t = 1; t < count; ++t)
    pool.emplace_back([&fn, n, t, count] { fn(n * t / count, n * (t + 1) / count); });
  fn(std::int64_t{0}, n / count);
  for (auto& th : pool) th.join();
}

}  // namespace eoir
