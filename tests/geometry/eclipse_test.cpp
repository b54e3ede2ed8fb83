// Solar-disk occultation (spec 4.1.5.3 culling of eclipsed sources; spec
// 6.1.2 Distance Ordering & Obscuration and its penumbra test): a GEO
// satellite through the Earth's shadow at the 2010 spring equinox against an
// independent conical-shadow calculation, closed-form overlaps, the exact
// spherical-cap integral, ray casts of the WGS84 spheroid, and robustness.
#include "geometry/eclipse.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "core/time.hpp"
#include "geometry/shape_intersect.hpp"
#include "universe/central_bodies.hpp"

namespace g = eoir::geometry;
namespace u = eoir::universe;
using g::Occulter;
using g::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kAu = 149597870700.0;
constexpr double kSunRadius = 695700e3;  // IAU 2015 nominal, as the engine's table
constexpr double kWgs84A = 6378137.0, kWgs84C = 6356752.314245;
constexpr double kGeoRadius = 42164.2e3;

Occulter earth(const Vec3& centre = Vec3::Zero(), const Vec3& pole = Vec3::UnitZ()) {
  return {centre, kWgs84A, kWgs84C, pole};
}

double visible(const Vec3& p, const Vec3& sun, const std::vector<Occulter>& occ, double sun_radius = kSunRadius) {
  return g::solar_disk_visible_fraction(p, sun, sun_radius, occ);
}

// Bisection of a predicate that is false at lo and true at hi.
double boundary(const std::function<bool(double)>& pred, double lo, double hi) {
  EXPECT_FALSE(pred(lo));
  EXPECT_TRUE(pred(hi));
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pred(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// ---- Independent references ------------------------------------------------

// Classic conical shadow of a spherical Earth (radius re) (e.g. Vallado,
// Fundamentals of Astrodynamics and Applications, sec. 5.3): the umbra cone is
// tangent to both spheres, half-angle asin((R_sun - re) / d), radius
// re / cos f at the Earth's centre; the penumbra cone crosses between them,
// half-angle asin((R_sun + re) / d).
struct ConeCoordinates {
  double behind_m, off_axis_m, sun_distance_m;
};
ConeCoordinates cone_coordinates(const Vec3& sat, const Vec3& sun) {
  const Vec3 axis = sun.normalized();
  return {-sat.dot(axis), (sat - sat.dot(axis) * axis).norm(), sun.norm()};
}
bool in_umbra_cone(const Vec3& sat, const Vec3& sun, double re) {
  const ConeCoordinates c = cone_coordinates(sat, sun);
  const double f = std::asin((kSunRadius - re) / c.sun_distance_m);
  return c.behind_m > 0.0 && c.off_axis_m < re / std::cos(f) - c.behind_m * std::tan(f);
}
bool in_penumbra_cone(const Vec3& sat, const Vec3& sun, double re) {
  const ConeCoordinates c = cone_coordinates(sat, sun);
  const double f = std::asin((kSunRadius + re) / c.sun_distance_m);
  return c.behind_m > -re && c.off_axis_m < re / std::cos(f) + c.behind_m * std::tan(f);
}

// Hidden fraction of the Sun's solid angle by a sphere, exactly on the unit
// sphere: rings at angular distance r from the Sun's centre, each inside the
// occulter's cap over the arc cos(phi) > q; integrated in long double by
// adaptive Simpson between the contact radii.
long double ring_inside(long double r, long double rho, long double gamma) {
  const long double s = std::sin(r) * std::sin(gamma);
  const long double num = std::cos(rho) - std::cos(r) * std::cos(gamma);
  if (s <= 0.0L) return num < 0.0L ? 1.0L : 0.0L;
  const long double q = num / s;
  if (q <= -1.0L) return 1.0L;
  if (q >= 1.0L) return 0.0L;
  return std::acos(q) / static_cast<long double>(kPi);
}
// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
struct Gauss {
  std::vector<long double> x, w;
  explicit Gauss(int n) {
    for (int i = 0; i < n; ++i) {
      long double z = std::cos(static_cast<long double>(kPi) * (i + 0.75L) / (n + 0.5L)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        long double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const long double step = p1 / dp;
        z -= step;
        if (std::fabs(step) < 1e-19L) break;
      }
      x.push_back(z);
      w.push_back(2 / ((1 - z * z) * dp * dp));
    }
  }
};
double exact_sphere_hidden(const Vec3& p, const Vec3& sun, double sun_radius, const Vec3& centre, double radius) {
  const Vec3 s = sun - p, o = centre - p;
  const long double alpha = std::asin(static_cast<long double>(sun_radius) / s.norm());
  const long double rho = std::asin(static_cast<long double>(radius) / o.norm());
  const long double gamma = std::atan2(static_cast<long double>(s.cross(o).norm()), s.dot(o));
  const auto f = [&](long double r) { return ring_inside(r, rho, gamma) * std::sin(r); };
  std::vector<long double> cuts = {0.0L, alpha};
  for (long double c : {std::fabs(gamma - rho), gamma + rho})
    if (c > 0.0L && c < alpha) cuts.push_back(c);
  std::sort(cuts.begin(), cuts.end());
  // Between contact radii the integrand has square-root ends: r = lo + (hi -
  // lo) (1 - cos t) / 2 makes it smooth in t.
  static const Gauss gauss(48);
  constexpr int kPanels = 8;
  long double total = 0.0L;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const long double lo = cuts[i], half = 0.5L * (cuts[i + 1] - cuts[i]), pi = kPi;
    for (int panel = 0; panel < kPanels; ++panel) {
      const long double t0 = pi * panel / kPanels, t1 = pi * (panel + 1) / kPanels;
      for (std::size_t k = 0; k < gauss.x.size(); ++k) {
        const long double t = 0.5L * (t0 + t1) + 0.5L * (t1 - t0) * gauss.x[k];
        total += 0.5L * (t1 - t0) * gauss.w[k] * f(lo + half * (1 - std::cos(t))) * half * std::sin(t);
      }
    }
  }
  return static_cast<double>(total / (1.0L - std::cos(alpha)));
}

// The classic planar shadow function (Montenbruck & Gill, Satellite Orbits,
// sec. 3.4.2), for comparison only: disks of the apparent radii.
double planar_hidden(double a, double b, double c) {
  if (c >= a + b) return 0.0;
  if (c <= b - a) return 1.0;
  if (c <= a - b) return (b * b) / (a * a);
  const double x = (c * c + a * a - b * b) / (2 * c), y = std::sqrt(a * a - x * x);
  return (a * a * std::acos(x / a) + b * b * std::acos((c - x) / b) - c * y) / (kPi * a * a);
}

// Visible fraction by ray casting the occulter (geometry::intersect_shape)
// over an n x n grid across the solar disk (azimuthal equidistant about the
// Sun's centre, solid-angle weights).
double raycast_visible(const Vec3& p, const Vec3& sun, double sun_radius, const Occulter& occ, int n) {
  const Vec3 s = sun - p;
  const double d = s.norm(), alpha = std::asin(sun_radius / d);
  const Vec3 w = s / d, e1 = w.unitOrthogonal(), e2 = w.cross(e1);
  const Eigen::Quaterniond to_body = Eigen::Quaterniond::FromTwoVectors(occ.polar_axis.normalized(), Vec3::UnitZ());
  const g::ShapeGeom shape = g::shape_geom(eoir::universe::ShapeKind::oblate,
                                           {occ.equatorial_radius_m, occ.polar_radius_m});
  const Vec3 origin = to_body * (p - occ.centre_m);
  double all = 0, lit = 0, t_m;
  Vec3 normal;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = ((i + 0.5) / n * 2.0 - 1.0) * alpha, y = ((j + 0.5) / n * 2.0 - 1.0) * alpha;
      const double r = std::hypot(x, y);
      if (r > alpha) continue;
      const Vec3 dir = r > 0 ? Vec3(std::cos(r) * w + std::sin(r) / r * (x * e1 + y * e2)) : w;
      const double weight = r > 0 ? std::sin(r) / r : 1.0;
      all += weight;
      if (!g::intersect_shape(shape, origin, to_body * dir, 0.0, d, t_m, normal)) lit += weight;
    }
  return lit / all;
}
bool ray_blocked(const Vec3& p, const Vec3& target, const Occulter& occ) {
  const Eigen::Quaterniond to_body = Eigen::Quaterniond::FromTwoVectors(occ.polar_axis.normalized(), Vec3::UnitZ());
  const g::ShapeGeom shape = g::shape_geom(eoir::universe::ShapeKind::oblate,
                                           {occ.equatorial_radius_m, occ.polar_radius_m});
  double t_m;
  Vec3 normal;
  return g::intersect_shape(shape, to_body * (p - occ.centre_m), to_body * (target - p).normalized(), 0.0,
                            (target - p).norm(), t_m, normal);
}

}  // namespace

