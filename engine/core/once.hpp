// std::call_once with a lock-free fast path, for work made once and then
// read per sample: after the first call, a call costs one acquire load
// (libstdc++'s std::call_once sets thread-locals and enters pthread_once on
// every call).
#pragma once
#include <atomic>
#include <mutex>

namespace eoir {

class OnceFlag {
 public:
  template <class F>
  void call(F&& fn) {
    if (done_.load(std::memory_order_acquire)) return;
    std::call_once(flag_, [&] {
      fn();
      done_.store(true, std::memory_order_release);
    });
  }

 private:
  std::once_flag flag_;
  std::atomic<bool> done_{false};
};

}  // namespace eoir
