// Analytic ray/shape intersection (spec 4.1.5.1): hand-computed hits, unit
// outward normals, grazing rays, the observer inside a shape.
#include "geometry/shape_intersect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace g = eoir::geometry;
using g::Vec3;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

g::ShapeGeom make(const std::string& shape, std::vector<double> dims) {
  return g::shape_geom(eoir::universe::parse_shape(shape, "shape"), dims);
}

struct Result {
  bool hit = false;
  double t = 0;
  Vec3 n = Vec3::Zero();
};

Result cast(const g::ShapeGeom& s, const Vec3& o, const Vec3& d) {
  Result r;
  r.hit = g::intersect_shape(s, o, d.normalized(), 0.0, kInf, r.t, r.n);
  return r;
}

void expect_hit(const Result& r, double t, const Vec3& n, double tol = 1e-12) {
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.t, t, tol);
  EXPECT_NEAR((r.n - n.normalized()).norm(), 0.0, 1e-12) << r.n.transpose();
}

}  // namespace

TEST(ShapeIntersect, Sphere) {
  const auto s = make("sphere", {1.0});
  expect_hit(cast(s, Vec3(0, 0, -5), Vec3(0, 0, 1)), 4.0, Vec3(0, 0, -1));
  expect_hit(cast(s, Vec3(0.6, 0, -5), Vec3(0, 0, 1)), 4.2, Vec3(0.6, 0, -0.8));
  EXPECT_FALSE(cast(s, Vec3(1.5, 0, -5), Vec3(0, 0, 1)).hit);
  EXPECT_FALSE(cast(s, Vec3(0, 0, -5), Vec3(0, 0, -1)).hit);  // behind
}

TEST(ShapeIntersect, Oblate) {
  const auto s = make("oblate", {2.0, 1.0});
  expect_hit(cast(s, Vec3(0, 0, 10), Vec3(0, 0, -1)), 9.0, Vec3(0, 0, 1));
  expect_hit(cast(s, Vec3(10, 0, 0), Vec3(-1, 0, 0)), 8.0, Vec3(1, 0, 0));
  const double z = std::sqrt(0.75);
  expect_hit(cast(s, Vec3(1, 0, 10), Vec3(0, 0, -1)), 10.0 - z, Vec3(1.0 / 4.0, 0, z));
  EXPECT_FALSE(cast(s, Vec3(0, 2.1, 10), Vec3(0, 0, -1)).hit);
}

TEST(ShapeIntersect, OblateEquatorialRadiusIsA) {
  const auto s = make("oblate", {2.0, 1.0});
  // Along y the equatorial radius 2 applies; at y = 1.5 the surface is at z = sqrt(1 - 0.5625).
  expect_hit(cast(s, Vec3(0, 1.5, 10), Vec3(0, 0, -1)), 10.0 - std::sqrt(1 - 0.5625), Vec3(0, 1.5 / 4.0, std::sqrt(1 - 0.5625)));
}

TEST(ShapeIntersect, Box) {
  const auto s = make("box", {2.0, 4.0, 6.0});
  expect_hit(cast(s, Vec3(5, 0, 0), Vec3(-1, 0, 0)), 4.0, Vec3(1, 0, 0));
  expect_hit(cast(s, Vec3(0, -9, 0), Vec3(0, 1, 0)), 7.0, Vec3(0, -1, 0));
  expect_hit(cast(s, Vec3(0.5, 1, -10), Vec3(0, 0, 1)), 7.0, Vec3(0, 0, -1));
  // Diagonal ray entering through +x at (1, 0.5, 0).
  expect_hit(cast(s, Vec3(3, 2.5, 0), Vec3(-1, -1, 0)), 2.0 * std::sqrt(2.0), Vec3(1, 0, 0));
  EXPECT_FALSE(cast(s, Vec3(1.5, 0, -10), Vec3(0, 0, 1)).hit);
}