// ---- 1. GEO through the Earth's shadow at the 2010 spring equinox (6.1.2) --

// The satellite (circular orbit of radius 42164.2 km in the J2000 equator,
// true anomaly from +x) against the WGS84 spheroid with its true pole, and the
// Sun's geocentric J2000 position at each instant. The conical reference uses
// a sphere of the equatorial radius a: at the equinox the Sun and the orbit
// lie within 0.06 deg of the equator (the J2000-to-date precession), so the
// limb points the solar disk touches at second and third contact are on the
// equator, where the spheroid's silhouette seen from the orbit reaches exactly
// as far as a sphere of radius a and curves with radius c^2/a, far larger than
// the Sun's disk: both models must give the same contacts (to about a metre).
TEST(Eclipse, GeoEquinoxUmbraAndSunsetDuration) {
  const eoir::EngineTime t0 = eoir::EngineTime::from(eoir::utc_from_iso("2010-03-20T17:32:00Z"));
  const u::CentralBodyInfo& sun_info = u::central_body_info(u::CentralBody::sun);
  ASSERT_DOUBLE_EQ(sun_info.equatorial_radius_m, kSunRadius);
  const auto sun_at = [&](const eoir::EngineTime& t) {
    Vec3 r, v;
    u::central_body_state_j2000(sun_info, t, r, v);
    return r;
  };
  const Vec3 sun0 = sun_at(t0);
  const Vec3 pole = eoir::frames::j2000_to_earth_fixed(t0).row(2).transpose();  // ITRS z in J2000
  EXPECT_LT(std::abs(std::asin(sun0.z() / sun0.norm())), 0.1 * kDeg);

  constexpr double mu_m3_s2 = 3.986004418e14;
  const double n_rad_s = std::sqrt(mu_m3_s2 / (kGeoRadius * kGeoRadius * kGeoRadius));
  const double nu_mid = std::atan2(-sun0.y(), -sun0.x());  // anti-Sun at t0
  struct State {
    Vec3 sat, sun;
  };
  const auto state = [&](double nu) {
    return State{kGeoRadius * Vec3(std::cos(nu), std::sin(nu), 0.0), sun_at(t0.plus_seconds((nu - nu_mid) / n_rad_s))};
  };
  const std::vector<Occulter> occ = {earth(Vec3::Zero(), pole)};
  const auto frac = [&](double nu) {
    const State s = state(nu);
    return visible(s.sat, s.sun, occ);
  };
  const auto umbra = [&](double nu) { return frac(nu) == 0.0; };
  const auto penumbra = [&](double nu) { return frac(nu) < 1.0; };
  const auto cone_umbra = [&](double nu) { return in_umbra_cone(state(nu).sat, state(nu).sun, kWgs84A); };
  const auto cone_penumbra = [&](double nu) { return in_penumbra_cone(state(nu).sat, state(nu).sun, kWgs84A); };
  const auto negate = [](std::function<bool(double)> f) { return [f](double x) { return !f(x); }; };

  const double w = 12.0 * kDeg;
  const double umbra_in = boundary(umbra, nu_mid - w, nu_mid), umbra_out = boundary(negate(umbra), nu_mid, nu_mid + w);
  const double pen_in = boundary(penumbra, nu_mid - w, nu_mid), pen_out = boundary(negate(penumbra), nu_mid, nu_mid + w);
  const double cone_umbra_in = boundary(cone_umbra, nu_mid - w, nu_mid);
  const double cone_umbra_out = boundary(negate(cone_umbra), nu_mid, nu_mid + w);
  const double cone_pen_in = boundary(cone_penumbra, nu_mid - w, nu_mid);
  const double cone_pen_out = boundary(negate(cone_penumbra), nu_mid, nu_mid + w);

  const auto deg360 = [](double rad) { return std::fmod(rad / kDeg + 720.0, 360.0); };
  std::printf("umbra entry nu %.5f deg (cone %.5f), exit %.5f deg (cone %.5f)\n", deg360(umbra_in),
              deg360(cone_umbra_in), deg360(umbra_out), deg360(cone_umbra_out));
  std::printf("penumbra entry nu %.5f deg (cone %.5f), exit %.5f deg (cone %.5f)\n", deg360(pen_in),
              deg360(cone_pen_in), deg360(pen_out), deg360(cone_pen_out));
  EXPECT_NEAR(umbra_in, cone_umbra_in, 0.01 * kDeg);
  EXPECT_NEAR(umbra_out, cone_umbra_out, 0.01 * kDeg);
  EXPECT_NEAR(pen_in, cone_pen_in, 0.01 * kDeg);
  EXPECT_NEAR(pen_out, cone_pen_out, 0.01 * kDeg);

  // Sunset from first to last contact lasts the Sun's traverse: spec 6.1.2,
  // 0.5316 deg / 0.004166667 deg/s = 127.6 s (the spec's STK run: 2:09).
  const double sunset_s = (umbra_in - pen_in) / n_rad_s, sunrise_s = (pen_out - umbra_out) / n_rad_s;
  std::printf("sunset %.2f s, sunrise %.2f s, umbra %.1f s (%.4f deg of true anomaly)\n", sunset_s, sunrise_s,
              (umbra_out - umbra_in) / n_rad_s, (umbra_out - umbra_in) / kDeg);
  EXPECT_NEAR(sunset_s, 127.6, 3.0);
  EXPECT_NEAR(sunrise_s, 127.6, 3.0);
  RecordProperty("sunset_s", std::to_string(sunset_s));

  // Through sunset the fraction falls monotonically from 1 to 0.
  double previous = 1.0;
  for (int i = 0; i <= 400; ++i) {
    const double f = frac(pen_in - 0.001 * kDeg + (umbra_in - pen_in + 0.002 * kDeg) * i / 400.0);
    EXPECT_LE(f, previous + 1e-12);
    previous = f;
  }
  EXPECT_EQ(frac(pen_in - 0.001 * kDeg), 1.0);
  EXPECT_EQ(previous, 0.0);
}

