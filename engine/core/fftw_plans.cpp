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
  fftw_plan get_c2r_2d(int rows, int cols, unsigned threads) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    return get(Key{Kind::c2r_2d, rows, cols, 0, static_cast<int>(threads)}, [&](unsigned flags) {
      ComplexBuffer c = complex_buffer(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols / 2 + 1));
      RealBuffer r = real_buffer(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
      fftw_plan_with_nthreads(static_cast<int>(threads));
      return fftw_plan_dft_c2r_2d(rows, cols, c.get(), r.get(), flags);
    });
  }
  fftw_plan get_row(bool forward, int n) {
    return get(Key{forward ? Kind::row_r2c : Kind::row_c2r, n, 1, 1, 1}, [&](unsigned flags) {
      ComplexBuffer c = complex_buffer(static_cast<std::size_t>(n / 2 + 1));
      double* real = reinterpret_cast<double*>(c.get());
      fftw_plan_with_nthreads(1);
      return forward ? fftw_plan_dft_r2c_1d(n, real, c.get(), flags) : fftw_plan_dft_c2r_1d(n, c.get(), real, flags);
    });
  }
  fftw_plan get_columns(int n, int count, int stride, int sign) {
    return get(Key{sign == FFTW_FORWARD ? Kind::columns_forward : Kind::columns_backward, n, count, stride, 1},
               [&](unsigned flags) {
                 ComplexBuffer c = complex_buffer(static_cast<std::size_t>(n) * static_cast<std::size_t>(stride));
                 fftw_plan_with_nthreads(1);
                 return fftw_plan_many_dft(1, &n, count, c.get(), nullptr, stride, 1, c.get(), nullptr, stride, 1,
                                           sign, flags);
               });
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
  enum class Kind { c2r_2d, row_r2c, row_c2r, columns_forward, columns_backward };
  using Key = std::tuple<Kind, int, int, int, int>;  // kind and its sizes, the thread count last
  // The plan for key, made by make(flags) on first request.
  template <class Make>
  fftw_plan get(const Key& key, Make&& make) {
    requests.fetch_add(1, std::memory_order_relaxed);
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = plans_.find(key);
    if (it != plans_.end()) return it->second;
    fftw_plan plan = make(wisdom_path_.empty() ? FFTW_ESTIMATE : FFTW_MEASURE);
    if (!plan)
      throw Error(Status::internal, "fft: FFTW could not plan a transform of size " + std::to_string(std::get<1>(key)) +
                                        " x " + std::to_string(std::get<2>(key)));
    plans_.emplace(key, plan);
    if (!wisdom_path_.empty()) save_wisdom();
    return plan;
  }
  std::mutex mutex_;
  std::map<Key, fftw_plan> plans_;
};
}  // namespace

fftw_plan c2r_2d(int rows, int cols, unsigned threads) { return Cache::instance().get_c2r_2d(rows, cols, threads); }
fftw_plan row_r2c(int n) { return Cache::instance().get_row(true, n); }
fftw_plan row_c2r(int n) { return Cache::instance().get_row(false, n); }
fftw_plan columns(int n, int count, int stride, int sign) {
  return Cache::instance().get_columns(n, count, stride, sign);
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
