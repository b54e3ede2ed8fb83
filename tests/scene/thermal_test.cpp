// The subsolar thermal model of spec 4.3.1.3 (eq. 12) and the coarse and
// smooth scene modes of spec 4.2: the full Moon of V_Test1 seen through a
// 0.6 deg field.
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <set>

#include "scenario_host.hpp"

using eoir::test::ScenarioHost;

namespace {
std::unique_ptr<ScenarioHost> moon_view(const char* mode, const char* band_integration = "grid") {
  auto host = std::make_unique<ScenarioHost>("v_test1.json", [mode, band_integration](nlohmann::json& doc) {
    auto& p = doc["sensors"][0]["parameters"];
    p["band_integration"] = band_integration;
    p["horizontal_fov_deg"] = 0.6;
    p["vertical_fov_deg"] = 0.6;
    p["scene_mode"] = mode;
    doc["sensors"][0]["pointing"] = {{"type", "target"}, {"target", "Moon"}};
  });
  host->set_string("Moon", "material", "gray_body");      // a black body: radiance = B(T)
  host->set_string("Moon", "thermal_model", "subsolar");  // T_ss 390 K, night 95 K by default
  host->render();
  return host;
}

using Vec = std::array<double, 3>;
eoir_state state(ScenarioHost& host, const char* name) {
  eoir_state s{};
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  EXPECT_EQ(host.api().object_get_state(host.handle(), name, &s), EOIR_OK);
  return s;
}
Vec position(ScenarioHost& host, const char* name) {
  const eoir_state s = state(host, name);
  return {s.position[0], s.position[1], s.position[2]};
}
// Where the sensor sees the Moon's centre: one light time ago (linear in its
// velocity), displaced by the aberration of the sensor's velocity (first
// order), as astronomers' apparent places of the Moon are.
Vec apparent_moon_centre(ScenarioHost& host) {
  const eoir_state m = state(host, "Moon"), s = state(host, "Sensor1");
  const double c = 299792458.0;
  Vec p{}, beta{};
  double range = 0;
  for (int i = 0; i < 3; ++i) range += (m.position[i] - s.position[i]) * (m.position[i] - s.position[i]);
  const double tau = std::sqrt(range) / c;
  range = 0;
  for (int i = 0; i < 3; ++i) {
    p[i] = m.position[i] - m.velocity[i] * tau - s.position[i];
    range += p[i] * p[i];
    beta[i] = s.velocity[i] / c;
  }
  range = std::sqrt(range);
  const double along = (beta[0] * p[0] + beta[1] * p[1] + beta[2] * p[2]) / range;
  return {s.position[0] + p[0] + range * (beta[0] - along * p[0] / range),
          s.position[1] + p[1] + range * (beta[1] - along * p[1] / range),
          s.position[2] + p[2] + range * (beta[2] - along * p[2] / range)};
}
Vec unit_difference(const Vec& a, const Vec& b) {
  const double n = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  return {(a[0] - b[0]) / n, (a[1] - b[1]) / n, (a[2] - b[2]) / n};
}

}  // namespace

// Smooth mode: each sample's temperature is T_ss cos^(1/4) of its own angle
// from the subsolar point (eq. 12) on the day side, computed here from the
// pick's surface point (the sensor's position plus the range along the
// sample's RA/Dec) about the Moon's apparent centre and the Sun's direction (within 0.05 K); with exact band integration its radiance equals
// the band integral of that temperature within 0.1 % (the L(T) table). On
// the night side (the Sun below 0.7 deg, where the night branch starts) the
// surface cools from the dusk value 390 sin^(1/4)(0.7 deg) = 129.7 K toward
// the reported minimum of 95 K at dawn (spec 4.3.1.3; the law itself is
// tested in tests/scene_units).
TEST(Thermal_4_3_1_3, SmoothModeFollowsEquation12) {
  auto host = moon_view("smooth", "exact");
  const Vec moon = apparent_moon_centre(*host), sensor = position(*host, "Sensor1");
  const Vec sun = unit_difference(position(*host, "Sun"), moon);
  int checked = 0;
  for (int y = 16; y < 512; y += 32)
    for (int x = 16; x < 512; x += 32) {
      const auto p = host->pick(x, y);
      if (p.object != "Moon") continue;
      eoir_pick full{};
      full.struct_size = sizeof full;
      size_t count = 0;
      ASSERT_EQ(host->api().pick_get(host->handle(), "Sensor1", 0, x, y, &full, nullptr, nullptr, 0, &count), EOIR_OK);
      // Outward normal of the sphere (the Moon's ellipsoid is a sphere) at
      // the surface point the sample ends on.
      const double ra = full.right_ascension_deg * M_PI / 180, dec = full.declination_deg * M_PI / 180;
      const Vec point{sensor[0] + full.range_m * std::cos(dec) * std::cos(ra),
                      sensor[1] + full.range_m * std::cos(dec) * std::sin(ra), sensor[2] + full.range_m * std::sin(dec)};
      const Vec n = unit_difference(point, moon);
      const double c = n[0] * sun[0] + n[1] * sun[1] + n[2] * sun[2];
      if (c < std::sin(0.7 * M_PI / 180)) {  // night
        EXPECT_GE(full.temperature_K, 95.0 - 1e-9) << x << "," << y;
        EXPECT_LE(full.temperature_K, 129.8) << x << "," << y;
        continue;
      }
      const double expected_T = 390.0 * std::pow(c, 0.25);
      EXPECT_NEAR(full.temperature_K, expected_T, 0.05) << x << "," << y;
      EXPECT_NEAR(p.effective_radiance / eoir::test::reference_band_radiance_8_12(expected_T), 1.0, 1e-3) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 50);
}

// Coarse mode takes one value per patch dA (the Moon has ~830 patches of
// ~210 km): far fewer distinct radiances across the disc than smooth mode,
// with the same mean within 2 %.
TEST(Thermal_4_3_1_3, CoarseModeIsPiecewiseConstantPerPatch) {
  auto coarse = moon_view("coarse");
  auto smooth = moon_view("smooth");
  std::set<double> coarse_values, smooth_values;
  double coarse_sum = 0, smooth_sum = 0;
  int n = 0;
  for (int y = 0; y < 512; y += 8)
    for (int x = 0; x < 512; x += 8) {
      const auto c = coarse->pick(x, y), s = smooth->pick(x, y);
      if (c.object != "Moon" || s.object != "Moon") continue;
      coarse_values.insert(c.effective_radiance);
      smooth_values.insert(s.effective_radiance);
      coarse_sum += c.effective_radiance;
      smooth_sum += s.effective_radiance;
      ++n;
    }
  ASSERT_GT(n, 300);
  EXPECT_LT(coarse_values.size(), 450u);                 // at most the visible patches
  EXPECT_GT(smooth_values.size(), 4 * coarse_values.size());
  EXPECT_NEAR(coarse_sum / smooth_sum, 1.0, 0.02);
}
