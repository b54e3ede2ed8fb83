// Spec 6.1.1 (V_Test1) and 7.1 (Valid_Sens_FOVextent): projected angles and
// distance ordering of the scene generator's samples.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_host.hpp"

using eoir::test::ScenarioHost;

namespace {
constexpr double deg = 3.14159265358979323846 / 180.0;
}

// 6.1.1: from 42164.2 km the Earth fills the 17.4008 deg field; the sample at
// the centre sees the Earth 35,786.1 km away (42,164.2 - 6,378.1 km).
TEST(Spec_6_1_1, EarthFillsFieldFromGeo) {
  ScenarioHost host("v_test1.json");
  host.render();
  const auto centre = host.pick(256, 256);
  ASSERT_TRUE(centre.hit);
  EXPECT_EQ(centre.object, "Earth");
  // WGS84 a = 6378.137 km: the range is 35786.06 km (spec: 35786.1 with 6378.1);
  // the centre sample is half a sample off the axis. Tolerance 1 km.
  EXPECT_NEAR(centre.range_m / 1e3, 35786.1, 1.0);
  // Both ends of the central row and column are on the Earth (the limb is at
  // the field edge horizontally; the polar radius is 21 km shorter, so the
  // vertical limb lies up to 2 samples inside the edge).
  EXPECT_EQ(host.pick(0, 255).object, "Earth");
  EXPECT_EQ(host.pick(511, 256).object, "Earth");
  int top = 0;
  while (top < 512 && host.pick(256, top).object != "Earth") ++top;
  EXPECT_LE(top, 2);
}

// 6.1.1: the full Moon, behind the Earth and partly hidden by it, subtends
// 2 asin(1737.4 km / range) -- about 0.48 deg, 14 samples -- within one sample.
TEST(Spec_6_1_1, MoonBehindEarthPartlyHiddenWithTrueSubtense) {
  ScenarioHost host("v_test1.json");
  host.render();
  int moon = 0, best_column = -1, best_count = 0;
  double moon_range = 0;
  for (int x = 0; x < 512; ++x) {
    int count = 0;
    for (int y = 0; y < 512; ++y) {
      const auto p = host.pick(x, y);
      if (p.object == "Moon") {
        ++count;
        ++moon;
        moon_range = p.range_m;
      }
    }
    if (count > best_count) {
      best_count = count;
      best_column = x;
    }
  }
  ASSERT_GT(moon, 0) << "the Moon is not in the field";
  // Distance ordering: the Moon is beyond the Earth.
  EXPECT_GT(moon_range, 35786.1e3 * 10);
  // Angular subtense along the column through the Moon's widest part.
  const double sample_rad = 2.0 * std::tan(17.4008 / 2 * deg) / 512.0;  // near the edge: pinhole spacing
  const double expected_samples = 2.0 * std::asin(1737.4e3 / moon_range) / sample_rad;
  EXPECT_NEAR(best_count, expected_samples, 1.0) << "column " << best_column;
  // Partly hidden: along that column the Earth covers some samples that the
  // Moon's disc spans (the Moon is cut by the limb, not by the field edge).
  int first = -1, last = -1;
  for (int y = 0; y < 512; ++y)
    if (host.pick(best_column, y).object == "Moon") {
      if (first < 0) first = y;
      last = y;
    }
  int hidden = 0;
  for (int x = 0; x < 512; ++x)
    for (int y = first; y <= last; ++y) {
      if (host.pick(x, y).object != "Earth") continue;
      // An Earth sample inside the Moon's circle (centre estimated from the
      // column and row extents) is a hidden part of the Moon.
      const double cy = 0.5 * (first + last);
      const double r = 0.5 * expected_samples;
      if (std::hypot(x - best_column, y - cy) < r - 1.0) ++hidden;
    }
  EXPECT_GT(hidden, 0) << "the Moon should be partly hidden by the Earth";
}

// 7.1: with FOV 17.401 x 17.342 deg (2 asin(R/42164.2) for R = 6378.1 and
// 6356.8 km) the Earth fills the field exactly: the samples just inside each
// edge see the Earth, the guard samples just outside see the sky.
TEST(Spec_7_1, EarthExactlyFillsField) {
  ScenarioHost host("valid_sens_fov_extent.json");
  host.render();
  const int n = 512, mid = 256;
  EXPECT_EQ(host.pick(0, mid).object, "Earth");
  EXPECT_EQ(host.pick(n - 1, mid).object, "Earth");
  EXPECT_EQ(host.pick(mid, 0).object, "Earth");
  EXPECT_EQ(host.pick(mid, n - 1).object, "Earth");
  // Corners see the sky: the Earth is a disc inscribed in the field.
  EXPECT_FALSE(host.pick(0, 0).hit);
  EXPECT_FALSE(host.pick(n - 1, n - 1).hit);
  // The scene radiance image shows the same: zero in the corners.
  const auto radiance = host.image(EOIR_IMAGE_SCENE_RADIANCE);
  EXPECT_EQ(radiance.at(0, 0), 0.0);
  EXPECT_GT(radiance.at(0, mid), 0.0);
}

// 7.1, converse: widen the field by three samples on each side and the edge
// samples see the sky -- the Earth fills the nominal field and no more.
TEST(Spec_7_1, WiderFieldShowsSkyAtTheEdges) {
  ScenarioHost host("valid_sens_fov_extent.json", [](nlohmann::json& doc) {
    auto& p = doc["sensors"][0]["parameters"];
    for (const char* key : {"horizontal_fov_deg", "vertical_fov_deg"}) {
      const double fov = p[key].get<double>() * deg;
      // Same pixel count, tan(FOV/2) larger by 3 samples of 512.
      p[key] = 2.0 * std::atan(std::tan(fov / 2) * (1.0 + 6.0 / 512.0)) / deg;
    }
  });
  host.render();
  const int n = 512, mid = 256;
  EXPECT_FALSE(host.pick(0, mid).hit);
  EXPECT_FALSE(host.pick(n - 1, mid).hit);
  EXPECT_FALSE(host.pick(mid, 0).hit);
  EXPECT_FALSE(host.pick(mid, n - 1).hit);
  EXPECT_EQ(host.pick(4, mid).object, "Earth");
  EXPECT_EQ(host.pick(mid, 4).object, "Earth");
}
