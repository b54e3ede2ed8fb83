// The heap bound of the fuzz targets (issue 25, item 5: a 64 MiB CSV whose
// header is commas cost 4.4 GB): the most heap an input may hold at once is
// a small multiple of its size. Measured with the sanitizer allocator's
// hooks, so in the sanitizer stage (build-asan) only; elsewhere the bound is
// not checked.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EOIR_FUZZ_HEAP_HOOKS 1
#include <sanitizer/allocator_interface.h>
#endif
#endif

namespace eoir_fuzz {

#ifdef EOIR_FUZZ_HEAP_HOOKS
namespace heap {
inline std::atomic<long long> live{0};
inline std::atomic<long long> peak{0};
inline void on_malloc(const volatile void*, std::size_t size) {
  const long long now = live += static_cast<long long>(size);
  long long high = peak.load();
  while (now > high && !peak.compare_exchange_weak(high, now)) {
  }
}
inline void on_free(const volatile void* p) {
  if (p != nullptr) live -= static_cast<long long>(__sanitizer_get_allocated_size(const_cast<const void*>(p)));
}
}  // namespace heap
#endif

// Runs f() (which may throw); aborts if the heap it held at its peak was more
// than factor * input_size + slack bytes.
template <class F>
void within_heap_bound(std::size_t input_size, double factor, std::size_t slack, F&& f) {
#ifdef EOIR_FUZZ_HEAP_HOOKS
  static const bool installed = __sanitizer_install_malloc_and_free_hooks(heap::on_malloc, heap::on_free) != 0;
  if (!installed) std::abort();
  const long long base = heap::live.load();
  heap::peak = base;
  const auto check = [&] {
    const long long held = heap::peak.load() - base;
    if (static_cast<double>(held) > factor * static_cast<double>(input_size) + static_cast<double>(slack)) {
      std::fprintf(stderr, "fuzz: %lld bytes of heap for %zu bytes of input (bound %g x + %zu)\n", held, input_size,
                   factor, slack);
      std::abort();
    }
  };
  try {
    f();
  } catch (...) {
    check();
    throw;
  }
  check();
#else
  (void)input_size, (void)factor, (void)slack;
  f();
#endif
}

}  // namespace eoir_fuzz