// ---- 2. Closed forms -------------------------------------------------------

TEST(Eclipse, CircleOverlapClosedForms) {
  EXPECT_EQ(g::circle_overlap_area(1.0, 2.0, 3.5), 0.0);
  EXPECT_EQ(g::circle_overlap_area(1.0, 2.0, 3.0), 0.0);  // external tangency
  EXPECT_DOUBLE_EQ(g::circle_overlap_area(1.0, 2.0, 0.5), kPi);
  EXPECT_DOUBLE_EQ(g::circle_overlap_area(2.0, 1.0, 0.5), kPi);
  EXPECT_DOUBLE_EQ(g::circle_overlap_area(3.0, 3.0, 0.0), 9.0 * kPi);
  // Equal circles through each other's centres: r^2 (2 pi / 3 - sqrt(3) / 2).
  EXPECT_NEAR(g::circle_overlap_area(2.0, 2.0, 2.0), 4.0 * (2.0 * kPi / 3.0 - std::sqrt(3.0) / 2.0), 1e-14);
  // Unit circles sqrt(2) apart cross at right angles: pi / 2 - 1.
  EXPECT_NEAR(g::circle_overlap_area(1.0, 1.0, std::sqrt(2.0)), kPi / 2.0 - 1.0, 1e-14);
  // Half-plane: through the centre, and a chord at r / 2 (r^2 (pi / 3 - sqrt(3) / 4)).
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(g::circle_overlap_area_by_edge(2.0, inf, 0.0), 2.0 * kPi);
  EXPECT_NEAR(g::circle_overlap_area_by_edge(2.0, inf, 1.0), 4.0 * (kPi / 3.0 - std::sqrt(3.0) / 4.0), 1e-14);
  EXPECT_NEAR(g::circle_overlap_area_by_edge(1.0, 1e12, 0.0), kPi / 2.0, 1e-11);

  // Against the textbook lens formula, and symmetric in the two circles.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.05, 3.0);
  for (int i = 0; i < 2000; ++i) {
    const double r1 = uni(rng), r2 = uni(rng), d = uni(rng) * (r1 + r2) / 3.0;
    double expect;
    if (d >= r1 + r2)
      expect = 0.0;
    else if (d <= std::abs(r1 - r2))
      expect = kPi * std::pow(std::min(r1, r2), 2);
    else
      expect = r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
               r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
               0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
    EXPECT_NEAR(g::circle_overlap_area(r1, r2, d), expect, 1e-12 * (1.0 + expect));
    EXPECT_EQ(g::circle_overlap_area(r1, r2, d), g::circle_overlap_area(r2, r1, d));
    EXPECT_NEAR(g::circle_overlap_area_by_edge(r1, r2, d - r2), expect, 1e-12 * (1.0 + expect));
  }
}

