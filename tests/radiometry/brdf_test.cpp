// Modified Phong BRDF with backscatter, spec 4.1.4.1 eq. 1, normalized so
// that every arriving photon is reflected (directional-hemispherical
// reflectance 1; SRF multiplies outside, spec 4.1.5.3 eq. 4).
#include "radiometry/brdf.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace r = eoir::radiometry;
using Eigen::Vector3d;

namespace {

constexpr double kPi = eoir::constants::pi;
constexpr double kDeg = eoir::constants::rad_per_deg;

// Gauss-Legendre rule on [-1, 1] by Newton iteration (the test's own).
struct Rule {
  std::vector<double> x, w;
  explicit Rule(int n) : x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n)) {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-15) break;
      }
      x[static_cast<std::size_t>(i)] = z;
      w[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

// Brute-force directional-hemispherical reflectance of value(): integral of
// BRDF cos(theta_o) dw over the hemisphere, in spherical coordinates
// (g, phi) about the mirror direction, independent of the class's tables.
// g: Gauss-Legendre panels, fine near the axis (narrow forward lobes) and
// 0.1 rad elsewhere (backscatter lobes, beta <= 20, are >= 0.12 rad wide),
// broken where rings start/stop being cut by the horizon. phi: each ring is
// integrated over its visible arc only (cos(theta_o) > 0, found from the
// geometry), with Gauss-Legendre, and doubled (mirror symmetry about the
// plane of incidence).
double brute_force_reflectance(const r::Brdf& brdf, double incidence_rad) {
  static const Rule g_rule(8), phi_rule(32);
  const Vector3d normal(0.0, 0.0, 1.0);
  const double si = std::sin(incidence_rad), ci = std::cos(incidence_rad);
  const Vector3d to_light(si, 0.0, ci);
  const Vector3d mirror(-si, 0.0, ci);
  const Vector3d e1(ci, 0.0, si), e2(0.0, 1.0, 0.0);  // completes (e1, e2, mirror)

  std::vector<double> breaks{0.0, 0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.25};
  for (double g = 0.3; g < kPi; g += 0.1) breaks.push_back(g);
  breaks.push_back(kPi);
  for (double kink : {0.5 * kPi - incidence_rad, 0.5 * kPi + incidence_rad}) {
    if (kink <= 0.0 || kink >= kPi) continue;
    for (std::size_t i = 1; i < breaks.size(); ++i)
      if (kink > breaks[i - 1] && kink < breaks[i]) {
        breaks.insert(breaks.begin() + static_cast<std::ptrdiff_t>(i), kink);
        break;
      }
  }

  double total = 0.0;
  for (std::size_t p = 1; p < breaks.size(); ++p) {
    const double g0 = breaks[p - 1], g1 = breaks[p];
    for (std::size_t i = 0; i < g_rule.x.size(); ++i) {
      const double g = 0.5 * (g0 + g1) + 0.5 * (g1 - g0) * g_rule.x[i];
      const double sg = std::sin(g), cg = std::cos(g);
      // cos(theta_o) = a cos(phi) + b on this ring.
      const double a = sg * e1.dot(normal), b = cg * mirror.dot(normal);
      double phi_max = kPi;
      if (b <= -std::abs(a)) continue;
      if (b < std::abs(a)) phi_max = std::acos(-b / a);
      double ring = 0.0;
      for (std::size_t j = 0; j < phi_rule.x.size(); ++j) {
        const double phi = 0.5 * phi_max * (1.0 + phi_rule.x[j]);
        const Vector3d v = sg * std::cos(phi) * e1 + sg * std::sin(phi) * e2 + cg * mirror;
        ring += phi_rule.w[j] * brdf.value(to_light, v, normal) * std::max(0.0, v.dot(normal));
      }
      total += 0.5 * (g1 - g0) * g_rule.w[i] * sg * 2.0 * 0.5 * phi_max * ring;
    }
  }
  return total;
}

Vector3d direction(double polar_rad, double azimuth_rad) {
  return {std::sin(polar_rad) * std::cos(azimuth_rad), std::sin(polar_rad) * std::sin(azimuth_rad),
          std::cos(polar_rad)};
}

}  // namespace

