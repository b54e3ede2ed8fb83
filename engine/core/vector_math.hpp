// Elementary functions over arrays: glibc's vector maths (libmvec, four
// doubles at a time with AVX2 and FMA) where the processor has them and GCC
// built the engine, else libm element by element. Both are within 4 ulp of
// the correctly rounded value (glibc's bound), so a result differs between
// machines by rounding only. For the scene's per-sample chains (a tile's
// latitudes and temperatures): each costs a fifth of libm's scalar call.
#pragma once

#include <cstddef>

namespace eoir::vector_math {

// out[i] = atan2(y[i], x[i]), radians.
void atan2(const double* y, const double* x, double* out, std::size_t n);
// out[i] = exp(x[i]).
void exp(const double* x, double* out, std::size_t n);
// out[i] = cos(x[i]), x in radians.
void cos(const double* x, double* out, std::size_t n);

}  // namespace eoir::vector_math
