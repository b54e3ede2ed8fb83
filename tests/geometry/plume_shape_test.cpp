// The rocket plume's shape (spec 4.3.6): a sphere with its tangent cone.
// Projected area (eq. 58) side-on and end-on against the closed forms,
// surface area, ray hits and the point -> patch rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/error.hpp"
#include "geometry/projected_area.hpp"
#include "geometry/scene_geometry.hpp"
#include "geometry/shape_intersect.hpp"

namespace g = eoir::geometry;
using g::Vec3;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double r = 1.5, L = 7.0;  // sphere radius, pole-to-apex length (m)
constexpr double h = L - r;         // apex from the sphere's centre

g::ShapePart plume() { return g::ShapePart{g::shape_geom(eoir::universe::ShapeKind::plume, {r, L})}; }

double patch_sum_area(const Vec3& v, double edge) {
  const std::vector<g::ShapePart> parts{plume()};
  const g::Tessellation t = g::tessellate(parts, edge);
  return g::projected_area_m2(parts, t, v);
}
}  // namespace

// End-on (either way) the silhouette is the sphere's disc: the cone lies
// within it (its widest circle, r sqrt(1 - r^2/h^2), is inside r).
TEST(PlumeShape, ProjectedAreaEndOnIsTheSpheresDisc) {
  const double closed = kPi * r * r;
  for (const Vec3& v : {Vec3(Vec3::UnitZ()), Vec3(-Vec3::UnitZ())}) {
    const double ratio = patch_sum_area(v, r / 60) / closed;
    std::printf("end-on (%+g): patch sum / pi r^2 - 1 = %.2e\n", v.z(), ratio - 1);
    EXPECT_NEAR(ratio, 1.0, 1e-3);
  }
}

// Side-on: the disc and the triangle of the two tangent lines from the apex:
// r sqrt(h^2 - r^2) (the kite centre-tangent-apex-tangent) plus the disc less
// the sector of angle 2 arccos(r/h) inside the kite.
TEST(PlumeShape, ProjectedAreaSideOnIsDiscPlusTangentTriangle) {
  const double closed = r * std::sqrt(h * h - r * r) + r * r * (kPi - std::acos(r / h));
  for (const Vec3& v : {Vec3(Vec3::UnitX()), Vec3(0, -1, 0)}) {
    const double ratio = patch_sum_area(v, r / 60) / closed;
    std::printf("side-on: patch sum / closed form - 1 = %.2e\n", ratio - 1);
    EXPECT_NEAR(ratio, 1.0, 1e-3);
  }
}

// Surface area: the sphere below the tangent circle (a zone, 2 pi r dz) and
// the cone's side (pi rho s, s the tangent length sqrt(h^2 - r^2)); the
// patches sum to it.
TEST(PlumeShape, SurfaceAreaClosedFormAndPatches) {
  const double zt = r * r / h, rho = r * std::sqrt(1 - r * r / (h * h)), s = std::sqrt(h * h - r * r);
  const double closed = 2 * kPi * r * (r + zt) + kPi * rho * s;
  EXPECT_NEAR(g::shape_surface_area_m2(plume().geom) / closed, 1.0, 1e-12);
  const g::Tessellation t = g::tessellate({plume()}, r / 10);
  double sum = 0;
  for (const g::Patch& p : t.patches) sum += p.area_m2;
  EXPECT_NEAR(sum / closed, 1.0, 1e-9);
}

TEST(PlumeShape, RayHits) {
  const g::ShapeGeom s = plume().geom;
  double t = 0;
  Vec3 n;
  // Along the axis from beyond the apex: the apex.
  ASSERT_TRUE(g::intersect_shape(s, Vec3(0, 0, 100), -Vec3::UnitZ(), 0, 1e9, t, n));
  EXPECT_NEAR(t, 100 - h, 1e-9);
  // From the other end: the sphere's pole, normal -z.
  ASSERT_TRUE(g::intersect_shape(s, Vec3(0, 0, -100), Vec3::UnitZ(), 0, 1e9, t, n));
  EXPECT_NEAR(t, 100 - r, 1e-9);
  EXPECT_NEAR(n.z(), -1.0, 1e-12);
  // Side-on through the centre: the sphere's equator.
  ASSERT_TRUE(g::intersect_shape(s, Vec3(100, 0, 0), -Vec3::UnitX(), 0, 1e9, t, n));
  EXPECT_NEAR(t, 100 - r, 1e-9);
  // Side-on halfway along the cone: its radius there, normal tilted by the
  // half-angle asin(r/h) toward +z.
  const double zt = r * r / h, rho_t = r * std::sqrt(1 - r * r / (h * h));
  const double z = 0.5 * (zt + h), rho = rho_t * (h - z) / (h - zt);
  ASSERT_TRUE(g::intersect_shape(s, Vec3(100, 0, z), -Vec3::UnitX(), 0, 1e9, t, n));
  EXPECT_NEAR(t, 100 - rho, 1e-9);
  EXPECT_NEAR(n.z(), r / h, 1e-9);
  // Past the apex: a miss; inside: seen from within, nothing (outward faces only).
  EXPECT_FALSE(g::intersect_shape(s, Vec3(100, 0, h + 1e-6), -Vec3::UnitX(), 0, 1e9, t, n));
  EXPECT_FALSE(g::intersect_shape(s, Vec3(0, 0, 0), Vec3::UnitX(), 0, 1e9, t, n));
  EXPECT_TRUE(g::shape_contains(s, Vec3(0, 0, 0.5 * (zt + h))));
  EXPECT_FALSE(g::shape_contains(s, Vec3(0, 0, h + 0.01)));
  EXPECT_NEAR(g::shape_bounding_radius_m(s), h, 1e-12);
}

// Every surface point maps to a patch of its own part near it, whose normal
// is the surface's there (continuous across the tangent circle).
TEST(PlumeShape, PointToPatchRule) {
  const std::vector<g::ShapePart> parts{plume()};
  const double edge = r / 8;
  const g::Tessellation t = g::tessellate(parts, edge);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss;
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o = 3 * h * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const Vec3 aim = 0.4 * r * Vec3(gauss(rng), gauss(rng), gauss(rng)) + Vec3(0, 0, 0.3 * h);
    const Vec3 d = (aim - o).normalized();
    double tt = 0;
    Vec3 n;
    if (!g::intersect_shape(parts[0].geom, o, d, 0, 1e9, tt, n)) continue;
    const Vec3 p = o + tt * d;
    EXPECT_LT((g::shape_normal(parts[0].geom, p) - n).norm(), 1e-6);
    const std::int32_t k = g::patch_at_facing(t, parts, 0, p, n);
    ASSERT_GE(k, 0);
    ASSERT_LT(static_cast<std::size_t>(k), t.patches.size());
    EXPECT_LT((t.patches[static_cast<std::size_t>(k)].centre_body_m - p).norm(), 4.0 * edge) << p.transpose();  // (the equal-area ring at the apex is long)
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(PlumeShape, LengthMustExceedTwiceTheRadius) {
  EXPECT_THROW(g::shape_geom(eoir::universe::ShapeKind::plume, {1.0, 2.0}), eoir::Error);
  EXPECT_THROW(g::shape_geom(eoir::universe::ShapeKind::plume, {1.0}), eoir::Error);
  EXPECT_NO_THROW(g::shape_geom(eoir::universe::ShapeKind::plume, {1.0, 2.5}));
}
