// The engine's worker threads: run_workers hands a job's workers 1..count-1
// to threads kept waiting between jobs, so a parallel loop costs a wake-up
// (tens of microseconds) rather than a thread's creation (50-130 us on the
// 2-core benchmark machine, against stages of 0.3-5 ms). One job runs on the
// pool at a time: a job started meanwhile (from another host thread, or
// nested inside a worker) gets threads of its own, as does a process forked
// from one that made the pool.
#pragma once
#include <functional>

namespace eoir {

// Runs worker(t) for t in [1, count) on other threads and worker(0) on the
// calling thread; returns when all have returned. worker must not throw.
void run_on_worker_threads(unsigned count, const std::function<void(unsigned)>& worker);

}  // namespace eoir