TEST(ShapeIntersect, PlateIsTwoSided) {
  const auto s = make("plate", {2.0, 2.0});
  expect_hit(cast(s, Vec3(0.5, 0.5, 5), Vec3(0, 0, -1)), 5.0, Vec3(0, 0, 1));
  expect_hit(cast(s, Vec3(0.5, 0.5, -5), Vec3(0, 0, 1)), 5.0, Vec3(0, 0, -1));
  expect_hit(cast(s, Vec3(-4, 0, 3), Vec3(4, 0, -3)), 5.0, Vec3(0, 0, 1));
  EXPECT_FALSE(cast(s, Vec3(2, 0, 5), Vec3(0, 0, -1)).hit);
  EXPECT_FALSE(cast(s, Vec3(-5, 0, 0), Vec3(1, 0, 0)).hit);  // edge-on
}

TEST(ShapeIntersect, Cylinder) {
  const auto s = make("cylinder", {1.0, 4.0});
  expect_hit(cast(s, Vec3(5, 0, 0), Vec3(-1, 0, 0)), 4.0, Vec3(1, 0, 0));
  expect_hit(cast(s, Vec3(0, 0, 10), Vec3(0, 0, -1)), 8.0, Vec3(0, 0, 1));
  expect_hit(cast(s, Vec3(0.5, 0, -10), Vec3(0, 0, 1)), 8.0, Vec3(0, 0, -1));
  EXPECT_FALSE(cast(s, Vec3(5, 0, 2.5), Vec3(-1, 0, 0)).hit);
  // Oblique: enters the side at (1, 0, 1) from (3, 0, 3).
  expect_hit(cast(s, Vec3(3, 0, 3), Vec3(-1, 0, -1)), 2.0 * std::sqrt(2.0), Vec3(1, 0, 0));
  // Oblique through the top cap at (0.5, 0, 2).
  expect_hit(cast(s, Vec3(2.5, 0, 4), Vec3(-1, 0, -1)), 2.0 * std::sqrt(2.0), Vec3(0, 0, 1));
}

TEST(ShapeIntersect, Cone) {
  // Base radius 1 at z = -1, apex at z = +1: r(z) = 0.5 - 0.5 z.
  const auto s = make("cone", {1.0, 2.0});
  const Vec3 side_n(1, 0, 0.5);
  expect_hit(cast(s, Vec3(5, 0, 0), Vec3(-1, 0, 0)), 4.5, side_n);
  expect_hit(cast(s, Vec3(0, 0, -5), Vec3(0, 0, 1)), 4.0, Vec3(0, 0, -1));
  expect_hit(cast(s, Vec3(0.25, 0, 5), Vec3(0, 0, -1)), 4.5, side_n);
  EXPECT_FALSE(cast(s, Vec3(0.6, 0, 5), Vec3(0, 0, 1)).hit);
  EXPECT_FALSE(cast(s, Vec3(5, 0, 1.2), Vec3(-1, 0, 0)).hit);  // above the apex
  EXPECT_FALSE(cast(s, Vec3(5, 0, -1.2), Vec3(-1, 0, 0)).hit);  // below the base
  // Ray along a generator direction (A = 0 branch): from below the base
  // parallel to the generator line x = 0.5 - 0.5 z shifted inwards.
  const Vec3 d = Vec3(-1, 0, 2).normalized();
  const Result r = cast(s, Vec3(0.2 + 1.0, 0, -1.0 - 2.0), d);  // reaches (0.2, 0, -1) on the base
  expect_hit(r, std::sqrt(5.0), Vec3(0, 0, -1));
}

