// The Catmull-Rom cubic (Keys 1981, a = -1/2): an interpolating kernel,
// C1, support |t| < 2, that reproduces polynomials up to degree 2. So for
// any t, sum_n phi(t - n) (n - t)^k = 1, 0, 0 for k = 0, 1, 2: spreading a
// point at t onto the integer nodes with these weights, or interpolating
// from them, keeps its energy, centroid and second moments.
#pragma once
#include <cmath>

namespace eoir::sensor {

inline double catmull_rom(double t) {
  const double a = std::abs(t);
  if (a < 1.0) return (1.5 * a - 2.5) * a * a + 1.0;
  if (a < 2.0) return ((-0.5 * a + 2.5) * a - 4.0) * a + 2.0;
  return 0.0;
}

// The weights of nodes -1, 0, 1, 2 for a point at f in [0, 1) between nodes
// 0 and 1: phi(f + 1), phi(f), phi(1 - f), phi(2 - f).
inline void catmull_rom_weights(double f, double w[4]) {
  const double g = 1.0 - f;
  w[0] = -0.5 * f * g * g;
  w[1] = 0.5 * ((3.0 * f - 5.0) * f * f + 2.0);
  w[2] = 0.5 * ((-3.0 * f + 4.0) * f * f + f);
  w[3] = -0.5 * f * f * g;
}

}  // namespace eoir::sensor