// The Sun half set behind a much larger occulter, and annular eclipses.
TEST(Eclipse, HalfCoveredAndAnnular) {
  const Vec3 sun_dir = Vec3::UnitX();
  // A point 1 m above a sphere of the Earth's radius, the Sun's centre on its
  // horizon (the limb through the Sun's centre is nearly straight).
  const double r = kWgs84A, d = r + 1.0;
  {
    const double rho = std::asin(r / d);
    // Occulter centre at angle rho from the Sun's direction.
    const Vec3 c = d * Vec3(std::cos(rho), std::sin(rho), 0.0);
    const Vec3 sun = kAu * sun_dir;
    const double f = visible(Vec3::Zero(), sun, {Occulter::sphere(c, r)});
    EXPECT_NEAR(f, 0.5, 1e-5);
    EXPECT_NEAR(1.0 - f, exact_sphere_hidden(Vec3::Zero(), sun, kSunRadius, c, r), 1e-6);
  }
  // An occulter of angular radius 80 deg with its limb through the Sun's centre.
  {
    const double rho = 80.0 * kDeg, dist = 1e7;
    const Vec3 c = dist * Vec3(std::cos(rho), std::sin(rho), 0.0);
    const Vec3 sun = kAu * sun_dir;
    const double f = visible(Vec3::Zero(), sun, {Occulter::sphere(c, dist * std::sin(rho))});
    EXPECT_NEAR(f, 0.5, 3e-4);
    EXPECT_NEAR(1.0 - f, exact_sphere_hidden(Vec3::Zero(), sun, kSunRadius, c, dist * std::sin(rho)), 1e-6);
  }
  // Annular: a sphere of apparent radius k * alpha fully inside the Sun's disk,
  // centred or off centre: 1 - k^2 (apparent radii), to O(alpha^2) ~ 1e-5,
  // the difference between plane and spherical caps.
  const Vec3 sun = kAu * sun_dir;
  const double alpha = std::asin(kSunRadius / kAu);
  for (double k : {0.1, 0.5, 0.9}) {
    const double dist = 384400e3, radius = dist * std::sin(k * alpha);
    for (double off : {0.0, 0.3 * (1.0 - k) * alpha, 0.95 * (1.0 - k) * alpha}) {
      const Vec3 c = dist * Vec3(std::cos(off), std::sin(off), 0.0);
      const double f = visible(Vec3::Zero(), sun, {Occulter::sphere(c, radius)});
      EXPECT_NEAR(f, 1.0 - k * k, 1e-5) << k << " " << off;
      EXPECT_NEAR(1.0 - f, exact_sphere_hidden(Vec3::Zero(), sun, kSunRadius, c, radius), 1e-5);
    }
  }
  // Total: apparent radius 1.05 alpha, centred.
  const double dist = 384400e3;
  EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(dist * sun_dir, dist * std::sin(1.05 * alpha))}), 0.0);
}

