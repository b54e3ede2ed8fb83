// Splits [0, n) into contiguous ranges, one per thread, and runs
// fn(begin, end) on each: the calling thread takes the first range. For
// loops whose iterations are independent (each writes its own outputs), so
// the result is the same for any thread count.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/worker_pool.hpp"

namespace eoir {

// Runs worker(t) for t in [0, count) on count threads (core/worker_pool.hpp),
// the calling thread taking t = 0, and rethrows on the calling thread the first exception a
// worker threw once all have finished (none escapes a worker thread).
template <class F>
void run_workers(unsigned count, F&& worker) {
  if (count <= 1) {
    worker(0u);
    return;
  }
  std::exception_ptr failure;
  std::mutex failure_mutex;
  run_on_worker_threads(count, [&](unsigned t) {
    try {
      worker(t);
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  });
  if (failure) std::rethrow_exception(failure);
}

// How many ranges parallel_ranges splits [0, n) into: threads (0 = all
// cores), fewer for small loops (fewer than min_per_thread iterations a thread).
inline unsigned parallel_range_count(std::int64_t n, unsigned threads, std::int64_t min_per_thread = 4096) {
  if (n <= 0) return 0;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const auto by_size = static_cast<unsigned>(std::max<std::int64_t>(1, n / std::max<std::int64_t>(1, min_per_thread)));
  return std::min(threads, by_size);
}

// fn(t, begin, end) on range t of parallel_range_count(n, threads,
// min_per_thread): for results kept per range, in range order.
template <class F>
void parallel_indexed_ranges(std::int64_t n, unsigned threads, F&& fn, std::int64_t min_per_thread = 4096) {
  const unsigned count = parallel_range_count(n, threads, min_per_thread);
  if (count == 0) return;
  run_workers(count, [&fn, n, count](unsigned t) { fn(t, n * t / count, n * (t + 1) / count); });
}

// fn(t, begin, end) on chunks of `chunk` iterations of [0, n), the threads
// taking the next chunk as they finish one (t: the thread, in [0,
// parallel_range_count(n, threads, chunk))): for loops whose iterations cost
// unevenly. Which thread takes a chunk varies from run to run, so each
// iteration must write only its own outputs.
template <class F>
void parallel_chunks(std::int64_t n, unsigned threads, std::int64_t chunk, F&& fn) {
  const unsigned count = parallel_range_count(n, threads, chunk);
  if (count == 0) return;
  std::atomic<std::int64_t> next{0};
  run_workers(count, [&](unsigned t) {
    for (std::int64_t begin; (begin = next.fetch_add(chunk, std::memory_order_relaxed)) < n;)
      fn(t, begin, std::min(n, begin + chunk));
  });
}

template <class F>
void parallel_ranges(std::int64_t n, unsigned threads, F&& fn, std::int64_t min_per_thread = 4096) {
  parallel_indexed_ranges(
      n, threads, [&fn](unsigned, std::int64_t begin, std::int64_t end) { fn(begin, end); }, min_per_thread);
}

}  // namespace eoir