// Spec 4.1.4.1: "normalized such that reflected flux is conserved. Every
// arriving photon will be reflected": with SRF = 1 the directional-
// hemispherical reflectance of eq. 1 is 1 at every incidence angle.
TEST(Brdf, ReflectanceIsOneAtEveryIncidenceBruteForce) {
  std::vector<double> incidences_deg;
  for (int d = 0; d < 80; d += 4) incidences_deg.push_back(d);
  for (int d = 80; d <= 89; ++d) incidences_deg.push_back(d);  // grazing: lobes cut by the horizon
  double worst = 0.0;
  int cases = 0;
  for (double alpha : {0.0, 1.0, 5.0, 20.0, 60.0, 100.0})
    for (double beta : {0.0, 1.0, 5.0, 20.0})
      for (double k0 : {0.0, 0.3, 1.0})
        for (double k1 : {0.0, 0.5, 1.0}) {
          const r::Brdf brdf({k0, k1, alpha, beta});
          for (double incidence_deg : incidences_deg) {
            const double rho = brute_force_reflectance(brdf, incidence_deg * kDeg);
            worst = std::max(worst, std::abs(rho - 1.0));
            ++cases;
            EXPECT_NEAR(rho, 1.0, 0.005) << "k0 " << k0 << " k1 " << k1 << " alpha " << alpha << " beta " << beta
                                         << " incidence " << incidence_deg << " deg";
          }
        }
  std::cout << "[ brute force ] " << cases << " cases, worst |rho - 1| = " << worst << "\n";
}

TEST(Brdf, ClassReflectanceAndLobeIntegral) {
  // The class's own diagnostic agrees (interpolation error only).
  for (double alpha : {0.5, 20.0, 100.0, 1000.0}) {
    const r::Brdf brdf({0.2, 0.3, alpha, alpha / 4.0});
    for (double incidence_deg = 0.0; incidence_deg < 90.0; incidence_deg += 0.37)
      EXPECT_NEAR(brdf.directional_hemispherical_reflectance(incidence_deg * kDeg), 1.0, 1e-4);
    EXPECT_EQ(brdf.directional_hemispherical_reflectance(90.5 * kDeg), 0.0);  // light from below
  }
  // Normal incidence has a closed form: 2 pi integral_0^1 e^{kappa (x-1)} x dx.
  for (double kappa : {1e-9, 0.01, 1.0, 10.0, 314.159, 3141.59}) {
    const double exact = 2.0 * kPi * (1.0 / kappa + std::expm1(-kappa) / (kappa * kappa));
    if (kappa > 1e-6) {
      EXPECT_NEAR(r::cosine_weighted_lobe_integral(kappa, 1.0) / exact, 1.0, 1e-12) << kappa;
    }
  }
  EXPECT_EQ(r::cosine_weighted_lobe_integral(0.0, 0.3), kPi);
  EXPECT_NEAR(r::cosine_weighted_lobe_integral(1e-9, 0.3), kPi, 1e-8);
}

TEST(Brdf, LambertianIsExactlyOneOverPi) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const r::BrdfParameters& p :
       {r::BrdfParameters{}, r::BrdfParameters{1.0, 0.4, 60.0, 5.0}, r::BrdfParameters{1.0, 1.0, 1000.0, 1000.0},
        r::BrdfParameters{0.3, 0.5, 0.0, 0.0}}) {
    const r::Brdf brdf(p);
    EXPECT_TRUE(brdf.lambertian());
    for (int i = 0; i < 1000; ++i) {
      const Vector3d l = direction(std::acos(u(rng)), 2.0 * kPi * u(rng));
      const Vector3d v = direction(std::acos(u(rng)), 2.0 * kPi * u(rng));
      if (l.z() <= 0.0 || v.z() <= 0.0) continue;
      EXPECT_EQ(brdf.value(l, v, Vector3d::UnitZ()), 1.0 / kPi);
    }
  }
  EXPECT_FALSE(r::Brdf({0.999, 0.0, 1.0, 0.0}).lambertian());
}

// Eq. 1 taken literally with the spec's vectors: I from the source (into the
// surface), O to the sensor, R = N (2 I.N) - I. The directional part of
// value() is proportional to alpha e^{-pi alpha (O.R)} (resp.
// beta e^{-pi beta (I.O)}) at fixed incidence, and peaks at the mirror
// (resp. source) direction.
TEST(Brdf, LobesFollowEquationOneAndPeakWhereExpected) {
  const Vector3d N = Vector3d::UnitZ();
  for (double incidence_deg : {0.0, 20.0, 45.0, 70.0, 85.0}) {
    const Vector3d to_light = direction(incidence_deg * kDeg, 0.3);
    const Vector3d I = -to_light;
    const Vector3d R = N * (2.0 * I.dot(N)) - I;
    const Vector3d mirror = 2.0 * N * N.dot(to_light) - to_light;
    for (bool back : {false, true}) {
      const double sharpness = 20.0;
      const r::Brdf brdf({0.0, back ? 1.0 : 0.0, back ? 0.0 : sharpness, back ? sharpness : 0.0});
      const Vector3d axis = back ? to_light : mirror;
      auto eq1_lobe = [&](const Vector3d& O) {
        return back ? sharpness * std::exp(-kPi * sharpness * (I.dot(O) + 1.0))
                    : sharpness * std::exp(-kPi * sharpness * (O.dot(R) + 1.0));  // e^{-pi s} scaled out
      };
      double best = -1.0, scale = 0.0;
      Vector3d best_direction = Vector3d::Zero();
      for (double polar_deg = 0.25; polar_deg < 90.0; polar_deg += 0.5)
        for (double azimuth_deg = 0.0; azimuth_deg < 360.0; azimuth_deg += 0.5) {
          const Vector3d O = direction(polar_deg * kDeg, azimuth_deg * kDeg);
          const double value = brdf.value(to_light, O, N);
          if (value > best) {
            best = value;
            best_direction = O;
          }
          const double lobe = eq1_lobe(O);
          if (lobe > 1e-3 * sharpness) {
            if (scale == 0.0) scale = value / lobe;
            EXPECT_NEAR(value / lobe / scale, 1.0, 1e-12);
          }
        }
      // Grid of 0.5 deg: the maximum lies within one step of the axis.
      EXPECT_LT(std::acos(std::min(1.0, best_direction.dot(axis))), 0.75 * kDeg)
          << (back ? "back" : "forward") << " lobe, incidence " << incidence_deg;
      EXPECT_GE(brdf.value(to_light, axis, N), best);
    }
  }
}