// Against the exact spherical-cap integral for spheres seen from LEO to beyond
// the Moon, across the whole penumbra.
TEST(Eclipse, SphereMatchesExactSphericalCaps) {
  const Vec3 sun = kAu * Vec3::UnitX();
  const double alpha = std::asin(kSunRadius / kAu);
  double worst = 0.0, worst_planar = 0.0;
  for (double dist : {6378.2e3, 6778e3, 7378e3, 12000e3, 42164.2e3, 384400e3, 1.5e9, 3e9, 1e10}) {
    const double rho = std::asin(kWgs84A / dist);
    for (int i = 0; i <= 40; ++i) {
      const double edge = (-1.2 + 2.4 * i / 40.0) * std::max(alpha, rho);  // limb to the Sun's centre
      const double gamma = rho + edge;
      const Vec3 c = dist * Vec3(std::cos(gamma), std::sin(gamma), 0.0);
      const double hidden = g::solar_disk_hidden_fraction(Vec3::Zero(), sun, kSunRadius, Occulter::sphere(c, kWgs84A));
      const double exact = exact_sphere_hidden(Vec3::Zero(), sun, kSunRadius, c, kWgs84A);
      worst = std::max(worst, std::abs(hidden - exact));
      worst_planar = std::max(worst_planar, std::abs(planar_hidden(alpha, rho, std::abs(gamma)) - exact));
      EXPECT_NEAR(hidden, exact, 1e-5) << dist << " " << edge / alpha;
    }
  }
  std::printf("sphere vs exact spherical caps: worst |hidden fraction error| %.2e (classic planar: %.2e)\n", worst,
              worst_planar);
}

// Along a path across the GEO-distance shadow: 1 far out, falling
// monotonically to 0 in the umbra, rising back; 0 everywhere inside the umbra
// cone; 1 far from the occulter.
TEST(Eclipse, MonotonicAcrossShadowUmbraConeAndFarAway) {
  const Vec3 sun = kAu * Vec3::UnitX();
  const std::vector<Occulter> occ = {Occulter::sphere(Vec3::Zero(), kWgs84A)};
  double previous = 1.0;
  bool rising = false;
  for (int i = 0; i <= 4000; ++i) {
    const double y = (-2.0 + 4.0 * i / 4000.0) * kWgs84A;
    const double f = visible(Vec3(-kGeoRadius, y, 0.3 * y), sun, occ);
    ASSERT_TRUE(f >= 0.0 && f <= 1.0);
    if (!rising && f > previous) rising = true;
    if (rising)
      EXPECT_GE(f, previous - 1e-12) << y;
    else
      EXPECT_LE(f, previous + 1e-12) << y;
    previous = f;
  }
  EXPECT_EQ(visible(Vec3(-kGeoRadius, 0, 0), sun, occ), 0.0);
  EXPECT_EQ(previous, 1.0);

  const double apex_m = kWgs84A * kAu / (kSunRadius - kWgs84A);  // umbra length, ~1.38e9 m
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double x = (1.001 + uni(rng) * (apex_m / kWgs84A - 1.01)) * kWgs84A;
    const double f_half = std::asin((kSunRadius - kWgs84A) / kAu);
    const double radius = (apex_m - x) * std::tan(f_half) * 0.999 * uni(rng);  // inside the cone
    const double phi = 2 * kPi * uni(rng);
    EXPECT_EQ(visible(Vec3(-x, radius * std::cos(phi), radius * std::sin(phi)), sun, occ), 0.0) << x;
  }
  // Beyond the apex: annular, 1 - (rho / alpha)^2.
  const Vec3 p(-3.0 * apex_m, 0, 0);
  const double rho = std::asin(kWgs84A / p.norm()), alpha = std::asin(kSunRadius / (sun - p).norm());
  EXPECT_NEAR(visible(p, sun, occ), 1.0 - std::pow(rho / alpha, 2), 1e-6);
  EXPECT_EQ(visible(Vec3(0, 2.0 * kGeoRadius, 0), sun, occ), 1.0);
  EXPECT_EQ(visible(Vec3(kGeoRadius, 0, 0), sun, occ), 1.0);  // on the day side
  EXPECT_EQ(visible(Vec3(0, 0, 1e9), sun, occ), 1.0);
}

// ---- 3. Oblateness ---------------------------------------------------------

