// Resolved objects that move during the integration (issue 23 item 5;
// scene/motion_substeps.hpp). Spec 5.1 assumption 6 holds the scene still
// over the integration: the image of eq. 49 is the scene at the frame time.
// With the sensor property motion_substeps = N the scene is the mean of N
// scenes at t + ((k + 1/2) / N - 1/2) t_i, so a resolved object smears into
// an extended streak with its energy kept.
//
// Scene: the gray-body sphere of spec 7.2.2 (300 K, reflectance 0: one
// radiance over its disc, whatever the lighting), 500 km from a sensor at
// rest, crossing its 0.1 deg field at 7.5 km/s across the line of sight (a
// LEO satellite at the zenith of a ground telescope), 8-12 um.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scenario_host.hpp"

namespace eoir::test {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double fov_deg = 0.1;
constexpr int pixels = 128;
constexpr int samples_per_pixel = 4;
constexpr double observer_x_m = 7000e3;  // the sensor's host, at rest on +x J2000 (boresight +z)

// The scenario of spec 7.2.2 with Satellite2 (radius_m) at `mid` (J2000, m)
// at start + 150 s moving at `velocity` (m/s), the sensor as above.
ScenarioHost sphere_host(double radius_m, const double mid[3], const double velocity[3], double integration_time_ms) {
  return ScenarioHost("valid_sens_uniform_ext_area_src.json", [&](nlohmann::json& doc) {
    doc["stop"] = "2010-08-25T18:05:00Z";
    auto& target = doc["objects"][1];
    auto& points = target["motion"]["points"];
    for (int i = 0; i < 2; ++i) {
      const double dt_s = i == 0 ? -150.0 : 150.0;
      for (int j = 0; j < 3; ++j) {
        points[i]["position_m"][j] = mid[j] + velocity[j] * dt_s;
        points[i]["velocity_m_s"][j] = velocity[j];
      }
    }
    target["properties"]["dimensions_m"] = nlohmann::json::array({radius_m});
    auto& p = doc["sensors"][0]["parameters"];
    p["horizontal_fov_deg"] = fov_deg;
    p["vertical_fov_deg"] = fov_deg;
    p["horizontal_pixels"] = pixels;
    p["vertical_pixels"] = pixels;
    p["integration_time_ms"] = integration_time_ms;
    p["sensitivity_pairs"] = nlohmann::json::array({integration_time_ms, 1e-9});
    p["saturation_pairs"] = nlohmann::json::array({integration_time_ms, 0.004});
    p["noise_enabled"] = false;
    p["samples_per_pixel"] = samples_per_pixel;
  });
}

// The light of a scene radiance image, sum L dOmega (W/cm^2; pinhole:
// dOmega = (tangent step)^2 cos^3 theta), its centroid and variance along
// each axis in angle (rad) from the boresight.
struct Moments {
  double flux = 0, mean_x = 0, mean_y = 0, var_x = 0, var_y = 0;
};
Moments moments(const Image& img) {
  const double step = 2.0 * std::tan(0.5 * fov_deg * pi / 180.0) / img.width;
  Moments m;
  double sx = 0, sy = 0, sxx = 0, syy = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double tx = (0.5 * img.width - x - 0.5) * step, ty = (0.5 * img.height - y - 0.5) * step;
      const double e = img.at(x, y) * step * step / std::pow(1.0 + tx * tx + ty * ty, 1.5);
      const double ax = std::atan(tx), ay = std::atan(ty);
      m.flux += e;
      sx += e * ax;
      sy += e * ay;
      sxx += e * ax * ax;
      syy += e * ay * ay;
    }
  m.mean_x = sx / m.flux;
  m.mean_y = sy / m.flux;
  m.var_x = sxx / m.flux - m.mean_x * m.mean_x;
  m.var_y = syy / m.flux - m.mean_y * m.mean_y;
  return m;
}

struct Frame {
  Moments scene;
  double electrons = 0;
  Image radiance;
};
Frame render(ScenarioHost& host, int substeps) {
  host.set_number("Sensor1", "motion_substeps", substeps);
  host.render();
  Frame f;
  f.radiance = host.image(EOIR_IMAGE_SCENE_RADIANCE);
  f.scene = moments(f.radiance);
  f.electrons = host.image(EOIR_IMAGE_SENSOR_ELECTRONS).sum();
  return f;
}