TEST(Brdf, FiniteEverywhere) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<r::Brdf> brdfs;
  for (const r::BrdfParameters& p : {r::BrdfParameters{0.0, 0.0, 1000.0, 0.0}, r::BrdfParameters{0.0, 1.0, 0.0, 1000.0},
                                     r::BrdfParameters{0.0, 0.5, 1e-12, 1e-300},
                                     r::BrdfParameters{0.1, 0.05, 60.0, 5.0}, r::BrdfParameters{0.0, 0.5, 100.0, 20.0}})
    brdfs.emplace_back(p);
  const Vector3d N = Vector3d::UnitZ();
  for (int i = 0; i < 200000; ++i) {
    // Polar angles over the whole sphere, with many near and at the horizon.
    auto polar = [&]() {
      const double x = u(rng);
      if (x < 0.2) return 0.5 * kPi - 1e-6 * u(rng);
      if (x < 0.25) return 0.5 * kPi;
      if (x < 0.3) return 0.5 * kPi + 1e-9 * u(rng);
      return std::acos(2.0 * u(rng) - 1.0);
    };
    const Vector3d l = direction(polar(), 2.0 * kPi * u(rng));
    const Vector3d v = direction(polar(), 2.0 * kPi * u(rng));
    for (const r::Brdf& brdf : brdfs) {
      const double value = brdf.value(l, v, N);
      ASSERT_TRUE(std::isfinite(value)) << l.transpose() << " / " << v.transpose();
      ASSERT_GE(value, 0.0);
      if (l.z() <= 0.0 || v.z() <= 0.0) {
        ASSERT_EQ(value, 0.0);
      }
    }
  }
  const double nan = std::nan("");
  for (const r::Brdf& brdf : brdfs) {
    EXPECT_EQ(brdf.value(Vector3d(nan, 0, 1), Vector3d::UnitZ(), N), 0.0);
    EXPECT_EQ(brdf.value(0.5, 0.5, nan), 0.0);
    EXPECT_TRUE(std::isfinite(brdf.value(1e-300, 1e-300, -1.0)));
    EXPECT_TRUE(std::isfinite(brdf.value(1.0 + 1e-15, 1.0, 1.0 + 1e-15)));  // rounding above 1
  }
}

// max_projected_value_per_sr() bounds N.L value() everywhere and is near its
// peak: the mirror and backscatter directions (where the lobes peak) at
// incidences from grazing to normal, and random pairs; 1/pi for a Lambertian BRDF.
TEST(Brdf, MaxProjectedValueBoundsEveryGeometry) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vector3d N = Vector3d::UnitZ();
  for (const r::BrdfParameters& p :
       {r::BrdfParameters{1.0, 0.0, 0.0, 0.0}, r::BrdfParameters{0.3, 0.05, 30.0, 2.0},
        r::BrdfParameters{0.9, 0.7, 1.0, 3.0}, r::BrdfParameters{0.0, 0.0, 1000.0, 0.0},
        r::BrdfParameters{0.0, 1.0, 0.0, 1000.0}, r::BrdfParameters{0.1, 0.05, 60.0, 5.0}}) {
    const r::Brdf brdf(p);
    const double bound = brdf.max_projected_value_per_sr();
    ASSERT_TRUE(std::isfinite(bound));
    if (brdf.lambertian()) {
      EXPECT_EQ(bound, 1.0 / kPi);
    }
    double peak = 0;
    for (int i = 0; i <= 2000; ++i) {
      const double incidence = 0.5 * kPi * (1.0 - std::pow(i / 2000.0, 3)) * (1 - 1e-9);  // dense near grazing
      const Vector3d l = direction(incidence, 0.3);
      const Vector3d mirror(-l.x(), -l.y(), l.z());
      for (const Vector3d& v : {mirror, l}) {
        const double projected = l.z() * brdf.value(l, v, N);
        ASSERT_LE(projected, bound) << p.k0 << " " << p.alpha << " " << p.beta << " at " << incidence;
        peak = std::max(peak, projected);
      }
    }
    for (int i = 0; i < 20000; ++i) {
      const Vector3d l = direction(std::acos(u(rng)), 2.0 * kPi * u(rng));
      const Vector3d v = direction(std::acos(u(rng)), 2.0 * kPi * u(rng));
      ASSERT_LE(l.z() * brdf.value(l, v, N), bound);
    }
    EXPECT_GT(peak, 0.8 * bound) << p.k0 << " " << p.alpha << " " << p.beta;
  }
}