// From above the pole the Earth's limb is the tangent cone to the equatorial
// bulge, tan(rho) = a / sqrt(D^2 - c^2); from the equator the limb toward the
// pole has tan(rho) = c / sqrt(D^2 - a^2) and toward the equator
// a / sqrt(D^2 - a^2). Sweeping the Sun across each limb the fraction follows a
// ray cast of the ellipsoid over the solar disk; with the Sun's centre on the
// limb a sphere of radius a would be off by ~0.07 from the equator.
TEST(Eclipse, OblateLimbAgainstRayCasts) {
  const double dist = kGeoRadius;
  const double alpha = std::asin(kSunRadius / kAu);
  struct View {
    const char* name;
    Vec3 point, toward_centre, across;  // unit: point -> Earth centre, and the limb's side
    double tan_rho;
  };
  const Vec3 pole = Vec3(0.1, -0.2, 1.0).normalized();  // a tilted pole
  const Vec3 e1 = pole.unitOrthogonal(), e2 = pole.cross(e1);
  const std::vector<View> views = {
      {"above the pole", dist * pole, -pole, e1, kWgs84A / std::sqrt(dist * dist - kWgs84C * kWgs84C)},
      {"equator, polar limb", dist * e1, -e1, pole, kWgs84C / std::sqrt(dist * dist - kWgs84A * kWgs84A)},
      {"equator, equatorial limb", dist * e1, -e1, e2, kWgs84A / std::sqrt(dist * dist - kWgs84A * kWgs84A)},
  };
  const Occulter occ = earth(Vec3::Zero(), pole);
  double worst = 0.0;
  for (const View& v : views) {
    const double rho = std::atan(v.tan_rho);
    const auto sun_at = [&](double edge) {  // Sun's centre `edge` outside the limb
      const double gamma = rho + edge;
      return Vec3(v.point + kAu * (std::cos(gamma) * v.toward_centre + std::sin(gamma) * v.across));
    };
    // Ray casts toward the Sun's centre and its nearest and farthest limb points.
    const double eps = 1e-7;
    EXPECT_TRUE(ray_blocked(v.point, sun_at(-eps), occ)) << v.name;
    EXPECT_FALSE(ray_blocked(v.point, sun_at(eps), occ)) << v.name;
    for (double side : {-1.0, 1.0}) {
      const Vec3 sun = sun_at(side * alpha * (1.0 + 1e-3));  // just past first / last contact
      const double f = g::solar_disk_visible_fraction(v.point, sun, kSunRadius, {occ});
      EXPECT_EQ(raycast_visible(v.point, sun, kSunRadius, occ, 200), side > 0 ? 1.0 : 0.0);
      if (side > 0)
        EXPECT_GT(f, 1.0 - 1e-4) << v.name;
      else
        EXPECT_LT(f, 1e-4) << v.name;
    }
    // The sweep.
    for (int i = 0; i <= 8; ++i) {
      const double edge = (-1.0 + 2.0 * i / 8.0) * alpha;
      const Vec3 sun = sun_at(edge);
      const double f = g::solar_disk_visible_fraction(v.point, sun, kSunRadius, {occ});
      const double cast = raycast_visible(v.point, sun, kSunRadius, occ, 1000);
      worst = std::max(worst, std::abs(f - cast));
      EXPECT_NEAR(f, cast, 5e-4) << v.name << " edge " << edge / alpha;
    }
    const Vec3 sun = sun_at(0.0);
    const double f = g::solar_disk_visible_fraction(v.point, sun, kSunRadius, {occ});
    const double f_sphere = g::solar_disk_visible_fraction(v.point, sun, kSunRadius, {Occulter::sphere(Vec3::Zero(), kWgs84A)});
    std::printf("%-26s Sun's centre on the limb: visible %.5f (sphere of radius a: %.5f)\n", v.name, f, f_sphere);
    EXPECT_NEAR(f, 0.5, 0.01);
  }
  std::printf("spheroid vs ray-cast grid: worst |visible fraction difference| %.2e\n", worst);
}

// The error bound of the near-circle treatment, on a strongly flattened
// spheroid (c = 0.9 a, f = a/c - 1 = 0.111) of every apparent size against
// the Sun, its pole in several directions, across the whole eclipse.
TEST(Eclipse, FlattenedSpheroidErrorBound) {
  const Vec3 sun = kAu * Vec3::UnitX();
  const double alpha = std::asin(kSunRadius / kAu), dist = 1e9;
  const std::vector<Vec3> poles = {Vec3::UnitZ(), Vec3::UnitX(), Vec3(1, 1, 0).normalized(), Vec3(1, 0.3, 0.8).normalized(),
                                   Vec3(0.2, 1, 0.4).normalized()};
  for (double size : {0.3, 0.8, 1.0, 1.5, 4.0, 30.0}) {
    const double a = dist * std::sin(size * alpha);
    double worst = 0.0, worst_sphere = 0.0;
    for (const Vec3& pole : poles) {
      const Occulter occ{Vec3::Zero(), a, 0.9 * a, pole};
      for (int i = 0; i <= 12; ++i) {
        const double gamma = (size + 1.1) * alpha * i / 12.0;
        const Vec3 c = dist * Vec3(std::cos(gamma), std::sin(gamma) * 0.8, std::sin(gamma) * 0.6);
        Occulter moved = occ;
        moved.centre_m = c;
        const double f = visible(Vec3::Zero(), sun, {moved});
        const double cast = raycast_visible(Vec3::Zero(), sun, kSunRadius, moved, 300);
        worst = std::max(worst, std::abs(f - cast));
        // The same body as a sphere of the mean radius, for scale.
        const double f_sphere = visible(Vec3::Zero(), sun, {Occulter::sphere(c, std::cbrt(a * a * 0.9 * a))});
        worst_sphere = std::max(worst_sphere, std::abs(f_sphere - cast));
      }
    }
    std::printf("c = 0.9 a, apparent a / alpha = %5.1f: worst |error| %.2e (volumetric sphere %.2e)\n", size, worst,
                worst_sphere);
    EXPECT_LT(worst, 0.15 * (1.0 / 0.9 - 1.0));
  }
}

// ---- 4. Robustness ---------------------------------------------------------

