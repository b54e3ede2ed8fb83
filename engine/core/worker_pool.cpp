#include "core/worker_pool.hpp"

#include <unistd.h>

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace eoir {
namespace {

// Set on the pool's threads and on a thread running worker 0 of a pool job:
// a loop started there gets threads of its own (the pool is busy with it).
thread_local bool in_pool_job = false;

class WorkerPool {
 public:
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  const pid_t owner = ::getpid();  // a forked child has none of these threads

  // False (and nothing run) when the pool is running another job.
  bool try_run(unsigned count, const std::function<void(unsigned)>& worker) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (threads_.size() + 1 < count) {
        const auto index = static_cast<unsigned>(threads_.size()) + 1;
        threads_.emplace_back([this, index] { serve(index); });
      }
      job_ = &worker;
      job_count_ = count;
      remaining_ = count - 1;
      ++generation_;
    }
    wake_.notify_all();
    in_pool_job = true;
    worker(0);
    in_pool_job = false;
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return remaining_ == 0; });
    job_ = nullptr;
    return true;
  }

 private:
  void serve(unsigned index) {
    in_pool_job = true;
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      if (index >= job_count_) continue;
      const std::function<void(unsigned)>* job = job_;
      lock.unlock();
      (*job)(index);
      lock.lock();
      if (--remaining_ == 0) done_.notify_one();
    }
  }

  std::mutex busy_;   // held by the job running
  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  const std::function<void(unsigned)>* job_ = nullptr;
  unsigned job_count_ = 0, remaining_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
};

WorkerPool& pool() {
  static WorkerPool instance;
  return instance;
}

void run_on_new_threads(unsigned count, const std::function<void(unsigned)>& worker) {
  std::vector<std::thread> threads;
  threads.reserve(count - 1);
  for (unsigned t = 1; t < count; ++t) threads.emplace_back(worker, t);
  worker(0);
  for (std::thread& t : threads) t.join();
}

}  // namespace

void run_on_worker_threads(unsigned count, const std::function<void(unsigned)>& worker) {
  if (count <= 1) {
    worker(0);
    return;
  }
  if (in_pool_job || pool().owner != ::getpid() || !pool().try_run(count, worker))
    run_on_new_threads(count, worker);
}

}  // namespace eoir
