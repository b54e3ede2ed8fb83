#include "core/vector_math.hpp"

#include <cmath>

// (GCC only: clang's calls of the two-argument variant gave wrong lanes in
// the sanitizer build, so clang builds take libm.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define EOIR_LIBMVEC 1
// glibc's AVX2 variants (x86_64 vector function ABI, 'd' = AVX2, 4 lanes).
extern "C" __attribute__((target("avx2,fma"))) __m256d _ZGVdN4vv_atan2(__m256d, __m256d);
extern "C" __attribute__((target("avx2,fma"))) __m256d _ZGVdN4v_exp(__m256d);
extern "C" __attribute__((target("avx2,fma"))) __m256d _ZGVdN4v_cos(__m256d);
#endif

namespace eoir::vector_math {

namespace {

#ifdef EOIR_LIBMVEC
const bool kHasAvx2 = [] {
  __builtin_cpu_init();  // (this may run before the library's own initialisers)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}();

enum class Unary { exp, cos };

template <Unary kF>
__attribute__((target("avx2,fma"))) inline __m256d apply4(__m256d v) {
  return kF == Unary::exp ? _ZGVdN4v_exp(v) : _ZGVdN4v_cos(v);
}

// Four lanes at a time; the last 1-3 elements through a padded block (the
// pad repeats the last element, so no lane sees an argument the caller did
// not give).
template <Unary kF>
__attribute__((target("avx2,fma"))) void unary_avx2(const double* x, double* out, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(out + i, apply4<kF>(_mm256_loadu_pd(x + i)));
  if (i == n) return;
  alignas(32) double a[4], r[4];
  for (std::size_t k = 0; k < 4; ++k) a[k] = x[i + k < n ? i + k : n - 1];
  _mm256_store_pd(r, apply4<kF>(_mm256_load_pd(a)));
  for (std::size_t k = 0; i + k < n; ++k) out[i + k] = r[k];
}

__attribute__((target("avx2,fma"))) void atan2_avx2(const double* y, const double* x, double* out, std::size_t n) {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(out + i, _ZGVdN4vv_atan2(_mm256_loadu_pd(y + i), _mm256_loadu_pd(x + i)));
  if (i == n) return;
  alignas(32) double a[4], b[4], r[4];
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t j = i + k < n ? i + k : n - 1;
    a[k] = y[j];
    b[k] = x[j];
  }
  _mm256_store_pd(r, _ZGVdN4vv_atan2(_mm256_load_pd(a), _mm256_load_pd(b)));
  for (std::size_t k = 0; i + k < n; ++k) out[i + k] = r[k];
}
#endif

}  // namespace

void atan2(const double* y, const double* x, double* out, std::size_t n) {
#ifdef EOIR_LIBMVEC
  if (kHasAvx2) return atan2_avx2(y, x, out, n);
#endif
  for (std::size_t i = 0; i < n; ++i) out[i] = std::atan2(y[i], x[i]);
}

void exp(const double* x, double* out, std::size_t n) {
#ifdef EOIR_LIBMVEC
  if (kHasAvx2) return unary_avx2<Unary::exp>(x, out, n);
#endif
  for (std::size_t i = 0; i < n; ++i) out[i] = std::exp(x[i]);
}

void cos(const double* x, double* out, std::size_t n) {
#ifdef EOIR_LIBMVEC
  if (kHasAvx2) return unary_avx2<Unary::cos>(x, out, n);
#endif
  for (std::size_t i = 0; i < n; ++i) out[i] = std::cos(x[i]);
}

}  // namespace eoir::vector_math