TEST(Eclipse, RangesFromMillimetreToTerametre) {
  // Observer-relative coordinates: the observer at GEO on the night side at
  // the origin, the Earth at -r_obs. A point 1 mm from the observer sees what
  // the observer sees (umbra); a 1 cm ball 1 m toward the Sun hides it all.
  const Vec3 sun_geo = kAu * Vec3::UnitX(), obs = Vec3(-kGeoRadius, 0, 0);
  const Vec3 sun = sun_geo - obs, earth_c = -obs;
  const std::vector<Occulter> occ = {earth(earth_c)};
  EXPECT_EQ(visible(Vec3(1e-3, 0, 0), sun, occ), 0.0);
  EXPECT_EQ(visible(Vec3(1e-3, 0, 0) + Vec3(0, 3.0 * kWgs84A, 0), sun, occ), 1.0);
  const Vec3 lit_point = Vec3(0, 3.0 * kWgs84A, 1e-3);
  EXPECT_EQ(visible(lit_point, sun, {Occulter::sphere(lit_point + Vec3(1.0, 0, 0), 0.01)}), 0.0);
  // A 1 mm ball 1 m away: apparent radius 1e-3 rad, an annulus.
  const double alpha = std::asin(kSunRadius / (sun - lit_point).norm()), rho = std::asin(1e-3 / 1.0);
  EXPECT_NEAR(visible(lit_point, sun, {Occulter::sphere(lit_point + Vec3(1.0, 0, 0), 1e-3)}),
              1.0 - std::pow(std::tan(rho) / alpha, 2), 1e-6);

  // 1e12 m out, on the far side of the Earth: the Earth transits the Sun.
  const Vec3 far = earth_c - 1e12 * Vec3::UnitX();
  // Apparent semi-axes of the Earth a / D and c / D (a transit seen in the equator).
  const double alpha_far = std::asin(kSunRadius / (sun - far).norm());
  EXPECT_NEAR(visible(far, sun, occ), 1.0 - (kWgs84A / 1e12) * (kWgs84C / 1e12) / (alpha_far * alpha_far), 1e-9);
  EXPECT_EQ(visible(earth_c + 1e12 * Vec3::UnitY(), sun, occ), 1.0);
  EXPECT_EQ(visible(earth_c + 1e12 * Vec3::UnitX(), sun, occ), 1.0);  // beyond the Sun
}

TEST(Eclipse, SunBehindPointOcculterBetweenAndSurfacePoints) {
  const Vec3 sun = kAu * Vec3::UnitX();
  // The occulter on the far side of the point from the Sun does not shade,
  // however close or large.
  EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(-2.0, 0, 0), 1.0)}), 1.0);
  EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(-1.0 - 1e-3, 0, 0), 1.0)}), 1.0);
  EXPECT_EQ(visible(Vec3::Zero(), sun, {earth(Vec3(-kWgs84A - 1.0, 0, 0), Vec3::UnitY())}), 1.0);
  // Exactly between: total, and the same from every distance along the line.
  for (double s : {1.0, 1e3, 1e6, 1e9})
    EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(s, 0, 0), 0.01 * s)}), 0.0) << s;
  EXPECT_EQ(visible(Vec3::Zero(), sun, {earth(Vec3(1e8, 0, 0))}), 0.0);
  // Inside an occulter: 0. On its surface, Sun overhead: 1; Sun below the
  // horizon: 0; Sun on the horizon: half.
  EXPECT_EQ(visible(Vec3::Zero(), sun, {earth(Vec3(10.0, 0, 0))}), 0.0);
  EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(-kWgs84A, 0, 0), kWgs84A)}), 1.0);
  EXPECT_EQ(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(kWgs84A, 0, 0), kWgs84A)}), 0.0);
  EXPECT_NEAR(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3(0, kWgs84A, 0), kWgs84A)}), 0.5, 1e-9);
  const Vec3 north_pole(0, 0, kWgs84C);  // at an equinox
  EXPECT_NEAR(visible(north_pole, north_pole + sun, {earth()}), 0.5, 1e-9);
  // A point inside the Sun sees it.
  EXPECT_EQ(visible(sun + Vec3(1e3, 0, 0), sun, {earth()}), 1.0);
}