TEST(ShapeIntersect, Coupler) {
  // r(z) = 0.75 - 0.25 z, bottom 1 at z = -1, top 0.5 at z = +1.
  const auto s = make("coupler", {1.0, 0.5, 2.0});
  expect_hit(cast(s, Vec3(5, 0, 0), Vec3(-1, 0, 0)), 4.25, Vec3(1, 0, 0.25));
  expect_hit(cast(s, Vec3(0, 0, 5), Vec3(0, 0, -1)), 4.0, Vec3(0, 0, 1));
  expect_hit(cast(s, Vec3(0.7, 0, 5), Vec3(0, 0, -1)), 4.8, Vec3(1, 0, 0.25));
  expect_hit(cast(s, Vec3(0.9, 0, -5), Vec3(0, 0, 1)), 4.0, Vec3(0, 0, -1));
}

TEST(ShapeIntersect, NoneNeverHit) {
  const auto s = make("none", {});
  EXPECT_FALSE(cast(s, Vec3(0, 0, -5), Vec3(0, 0, 1)).hit);
  EXPECT_FALSE(g::shape_contains(s, Vec3::Zero()));
}

// Random rays from outside aimed near each shape: hits lie on the surface,
// normals are unit, outward (against the ray) and agree with shape_normal.
TEST(ShapeIntersect, NormalsUnitOutwardOnSurface) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unif(-1.5, 1.5);
  const std::vector<std::pair<std::string, std::vector<double>>> shapes = {
      {"sphere", {1.0}},       {"oblate", {1.5, 1.0}},          {"box", {1.0, 2.0, 3.0}}, {"plate", {2.0, 1.0}},
      {"cylinder", {1.0, 2.0}}, {"cone", {1.0, 2.0}}, {"coupler", {1.0, 0.4, 2.0}}};
  for (const auto& [name, dims] : shapes) {
    const auto s = make(name, dims);
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 o = 10.0 * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
      const Vec3 aim(unif(rng), unif(rng), unif(rng));
      const Vec3 d = (aim - o).normalized();
      const Result r = cast(s, o, d);
      if (!r.hit) continue;
      ++hits;
      ASSERT_TRUE(std::isfinite(r.t)) << name;
      EXPECT_NEAR(r.n.norm(), 1.0, 1e-12) << name;
      EXPECT_LT(r.n.dot(d), 1e-12) << name;
      const Vec3 p = o + r.t * d;
      const Vec3 n2 = g::shape_normal(s, p);
      if (name != "plate") {
        EXPECT_GT(n2.dot(r.n), 0.99) << name << " at " << p.transpose();
      }
      // Nearest: a slightly earlier start point gives the same hit.
      double t2 = 0;
      Vec3 nn;
      ASSERT_TRUE(g::intersect_shape(s, o + 0.5 * r.t * d, d, 0.0, kInf, t2, nn)) << name;
      EXPECT_NEAR(t2, 0.5 * r.t, 1e-9) << name;
    }
    EXPECT_GT(hits, 100) << name;
  }
}

TEST(ShapeIntersect, GrazingRaysNoNaN) {
  const auto s = make("sphere", {1.0});
  double t = 0;
  Vec3 n;
  // Exactly tangent: a hit at t = 5 or a miss, never NaN.
  if (g::intersect_shape(s, Vec3(1, 0, -5), Vec3(0, 0, 1), 0.0, kInf, t, n)) {
    EXPECT_NEAR(t, 5.0, 1e-6);
    EXPECT_TRUE(n.allFinite());
  }
  for (double eps : {1e-17, 1e-16, 1e-12, -1e-12, -1e-16}) {
    for (const char* name : {"sphere", "oblate", "cylinder", "cone", "coupler", "box"}) {
      const std::string shape = name;
      const auto sh = make(name, shape == "coupler" ? std::vector<double>{1.0, 1.0, 2.0}
                                 : shape == "box"   ? std::vector<double>{2.0, 2.0, 2.0}
                                 : shape == "sphere" ? std::vector<double>{1.0}
                                                     : std::vector<double>{1.0, 2.0});
      const Vec3 d = Vec3(0, eps, 1).normalized();
      if (g::intersect_shape(sh, Vec3(1, 0, -5), d, 0.0, kInf, t, n)) {
        EXPECT_TRUE(std::isfinite(t)) << name;
        EXPECT_TRUE(n.allFinite()) << name;
      }
    }
  }
}

