// Process-wide FFTW plan cache. FFTW's planner is not thread-safe, so every
// plan in the engine is made here, under one mutex, once per shape, and kept
// for the life of the process; executing a kept plan on fresh aligned arrays
// (fftw_execute_dft_r2c / _c2r / fftw_execute_dft) is thread-safe. FFTW_ESTIMATE planning by
// default: FFTW_MEASURE costs 1-2 s per size and thread count. With the
// environment variable EOIR_FFTW_WISDOM naming a file, plans are measured
// (FFTW_MEASURE: the 256^2 frame's scene convolution 9.0 -> 6.8 ms on one
// core of the 2-core machine) and kept there as FFTW wisdom, read when the process first plans:
// each size is measured once per machine. The file is a cache (a corrupt or
// unreadable one is planned anew and rewritten, by a rename); transforms
// differ from estimated plans' by rounding only.
#pragma once
#include <fftw3.h>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace eoir::fftw {

// Complex-to-real 2-D plan of rows x cols real samples (row-major, the
// complex side rows x (cols/2 + 1)), out of place, on `threads` threads (0 =
// all cores).
fftw_plan c2r_2d(int rows, int cols, unsigned threads = 0);
// One-thread plans for transforms a caller splits among its own threads:
// - row_r2c / row_c2r: one row of n reals in place (the row padded to
//   2 (n/2 + 1) reals, its half spectrum n/2 + 1 complex values);
// - columns: `count` complex transforms of length n in place, element k of
//   transform j at offset j + k * stride (adjacent columns of a row-major
//   array `stride` complex values wide); sign FFTW_FORWARD or FFTW_BACKWARD.
// Executed on other arrays of the same layout with fftw_execute_dft_r2c /
// _c2r / fftw_execute_dft (16-byte aligned like every fftw_alloc array).
fftw_plan row_r2c(int n);
fftw_plan row_c2r(int n);
fftw_plan columns(int n, int count, int stride, int sign);
// How many plans the functions above have handed out in this process: the
// engine asks for its plans when a frame needs a transform, so tests can
// check that a frame does none it need not.
std::uint64_t plan_requests();

struct Free {
  void operator()(void* p) const { fftw_free(p); }
};
using RealBuffer = std::unique_ptr<double[], Free>;
using ComplexBuffer = std::unique_ptr<fftw_complex[], Free>;
inline RealBuffer real_buffer(std::size_t n) { return RealBuffer(fftw_alloc_real(n)); }
inline ComplexBuffer complex_buffer(std::size_t n) { return ComplexBuffer(fftw_alloc_complex(n)); }

// A size FFTW transforms quickly (only factors 2, 3, 5, 7) that is >= n.
int good_size(int n);

}  // namespace eoir::fftw
