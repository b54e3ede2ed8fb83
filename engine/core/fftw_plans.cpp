#include "core/fftw_plans.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>

#include "core/error.hpp"

namespace eoir::fftw {
namespace {

std::atomic<std::uint64_t> requests{0};

class Cache {
 public:
  static Cache& instance() {
    static Cache cache;
    return cache;
  }
  fftw_plan get(bool forward, int rows, int cols, Placement placement, unsigned threads) {
    requests.fetch_add(1, std::memory_order_relaxed);
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    std::lock_guard<std::mutex> lock(mutex_);
    const auto key = std::make_tuple(forward, rows, cols, placement, threads);
    auto it = plans_.find(key);
    if (it != plans_.end()) return it->second;
    const std::size_t real_n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    const std::size_t complex_n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols / 2 + 1);
    ComplexBuffer c = complex_buffer(complex_n);
    RealBuffer r = placement == Placement::in_place ? nullptr : real_buffer(real_n);
    double* real = placement == Placement::in_place ? reinterpret_cast<double*>(c.get()) : r.get();
    fftw_plan_with_nthreads(static_cast<int>(threads));
    const unsigned flags = wisdom_path_.empty() ? FFTW_ESTIMATE : FFTW_MEASURE;
    fftw_plan plan = forward ? fftw_plan_dft_r2c_2d(rows, cols, real, c.get(), flags)
                             : fftw_plan_dft_c2r_2d(rows, cols, c.get(), real, flags);
    if (!plan)
      throw Error(Status::internal, "fft: FFTW could not plan a " + std::to_string(rows) + "x" +
                                        std::to_string(cols) + " transform");
    plans_.emplace(key, plan);
    if (!wisdom_path_.empty()) save_wisdom();
    return plan;
  }

 private:
  Cache() {
    fftw_init_threads();
    if (const char* path = std::getenv("EOIR_FFTW_WISDOM"); path && *path) {
      wisdom_path_ = path;
      // A cache: absent, unreadable or corrupt, it is planned anew and rewritten.
      fftw_import_wisdom_from_filename(path);
    }
  }
  // Written to a temporary file and renamed: a reader never sees half a file.
  void save_wisdom() const {
    const std::string temporary = wisdom_path_ + ".tmp" + std::to_string(::getpid());
    if (fftw_export_wisdom_to_filename(temporary.c_str()) && std::rename(temporary.c_str(), wisdom_path_.c_str()) == 0)
      return;
    std::remove(temporary.c_str());
  }
  std::string wisdom_path_;  // EOIR_FFTW_WISDOM: plans measured (FFTW_MEASURE) and kept there
  ~Cache() {
    for (auto& entry : plans_) fftw_destroy_plan(entry.second);
  }
  std::mutex mutex_;
  std::map<std::tuple<bool, int, int, Placement, unsigned>, fftw_plan> plans_;
};
}  // namespace

fftw_plan r2c_2d(int rows, int cols, Placement placement, unsigned threads) {
  return Cache::instance().get(true, rows, cols, placement, threads);
}
fftw_plan c2r_2d(int rows, int cols, Placement placement, unsigned threads) {
  return Cache::instance().get(false, rows, cols, placement, threads);
}
std::uint64_t plan_requests() { return requests.load(std::memory_order_relaxed); }

int good_size(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int k = m;
    for (int f : {2, 3, 5, 7})
      while (k % f == 0) k /= f;
    if (k == 1) return m;
  }
}
}  // namespace eoir::fftw