TEST(ShapeIntersect, EarthLimbFromGeo) {
  // WGS84 ellipsoid, observer at GEO radius on the x axis (equatorial plane).
  const double a = 6378137.0, c = 6356752.314245, D = 42164.2e3;
  const auto s = make("oblate", {a, c});
  const Vec3 o(D, 0, 0);
  double t = 0;
  Vec3 n;
  const double limb_eq = std::asin(a / D);
  for (double sign : {-1.0, 1.0}) {
    const double th = limb_eq + sign * 1e-9;
    const Vec3 d(-std::cos(th), std::sin(th), 0);
    EXPECT_EQ(g::intersect_shape(s, o, d, 0.0, kInf, t, n), sign < 0) << sign;
  }
  // Polar limb: the tangent from (D, 0) to the meridian ellipse has sin = c / sqrt(D^2 - a^2 + c^2).
  const double limb_pol = std::asin(c / std::sqrt(D * D - a * a + c * c));
  for (double sign : {-1.0, 1.0}) {
    const double th = limb_pol + sign * 1e-9;
    const Vec3 d(-std::cos(th), 0, std::sin(th));
    EXPECT_EQ(g::intersect_shape(s, o, d, 0.0, kInf, t, n), sign < 0) << sign;
  }
  // Centre ray: range D - a.
  ASSERT_TRUE(g::intersect_shape(s, o, Vec3(-1, 0, 0), 0.0, kInf, t, n));
  EXPECT_NEAR(t, D - a, 1e-6);
}

// Documented behaviour: rays from inside a closed shape see nothing of it.
TEST(ShapeIntersect, ObserverInsideSeesNothing) {
  const auto s = make("sphere", {10.0});
  EXPECT_TRUE(g::shape_contains(s, Vec3(1, 2, 3)));
  EXPECT_FALSE(g::shape_contains(s, Vec3(10, 0, 0)));  // on the surface: outside
  EXPECT_FALSE(cast(s, Vec3(1, 2, 3), Vec3(0, 0, 1)).hit);
  const auto b = make("box", {2, 2, 2});
  EXPECT_TRUE(g::shape_contains(b, Vec3(0.5, 0, 0)));
  EXPECT_FALSE(cast(b, Vec3(0.5, 0, 0), Vec3(1, 0, 0)).hit);
  const auto cy = make("cone", {1, 2});
  EXPECT_TRUE(g::shape_contains(cy, Vec3(0.1, 0, 0)));
  EXPECT_FALSE(g::shape_contains(cy, Vec3(0.6, 0, 0)));
  EXPECT_FALSE(cast(cy, Vec3(0.1, 0, 0), Vec3(1, 0, 0)).hit);
}

TEST(ShapeIntersect, SurfaceAreas) {
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(g::shape_surface_area_m2(make("sphere", {2.0})), 16 * pi, 1e-12);
  // WGS84 ellipsoid area 5.10065621724e14 m^2.
  const double a = 6378137.0, c = 6356752.314245;
  const double e = std::sqrt(1 - c * c / (a * a));
  const double wgs = 2 * pi * a * a * (1 + (1 - e * e) / e * std::atanh(e));
  EXPECT_NEAR(g::shape_surface_area_m2(make("oblate", {a, c})) / wgs, 1.0, 1e-13);
  EXPECT_NEAR(wgs, 5.10065621724e14, 1e4);
  // Prolate.
  const double ap = 1.0, cp = 2.0, ep = std::sqrt(1 - ap * ap / (cp * cp));
  EXPECT_NEAR(g::shape_surface_area_m2(make("oblate", {ap, cp})),
              2 * pi * ap * ap * (1 + cp / (ap * ep) * std::asin(ep)), 1e-12);
  // Nearly spherical (series branch).
  EXPECT_NEAR(g::shape_surface_area_m2(make("oblate", {1.0, 1.0 - 1e-9})), 4 * pi, 1e-7);
  EXPECT_NEAR(g::shape_surface_area_m2(make("cone", {3.0, 4.0})), pi * 3 * 5 + pi * 9, 1e-12);
}

