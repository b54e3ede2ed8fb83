// Surface tessellation (spec 4.1.5.2): exact areas, patch count for the Earth
// at 785 km (spec 4.2.3), the O(1) point -> patch rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/scene_geometry.hpp"
#include "geometry/shape_intersect.hpp"

namespace g = eoir::geometry;
using g::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

g::ShapePart part(const std::string& shape, std::vector<double> dims) {
  return g::ShapePart{g::shape_geom(eoir::universe::parse_shape(shape, "shape"), dims)};
}

const std::vector<std::pair<std::string, std::vector<double>>>& all_shapes() {
  static const std::vector<std::pair<std::string, std::vector<double>>> s = {
      {"sphere", {1.0}},        {"oblate", {6378137.0, 6356752.314245}}, {"oblate", {1.0, 2.0}},
      {"box", {1.0, 2.0, 3.0}}, {"plate", {2.0, 1.0}},                   {"cylinder", {1.0, 2.0}},
      {"cone", {1.0, 2.0}},     {"coupler", {1.0, 0.4, 2.0}},            {"coupler", {0.3, 1.1, 0.7}}};
  return s;
}

// Size of the shape for choosing targets.
double scale(const std::vector<double>& d) { return *std::max_element(d.begin(), d.end()); }

// Random point on the surface: a ray from outside towards a random interior aim.
bool random_surface_point(const g::ShapeGeom& s, std::mt19937_64& rng, Vec3& p, Vec3& n) {
  std::normal_distribution<double> gauss;
  const double r = g::shape_bounding_radius_m(s);
  const Vec3 o = 3 * r * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
  const Vec3 aim = 0.5 * r * Vec3(gauss(rng), gauss(rng), gauss(rng));
  const Vec3 d = (aim - o).normalized();
  double t = 0;
  if (!g::intersect_shape(s, o, d, 0.0, 1e300, t, n)) return false;
  p = o + t * d;
  return true;
}

}  // namespace

TEST(Tessellation, AreasSumToSurfaceArea) {
  for (const auto& [name, dims] : all_shapes()) {
    const auto sp = part(name, dims);
    const double area = g::shape_surface_area_m2(sp.geom);
    for (double f : {10.0, 0.3, 0.05, 0.013}) {
      const auto t = g::tessellate({sp}, f * scale(dims));
      double sum = 0;
      for (const auto& p : t.patches) {
        EXPECT_GT(p.area_m2, 0.0);
        EXPECT_NEAR(p.normal_body.norm(), 1.0, 1e-12);
        sum += p.area_m2;
      }
      EXPECT_NEAR(sum / area, 1.0, 1e-6) << name << " target factor " << f;
      EXPECT_GE(t.patches.size(), name == "box" ? 6u : 1u);
    }
  }
}

TEST(Tessellation, PatchCentresOnSurfaceWithOutwardNormals) {
  for (const auto& [name, dims] : all_shapes()) {
    const auto sp = part(name, dims);
    const auto s = sp.geom;
    const auto t = g::tessellate({sp}, 0.1 * scale(dims));
    for (const auto& p : t.patches) {
      // Outward: moving along the normal leaves the shape; the normal matches the surface's.
      const Vec3 c = p.centre_body_m;
      EXPECT_FALSE(g::shape_contains(s, c + 1e-6 * scale(dims) * p.normal_body)) << name;
      if (name != "plate" && name != "box" && c.head<2>().norm() > 1e-9 * scale(dims)) {
        EXPECT_GT(g::shape_normal(s, c).dot(p.normal_body), 0.999) << name;
      }
    }
  }
}

TEST(Tessellation, EarthAt785kmHasAbout830Patches) {
  const auto t = g::tessellate({part("oblate", {6378137.0, 6356752.314245})}, 785e3);
  const double expected = 4 * kPi * 6371e3 * 6371e3 / (785e3 * 785e3);  // ~ 828
  EXPECT_NEAR(static_cast<double>(t.patches.size()) / expected, 1.0, 0.05) << t.patches.size();
  double min_a = 1e300, max_a = 0;
  for (const auto& p : t.patches) {
    min_a = std::min(min_a, p.area_m2);
    max_a = std::max(max_a, p.area_m2);
  }
  EXPECT_LT(max_a / min_a, 2.0);  // roughly equal areas
}

TEST(Tessellation, PatchAtReturnsEachPatchForItsCentre) {
  for (const auto& [name, dims] : all_shapes()) {
    const std::vector<g::ShapePart> parts = {part(name, dims)};
    const auto t = g::tessellate(parts, 0.07 * scale(dims));
    for (std::size_t k = 0; k < t.patches.size(); ++k) {
      const auto& p = t.patches[k];
      EXPECT_EQ(g::patch_at_facing(t, parts, 0, p.centre_body_m, p.normal_body), static_cast<int>(k)) << name;
    }
  }
}

TEST(Tessellation, PatchAtMostlyAgreesWithNearestCentre) {
  std::mt19937_64 rng(11);
  for (const auto& [name, dims] : all_shapes()) {
    const std::vector<g::ShapePart> parts = {part(name, dims)};
    const auto s = parts[0].geom;
    const auto t = g::tessellate(parts, 0.1 * scale(dims));
    int agree = 0, total = 0;
    for (int k = 0; k < 3000; ++k) {
      Vec3 p, n;
      if (!random_surface_point(s, rng, p, n)) continue;
      const int idx = g::patch_at_facing(t, parts, 0, p, n);
      ASSERT_GE(idx, 0);
      ASSERT_LT(idx, static_cast<int>(t.patches.size()));
      EXPECT_GT(t.patches[static_cast<std::size_t>(idx)].normal_body.dot(n), -0.5) << name;  // same face side
      int nearest = -1;
      double best = 1e300;
      for (std::size_t q = 0; q < t.patches.size(); ++q) {
        if (t.patches[q].normal_body.dot(n) < -0.5) continue;  // plate: other face
        const double dd = (t.patches[q].centre_body_m - p).squaredNorm();
        if (dd < best) {
          best = dd;
          nearest = static_cast<int>(q);
        }
      }
      agree += nearest == idx;
      ++total;
    }
    EXPECT_GT(total, 500) << name;
    EXPECT_GT(static_cast<double>(agree) / total, 0.75) << name;
  }
}

TEST(Tessellation, CompositeWithOffsetsAndOrientation) {
  std::vector<g::ShapePart> parts = {part("box", {1, 1, 2}), part("plate", {4, 1}), part("none", {}),
                                     part("cylinder", {0.2, 1})};
  parts[1].offset_m = Vec3(3, 0, 0);
  parts[1].orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  parts[3].offset_m = Vec3(0, 0, 1.5);
  parts[3].orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Vec3(1, 1, 0).normalized()));
  const auto t = g::tessellate(parts, 0.25);
  ASSERT_EQ(t.first_patch.size(), parts.size());
  double total = 0;
  for (std::size_t k = 0; k < t.patches.size(); ++k) {
    const auto& p = t.patches[k];
    total += p.area_m2;
    EXPECT_EQ(g::patch_at_facing(t, parts, p.part, p.centre_body_m, p.normal_body), static_cast<int>(k));
  }
  double expected = 0;
  for (const auto& sp : parts) expected += g::shape_surface_area_m2(sp.geom);
  EXPECT_NEAR(total / expected, 1.0, 1e-9);
  EXPECT_EQ(t.first_patch[2], t.first_patch[3]);  // none: no patches
  EXPECT_EQ(g::patch_at_facing(t, parts, 2, Vec3::Zero(), Vec3::UnitZ()), -1);
}