TEST(Eclipse, SeveralOcculters) {
  const Vec3 sun = kAu * Vec3::UnitX();
  const double alpha = std::asin(kSunRadius / kAu);
  // Two disjoint balls over the Sun: hidden fractions add.
  const double dist = 1000.0, radius = dist * std::sin(0.3 * alpha);
  const Occulter b1 = Occulter::sphere(dist * Vec3(1, 0.5 * alpha, 0), radius);
  const Occulter b2 = Occulter::sphere(dist * Vec3(1, -0.5 * alpha, 0), radius);
  const double h1 = 1.0 - visible(Vec3::Zero(), sun, {b1}), h2 = 1.0 - visible(Vec3::Zero(), sun, {b2});
  EXPECT_NEAR(h1, 0.09, 1e-5);
  EXPECT_NEAR(visible(Vec3::Zero(), sun, {b1, b2}), 1.0 - h1 - h2, 1e-15);
  // A ball in front of the Earth's disk counts once; the same ball twice too.
  const Vec3 p(-kGeoRadius, 0, 0);
  const double rho = std::asin(kWgs84A / kGeoRadius);
  const Vec3 sun_p = p + kAu * Vec3(std::cos(rho), std::sin(rho), 0);  // Sun's centre on the limb
  const Occulter ball = Occulter::sphere(p + Vec3(10.0, -0.05, 0), 0.02);  // 1.1 deg inside the Earth's disk
  const double earth_only = visible(p, sun_p, {earth()});
  EXPECT_EQ(visible(p, sun_p, {earth(), ball}), earth_only);
  EXPECT_EQ(visible(p, sun_p, {ball, earth(), ball}), earth_only);
  EXPECT_NEAR(visible(Vec3::Zero(), sun, {b1, b1}), 1.0 - h1, 1e-15);
  // Partly overlapping: conservative (at most the lesser of the two alone).
  const Occulter b3 = Occulter::sphere(dist * Vec3(1, 0.3 * alpha, 0), radius);
  const double both = visible(Vec3::Zero(), sun, {b1, b3});
  EXPECT_LE(both, std::min(visible(Vec3::Zero(), sun, {b1}), visible(Vec3::Zero(), sun, {b3})));
  EXPECT_GE(both, 0.0);
  EXPECT_EQ(visible(Vec3::Zero(), sun, {}), 1.0);
}

TEST(Eclipse, FiniteEverywhereAndInputChecks) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(-1.0, 1.0), lg(-3.0, 12.0);
  const auto rand_vec = [&](double scale) -> Vec3 { return Vec3(uni(rng), uni(rng), uni(rng)) * scale; };
  const auto rand_len = [&] { return std::pow(10.0, lg(rng)); };
  int partial = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 p = rand_vec(rand_len());
    const Vec3 sun = p + rand_vec(rand_len());
    const double sun_radius = (i % 7 == 0) ? 0.0 : rand_len() * 1e-3;
    std::vector<Occulter> occ;
    for (int k = 0; k < 1 + i % 3; ++k) {
      const double a = rand_len() * 1e-2, flat = (i % 2) ? 0.0 : 0.1 * (uni(rng) + 1.0) / 2.0;
      // Occulters near the point-Sun line half the time.
      const Vec3 c = (i % 4 < 2) ? Vec3(p + (sun - p) * (uni(rng) + 1.0) / 2.0 + rand_vec(a)) : rand_vec(rand_len());
      occ.push_back({c, a, a * (1.0 - flat), rand_vec(1.0) + Vec3(0, 0, 1e-3)});
    }
    if (i % 50 == 0) occ.push_back(Occulter::sphere(p, 0.0));
    if (i % 50 == 1) occ.push_back(Occulter::sphere(p + (sun - p) * 1e-9, (sun - p).norm() * 1e-9));  // on its surface
    const double f = g::solar_disk_visible_fraction(p, sun, sun_radius, occ);
    ASSERT_TRUE(f >= 0.0 && f <= 1.0) << i << " " << f;
    if (f > 0.0 && f < 1.0) ++partial;
    for (const Occulter& o : occ) {
      const double h = g::solar_disk_hidden_fraction(p, sun, sun_radius, o);
      ASSERT_TRUE(h >= 0.0 && h <= 1.0) << i;
    }
  }
  EXPECT_GT(partial, 1000);
  // Degenerate geometry.
  EXPECT_EQ(visible(Vec3::Zero(), Vec3::Zero(), {earth()}), 1.0);           // point at the Sun's centre
  EXPECT_EQ(visible(Vec3::Zero(), kAu * Vec3::UnitX(), {earth()}), 0.0);    // at the occulter's centre
  EXPECT_EQ(visible(Vec3(1, 0, 0), kAu * Vec3::UnitX(), {Occulter::sphere(Vec3(1, 0, 0), 0.0)}), 1.0);
  EXPECT_EQ(visible(Vec3::Zero(), kAu * Vec3::UnitX(), {Occulter::sphere(Vec3(1, 0, 0), 0.5)}, 0.0), 0.0);
  EXPECT_EQ(visible(Vec3::Zero(), kAu * Vec3::UnitX(), {Occulter::sphere(Vec3(1, 1, 0), 0.5)}, 0.0), 1.0);
  // Bad input.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vec3 sun = kAu * Vec3::UnitX();
  EXPECT_THROW(visible(Vec3(nan, 0, 0), sun, {earth()}), eoir::Error);
  EXPECT_THROW(visible(Vec3::Zero(), Vec3(0, nan, 0), {earth()}), eoir::Error);
  EXPECT_THROW(visible(Vec3::Zero(), sun, {earth()}, -1.0), eoir::Error);
  EXPECT_THROW(visible(Vec3::Zero(), sun, {Occulter::sphere(Vec3::Zero(), -1.0)}), eoir::Error);
  EXPECT_THROW(visible(Vec3::Zero(), sun, {earth(Vec3(0, 0, nan))}), eoir::Error);
  EXPECT_THROW(visible(Vec3::Zero(), sun, {earth(Vec3(1e8, 0, 0), Vec3::Zero())}), eoir::Error);
  EXPECT_THROW(g::solar_disk_visible_fraction(Vec3::Zero(), sun, kSunRadius, nullptr, 1), eoir::Error);
}