// A LEO satellite (a sphere of 10 m radius) crossing the field in 40 ms: with
// 16 sub-steps its image holds the
// energy of the same object at rest within 0.5 % (the figure) and
// is a streak along the motion as long as the angle it sweeps in the
// integration, 2 atan(v t_i / 2 / R) (straight motion across the line of
// sight, centred on the frame time): N discs evenly spaced over a length l
// add l^2 (N^2 - 1) / (12 N^2) to the variance of one disc along the motion
// and nothing across it.
TEST(MotionSubsteps, LeoStreakKeepsItsEnergyAndSweptLength) {
  constexpr double radius_m = 10.0, range_m = 500e3, speed_m_s = 7500.0, integration_time_ms = 40.0;
  constexpr int substeps = 16;
  const double mid[3] = {observer_x_m, 0.0, range_m};
  const double rest_v[3] = {0.0, 0.0, 0.0}, moving_v[3] = {speed_m_s, 0.0, 0.0};
  ScenarioHost rest = sphere_host(radius_m, mid, rest_v, integration_time_ms);
  ScenarioHost moving = sphere_host(radius_m, mid, moving_v, integration_time_ms);
  rest.at(150.0);
  moving.at(150.0);
  const Frame still = render(rest, 1);
  const Frame frozen = render(moving, 1);    // spec 5.1 assumption 6: the scene at the frame time
  const Frame smeared = render(moving, substeps);

  // The object at rest: the closed form L pi r^2 / R^2 (eq. 58 of a sphere).
  const double L = reference_band_radiance_8_12(300.0);
  const double sphere_W_cm2 = L * pi * radius_m * radius_m / (range_m * range_m);
  EXPECT_NEAR(still.scene.flux / sphere_W_cm2, 1.0, 0.01);
  // Assumption 6 (one sub-step): the moving object is imaged where it is at the frame time.
  EXPECT_NEAR(frozen.scene.flux / still.scene.flux, 1.0, 1e-12);
  EXPECT_NEAR(frozen.scene.var_x / still.scene.var_x, 1.0, 1e-9);

  // The streak's energy: the object at rest's, scene and sensor image.
  EXPECT_NEAR(smeared.scene.flux / still.scene.flux, 1.0, 0.005);
  EXPECT_NEAR(smeared.electrons / still.electrons, 1.0, 0.005);
  std::printf("flux: at rest %.6e W/cm2 (closed form %.6e), streak %.6e (ratio %.6f); electrons ratio %.6f\n",
              still.scene.flux, sphere_W_cm2, smeared.scene.flux, smeared.scene.flux / still.scene.flux,
              smeared.electrons / still.electrons);

  // Its length along the motion (+x J2000 is the image's -column axis).
  const double swept_rad = 2.0 * std::atan(0.5 * speed_m_s * integration_time_ms * 1e-3 / range_m);
  const double n = substeps;
  const double added = smeared.scene.var_x - still.scene.var_x;
  ASSERT_GT(added, 0.0);
  const double length_rad = std::sqrt(added * 12.0 * n * n / (n * n - 1.0));
  EXPECT_NEAR(length_rad / swept_rad, 1.0, 0.02);
  // Centred where the object is at the frame time; nothing across the motion.
  const double sample_rad = 2.0 * std::tan(0.5 * fov_deg * pi / 180.0) / (pixels * samples_per_pixel);
  EXPECT_NEAR(smeared.scene.mean_x, still.scene.mean_x, 0.1 * sample_rad);
  EXPECT_NEAR(smeared.scene.var_y / still.scene.var_y, 1.0, 0.05);
  // Visibly a streak: its length is many times the disc's width.
  const double disc_rad = 2.0 * radius_m / range_m;
  EXPECT_GT(length_rad, 10.0 * disc_rad);
  std::printf("streak: %.6e rad measured, %.6e rad swept (ratio %.6f, %.1f pixels), disc %.2e rad\n", length_rad,
              swept_rad, length_rad / swept_rad, swept_rad / (sample_rad * samples_per_pixel), disc_rad);

  // Made in strips (scene_memory_max_mib 0: each strip's rows averaged over
  // the sub-steps), the same streak: scene radiance and electrons to 1e-9.
  moving.set_number("Sensor1", "scene_memory_max_mib", 0.0);
  const Frame strips = render(moving, substeps);
  EXPECT_NEAR(strips.scene.flux / smeared.scene.flux, 1.0, 1e-9);
  EXPECT_NEAR(strips.electrons / smeared.electrons, 1.0, 1e-9);
  double worst = 0;
  for (std::size_t i = 0; i < strips.radiance.values.size(); ++i)
    worst = std::max(worst, std::abs(strips.radiance.values[i] - smeared.radiance.values[i]));
  EXPECT_LE(worst, 1e-9 * *std::max_element(smeared.radiance.values.begin(), smeared.radiance.values.end()));
}