TEST(Brdf, ValidateRefusesOutOfRangeNamingTheField) {
  const double nan = std::nan(""), inf = HUGE_VAL;
  struct Case {
    r::BrdfParameters parameters;
    const char* field;
  };
  const Case cases[] = {
      {{nan, 0, 1, 1}, "material.brdf.k0"},
      {{-0.1, 0, 1, 1}, "material.brdf.k0"},
      {{1.1, 0, 1, 1}, "material.brdf.k0"},
      {{0.5, nan, 1, 1}, "material.brdf.k1"},
      {{0.5, 2.0, 1, 1}, "material.brdf.k1"},
      {{0.5, 0.5, -1, 1}, "material.brdf.alpha"},
      {{0.5, 0.5, nan, 1}, "material.brdf.alpha"},
      {{0.5, 0.5, inf, 1}, "material.brdf.alpha"},
      {{0.5, 0.5, r::brdf_max_sharpness * 1.001, 1}, "material.brdf.alpha"},
      {{0.5, 0.5, 1, -1e-300}, "material.brdf.beta"},
      {{0.5, 0.5, 1, nan}, "material.brdf.beta"},
  };
  for (const Case& c : cases) {
    try {
      r::validate(c.parameters, "material.brdf");
      ADD_FAILURE() << "accepted " << c.field;
    } catch (const eoir::Error& e) {
      EXPECT_EQ(e.status(), eoir::Status::out_of_range);
      EXPECT_EQ(std::string(e.what()).rfind(std::string(c.field) + ":", 0), 0u) << e.what();
    }
    EXPECT_THROW(r::Brdf{c.parameters}, eoir::Error);
  }
  EXPECT_NO_THROW(r::validate({0.0, 1.0, 0.0, r::brdf_max_sharpness}, "material.brdf"));
  EXPECT_NO_THROW(r::validate({1.0, 0.0, r::brdf_max_sharpness, 0.0}, "material.brdf"));
}

// Reported, loosely bounded (shared machines): the minimum over repeats.
TEST(Brdf, Timing) {
  using clock = std::chrono::steady_clock;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vector3d> dirs;  // upper hemisphere
  for (int i = 0; i < 1024; ++i) dirs.push_back(direction(std::acos(u(rng)), 2.0 * kPi * u(rng)));
  double sink = 0.0;
  for (double alpha : {0.0, 1.0, 20.0, 100.0, 1000.0}) {
    const r::BrdfParameters parameters{0.1, 0.5, alpha, alpha / 4.0};
    double build_us = HUGE_VAL, eval_ns = HUGE_VAL;
    for (int repeat = 0; repeat < 5; ++repeat) {
      const auto t0 = clock::now();
      for (int i = 0; i < 4; ++i) sink += r::Brdf(parameters).parameters().alpha;
      build_us = std::min(build_us, std::chrono::duration<double, std::micro>(clock::now() - t0).count() / 4);
      const r::Brdf brdf(parameters);
      const auto t1 = clock::now();
      const std::size_t evaluations = 200000;
      for (std::size_t i = 0; i < evaluations; ++i)
        sink += brdf.value(dirs[i & 1023u], dirs[(i * 7 + 1) & 1023u], Vector3d::UnitZ());
      eval_ns = std::min(eval_ns, std::chrono::duration<double, std::nano>(clock::now() - t1).count() / evaluations);
    }
    std::cout << "[ timing ] alpha " << alpha << ", beta " << alpha / 4.0 << ": construction " << build_us
              << " us, value() " << eval_ns << " ns\n";
    EXPECT_LT(build_us, 20000.0);
    EXPECT_LT(eval_ns, 2000.0);
  }
  EXPECT_TRUE(std::isfinite(sink));
}