// intersect_spheroid_rays (a tile's rays against a sphere or spheroid, four
// at a time with AVX) gives every ray exactly what intersect_shape gives it:
// the Earth from GEO and from low orbit (hits, misses, rays grazing the limb
// to within 1e-9 of its angle, t_max cutting a hit off), a 1 m sphere from
// 10 km, every count of rays 0..9 (the last 1-3 rays by the scalar code).
TEST(ShapeIntersect, SpheroidRaysAreEachRaysIntersection) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const struct {
    g::ShapeGeom shape;
    Vec3 origin;
  } cases[] = {{make("oblate", {6378137.0, 6356752.314245}), Vec3(-42164e3, 1200.0, -300.0)},
               {make("oblate", {6378137.0, 6356752.314245}), Vec3(-3e6, -6.1e6, 2e6)},
               {make("sphere", {1.0}), Vec3(1e4, 20.0, -5.0)}};
  long compared = 0, hits = 0, misses = 0;
  for (const auto& c : cases) {
    const Vec3 to_centre = -c.origin.normalized();
    // the limb's half-angle from the origin (bounding sphere)
    const double limb = std::asin(std::min(1.0, c.shape.a_m / c.origin.norm()));
    std::vector<Vec3> dir;
    for (int k = 0; k < 4000; ++k) {
      // directions within ~1.2 limb angles of the centre, some on the limb itself
      const Vec3 side = to_centre.cross(Vec3(u(rng), u(rng), u(rng))).normalized();
      const double angle = k % 5 == 0 ? limb * (1.0 + 1e-9 * u(rng)) : 1.2 * limb * std::fabs(u(rng));
      dir.push_back((std::cos(angle) * to_centre + std::sin(angle) * side).normalized());
    }
    std::vector<double> t_max(dir.size());
    for (std::size_t k = 0; k < dir.size(); ++k)
      t_max[k] = k % 7 == 0 ? c.origin.norm() * (0.9 + 0.2 * std::fabs(u(rng))) : kInf;
    for (int n : {0, 1, 2, 3, 4, 5, 7, 9, static_cast<int>(dir.size())}) {
      std::vector<char> hit(static_cast<std::size_t>(n) + 1);
      std::vector<double> t(static_cast<std::size_t>(n) + 1, -1.0);
      std::vector<Vec3> normal(static_cast<std::size_t>(n) + 1, Vec3::Zero());
      bool* hit_ptr = reinterpret_cast<bool*>(hit.data());
      g::intersect_spheroid_rays(c.shape, c.origin, dir.data(), n, t_max.data(), hit_ptr, t.data(), normal.data());
      for (int i = 0; i < n; ++i) {
        double t1 = 0;
        Vec3 n1;
        const bool h1 = g::intersect_shape(c.shape, c.origin, dir[static_cast<std::size_t>(i)], 0.0,
                                           t_max[static_cast<std::size_t>(i)], t1, n1);
        ASSERT_EQ(hit_ptr[i], h1) << "ray " << i;
        ++compared;
        if (!h1) {
          ++misses;
          continue;
        }
        ++hits;
        EXPECT_EQ(t[static_cast<std::size_t>(i)], t1) << "ray " << i;
        EXPECT_EQ(normal[static_cast<std::size_t>(i)], n1) << "ray " << i;
      }
    }
  }
  // both outcomes well represented
  EXPECT_GT(compared, 12000);
  EXPECT_GT(hits, 5000);
  EXPECT_GT(misses, 2000);
}