// Near the point/extended limit an object changes class within an
// integration; the frame time's class decides for every sub-step. A sphere
// of 5 m radius flies straight at the sensor (2 km/s, 60 s), its range within
// +-1.8 % of a frame-time range 1 % from the limit R* = r / sin(s / 2)
// (s the scene sample's angle, world.cpp's test), so the outer sub-steps
// lie on the other side of the limit.
constexpr double small_radius_m = 5.0;
double limit_range_m() {
  const double sample_rad = 2.0 * std::tan(0.5 * fov_deg * pi / 180.0) / (pixels * samples_per_pixel);
  return small_radius_m / std::sin(0.5 * sample_rad);
}

// A point source at the frame time: its point source (streaked over the
// integration) carries all its light, counted once; the sub-steps where it
// is nearer and larger than a sample add nothing to the resolved image.
TEST(MotionSubsteps, PointSourceAtFrameTimeIsCountedOnce) {
  const double mid[3] = {observer_x_m, 0.0, 1.01 * limit_range_m()}, v[3] = {0.0, 0.0, -2000.0};
  ScenarioHost host = sphere_host(small_radius_m, mid, v, 60000.0);
  host.at(150.0);
  const Frame one = render(host, 1);
  const Frame eight = render(host, 8);
  ASSERT_GT(one.electrons, 0.0);
  EXPECT_NEAR(eight.electrons / one.electrons, 1.0, 1e-9);
  // The resolved image holds nothing of it (the background's alone).
  const double L = reference_band_radiance_8_12(300.0);
  const double sphere_W_cm2 = L * pi * small_radius_m * small_radius_m / (mid[2] * mid[2]);
  EXPECT_NEAR(eight.scene.flux, one.scene.flux, 1e-9 * sphere_W_cm2);
  std::printf("electrons ratio 8 / 1 sub-steps: %.15f\n", eight.electrons / one.electrons);
}

// Resolved at the frame time: every sub-step images it resolved, also those
// where it is farther and smaller than a sample (small_extended, drawn to
// its point irradiance), so the frame holds the mean of its sub-steps'
// irradiance, pi r^2 L / R_k^2: the frame time's times the mean of
// (R / R_k)^2.
TEST(MotionSubsteps, ResolvedAtFrameTimeKeepsItsLightInEverySubstep) {
  constexpr int substeps = 8;
  constexpr double speed_m_s = 2000.0, integration_time_ms = 60000.0;
  const double range_m = 0.99 * limit_range_m();
  const double mid[3] = {observer_x_m, 0.0, range_m}, v[3] = {0.0, 0.0, -speed_m_s};
  ScenarioHost host = sphere_host(small_radius_m, mid, v, integration_time_ms);
  host.at(150.0);
  const Frame one = render(host, 1);
  const Frame many = render(host, substeps);
  double expected = 0;
  int beyond = 0;
  for (int k = 0; k < substeps; ++k) {
    const double offset_s = ((k + 0.5) / substeps - 0.5) * integration_time_ms * 1e-3;
    const double r_k = range_m - speed_m_s * offset_s;
    expected += (range_m / r_k) * (range_m / r_k) / substeps;
    beyond += r_k > limit_range_m();
  }
  ASSERT_GE(beyond, 1);  // some sub-steps lie past the limit
  ASSERT_GT(one.electrons, 0.0);
  EXPECT_NEAR(many.electrons / one.electrons / expected, 1.0, 0.005);
  EXPECT_NEAR(many.scene.flux / one.scene.flux / expected, 1.0, 0.005);
  std::printf("%d of %d sub-steps past the limit; electrons %.6f, scene %.6f of the expected\n", beyond, substeps,
              many.electrons / one.electrons / expected, many.scene.flux / one.scene.flux / expected);
}

}  // namespace
}  // namespace eoir::test
