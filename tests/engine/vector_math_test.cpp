// core/vector_math.hpp: glibc's vector maths (or libm where the processor
// lacks AVX2) within 4 ulp of libm's scalar functions, glibc's stated bound
// for both (so within 8 ulp of each other, and of the correctly rounded
// value), over the arguments the scene gives them and past them; every array
// length (the last 1-3 elements go through a padded block) and lanes that do
// not see each other's arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/vector_math.hpp"

namespace {

namespace vm = eoir::vector_math;

// |a - b| in units of b's last place (0 when both are the same, including infinities).
double ulps(double a, double b) {
  if (a == b) return 0.0;
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  const double ulp = std::nextafter(std::fabs(b), std::numeric_limits<double>::infinity()) - std::fabs(b);
  return std::fabs(a - b) / ulp;
}

TEST(VectorMath, Atan2WithinFourUlpOfLibm) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> y, x;
  // Every quadrant at the scales the scene gives (body-frame metres, the
  // geodetic latitude's a^2 z and c^2 rho ~ 1e20), the axes, tiny arguments.
  for (double scale : {1e-300, 1e-3, 1.0, 6.4e6, 2.6e20, 1e300})
    for (int k = 0; k < 20000; ++k) {
      y.push_back(scale * u(rng));
      x.push_back(scale * u(rng));
    }
  for (double a : {0.0, 1.0, -1.0, 6378137.0, -6378137.0})
    for (double b : {0.0, 1.0, -1.0, 6378137.0, -6378137.0}) {
      y.push_back(a);
      x.push_back(b);
    }
  std::vector<double> out(y.size());
  vm::atan2(y.data(), x.data(), out.data(), y.size());
  double worst = 0;
  for (std::size_t i = 0; i < y.size(); ++i) worst = std::max(worst, ulps(out[i], std::atan2(y[i], x[i])));
  EXPECT_LE(worst, 4.0);
}

TEST(VectorMath, ExpAndCosWithinFourUlpOfLibm) {
  std::mt19937_64 rng(11);
  std::vector<double> x;
  // exp: the temperatures' night decay (-n/k in [-40, 0]), the Planck
  // tables' log ratios (|x| < 1), the whole range to under- and overflow.
  std::uniform_real_distribution<double> decay(-40.0, 0.0), small(-1.0, 1.0), whole(-745.0, 709.0);
  for (int k = 0; k < 20000; ++k) {
    x.push_back(decay(rng));
    x.push_back(small(rng));
    x.push_back(whole(rng));
  }
  std::vector<double> out(x.size());
  vm::exp(x.data(), out.data(), x.size());
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, ulps(out[i], std::exp(x[i])));
  EXPECT_LE(worst, 4.0) << "exp";
  // cos: the diurnal cycle's pi (t - t_m) / w in about [-2 pi, 2 pi], and further out.
  x.clear();
  std::uniform_real_distribution<double> day(-7.0, 7.0), far(-1e5, 1e5);
  for (int k = 0; k < 30000; ++k) {
    x.push_back(day(rng));
    x.push_back(far(rng));
  }
  out.assign(x.size(), 0.0);
  vm::cos(x.data(), out.data(), x.size());
  worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    // (near a zero of cos, ulps of the result's own tiny size: 4 ulp of 1 there)
    const double ref = std::cos(x[i]);
    worst = std::max(worst, std::min(ulps(out[i], ref), std::fabs(out[i] - ref) / std::numeric_limits<double>::epsilon()));
  }
  EXPECT_LE(worst, 4.0) << "cos";
}

TEST(VectorMath, EveryLengthGivesEachElementItsOwnValue) {
  // An element's value does not depend on the array's length or on its
  // neighbours (the padded last block repeats the last argument).
  const std::vector<double> y{0.3, -2.0, 5.0, -0.1, 7.5, 1e-9, -3.0, 2.5, 0.0},
      x{1.0, -0.5, 2.0, -4.0, 0.25, -1e-9, 6.0, -2.0, -1.0};
  std::vector<double> whole(y.size()), whole_exp(y.size()), whole_cos(y.size());
  vm::atan2(y.data(), x.data(), whole.data(), y.size());
  vm::exp(y.data(), whole_exp.data(), y.size());
  vm::cos(y.data(), whole_cos.data(), y.size());
  for (std::size_t n = 0; n <= y.size(); ++n)
    for (std::size_t first = 0; first + n <= y.size(); ++first) {
      std::vector<double> a(n + 1, -7.0), e(n + 1, -7.0), c(n + 1, -7.0);
      vm::atan2(y.data() + first, x.data() + first, a.data(), n);
      vm::exp(y.data() + first, e.data(), n);
      vm::cos(y.data() + first, c.data(), n);
      for (std::size_t k = 0; k < n; ++k) {
        EXPECT_EQ(a[k], whole[first + k]) << "atan2 n " << n << " element " << first + k;
        EXPECT_EQ(e[k], whole_exp[first + k]) << "exp n " << n << " element " << first + k;
        EXPECT_EQ(c[k], whole_cos[first + k]) << "cos n " << n << " element " << first + k;
      }
      // nothing written past the n-th element
      EXPECT_EQ(a[n], -7.0);
      EXPECT_EQ(e[n], -7.0);
      EXPECT_EQ(c[n], -7.0);
    }
}

}  // namespace
