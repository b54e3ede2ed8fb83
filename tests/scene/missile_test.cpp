// Missiles (spec 4.3.6): stages stacked along the body's +z, their timing,
// and their plumes (a sphere with its tangent cone, a gray body of emittance
// 0.99 or a tabulated radiance), hidden by the hardbody in the detailed
// point-source sum (spec 4.1.6.1). The uniform-source scenario's Satellite2
// (1000 km along the sensor's boresight +z) is made a missile; with the
// identity attitude its tail (-z) faces the sensor. Picks are of pixels
// (space 1: a pixel's centre sample).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scenario_host.hpp"

using eoir::test::ScenarioHost;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Satellite2 made a missile with `stages` (missile_stages) launched at the
// scenario's start; its hardbody black (0 K, reflectance 0).
std::function<void(nlohmann::json&)> missile(const std::string& stages, const nlohmann::json& extra = {}) {
  return [=](nlohmann::json& doc) {
    for (auto& o : doc["objects"])
      if (o["name"] == "Satellite2") {
        o["kind"] = "missile";
        o["properties"] = {{"material", "gray_body"},
                           {"reflectance", 0.0},
                           {"temperature_K", 0.0},
                           {"missile_stages", stages},
                           {"launch_time_utc", doc["start"]}};
        for (auto it = extra.begin(); it != extra.end(); ++it) {
          if (it.key() == "attitude") {
            o["attitude"] = *it;
          } else if (it.key() == "position_m") {
            for (auto& p : o["motion"]["points"]) p["position_m"] = *it;
          } else {
            o["properties"][it.key()] = *it;
          }
        }
      }
    doc["sensors"][0]["parameters"]["band_integration"] = "exact";
  };
}
}  // namespace

// A plume's radiance is that of a gray body of emittance 0.99 (spec 4.3.6):
// 0.99 B(T) over the band, against an independent Simpson integral of eq. 5,
// to 1e-9.
TEST(Missile, PlumeBandRadianceIsGrayBody099) {
  for (double T : {700.0, 1500.0}) {
    const std::string stages = R"([{"length_m": 20e3, "radius_m": 3e3,
        "plume": {"temperature_K": )" + std::to_string(T) + R"(, "length_scale": 2}}])";
    ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages));
    host.at(1.0);
    host.render();
    const auto p = host.pick(64, 64, 1);
    ASSERT_TRUE(p.hit);
    EXPECT_EQ(p.object, "Satellite2");
    // The plume's apex (stage aft end at 1000 km, apex 37 km nearer).
    EXPECT_NEAR(p.range_m, 1000e3 - (40e3 - 3e3), 3e3);  // (the sample is off the axis by up to ~100 m)
    const double expected = 0.99 * eoir::test::reference_band_radiance_8_12(T);
    std::printf("T = %g K: L / (0.99 B) - 1 = %.2e\n", T, p.effective_radiance / expected - 1);
    EXPECT_NEAR(p.effective_radiance / expected, 1.0, 1e-9) << T;
  }
}

// A plume given a tabulated spectral radiance (spec 4.1.4's table) shows it
// instead: a flat 2e-4 W/(cm^2 sr um) over 8-12 um integrates to 8e-4.
TEST(Missile, PlumeTabulatedRadiance) {
  const std::string stages = R"([{"length_m": 20e3, "radius_m": 3e3,
      "plume": {"spectrum": "flat", "length_scale": 2}}])";
  ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages, {{"missile_stages", "[]"}}));
  const double wl[2] = {1.0, 20.0}, L[2] = {2e-4, 2e-4};
  ASSERT_EQ(host.api().spectrum_add(host.handle(), "flat", wl, L, 2), EOIR_OK) << host.api().last_error();
  host.set_string("Satellite2", "missile_stages", stages);
  host.at(1.0);
  host.render();
  const auto p = host.pick(64, 64, 1);
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.effective_radiance / 8e-4, 1.0, 1e-9);
}

// A stage shows until its separation and a plume over [on_s, off_s) of its
// stage's life, to the step (1 ms here). Stage 1 (radius 6 km) separates at
// 10 s with its plume (800 K) on from launch; stage 2 (radius 2 km, its time
// 0 the separation) lights its plume (1100 K) 2 s later. The sample 4.5 km
// off the axis sees stage 1's aft end (300 K) while it is attached, then
// nothing; the axis sees stage 1's plume, stage 2's aft end, its plume.
TEST(Missile, StagesAndPlumesAtTheirTimes) {
  const std::string stages = R"([
      {"length_m": 10e3, "radius_m": 6e3, "separation_s": 10,
       "parts": [{"shape": "cylinder", "dimensions_m": [6e3, 10e3], "offset_m": [0, 0, 5e3], "temperature_K": 300}],
       "plume": {"temperature_K": 800, "width_scale": 0.5, "length_scale": 1}},
      {"length_m": 10e3, "radius_m": 2e3,
       "parts": [{"shape": "cylinder", "dimensions_m": [2e3, 10e3], "offset_m": [0, 0, 5e3], "temperature_K": 300}],
       "plume": {"temperature_K": 1100, "on_s": 2, "length_scale": 1}}])";
  ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages));
  // 1 deg over 128 samples at 1000 km: 4.5 km off the axis is ~33 samples.
  const int off = static_cast<int>(std::lround(4.5e3 / (1000e3 * std::tan(kPi / 180) / 128)));
  const double L300 = eoir::test::reference_band_radiance_8_12(300);
  const double L800 = 0.99 * eoir::test::reference_band_radiance_8_12(800);
  const double L1100 = 0.99 * eoir::test::reference_band_radiance_8_12(1100);
  struct Expect {
    double t_s;
    bool ring_hit;
    double axis_radiance;
  };
  for (const Expect& e : {Expect{0.0, true, L800}, Expect{9.999, true, L800}, Expect{10.001, false, L300},
                          Expect{11.999, false, L300}, Expect{12.001, false, L1100}, Expect{100.0, false, L1100}}) {
    host.at(e.t_s);
    host.render();
    EXPECT_EQ(host.pick(64 + off, 64, 1).hit, e.ring_hit) << e.t_s;
    const auto axis = host.pick(64, 64, 1);
    ASSERT_TRUE(axis.hit) << e.t_s;
    EXPECT_NEAR(axis.effective_radiance / e.axis_radiance, 1.0, 1e-6) << e.t_s;
  }
}

// Before its launch the stack stands whole, without plumes.
TEST(Missile, NoPlumeBeforeLaunch) {
  const std::string stages = R"([{"length_m": 20e3, "radius_m": 3e3,
      "parts": [{"shape": "cylinder", "dimensions_m": [3e3, 20e3], "offset_m": [0, 0, 10e3], "temperature_K": 300}],
      "plume": {"temperature_K": 1500, "length_scale": 2}}])";
  ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages, {{"launch_time_utc", "2010-08-25T18:00:30Z"}}));
  host.at(29.0);
  host.render();
  auto p = host.pick(64, 64, 1);
  ASSERT_TRUE(p.hit);
  EXPECT_NEAR(p.range_m, 1000e3, 100.0);  // the stage's aft end
  EXPECT_NEAR(p.effective_radiance / eoir::test::reference_band_radiance_8_12(300), 1.0, 1e-6);
  host.at(31.0);
  host.render();
  p = host.pick(64, 64, 1);
  EXPECT_NEAR(p.effective_radiance / (0.99 * eoir::test::reference_band_radiance_8_12(1500)), 1.0, 1e-6);
}

// Detailed point source (spec 4.1.6.1): far away, the irradiance is the sum
// over the patches seen. Seen nose-on, the black stage (radius R) hides the
// middle of its plume (sphere radius r = 2R): the plume shows the annulus
// pi (r^2 - R^2), 3/4 of its disc; tail-on, the whole disc pi r^2 (the
// sphere's silhouette: the cone lies within it). Patches of r/100: 0.5 %.
TEST(Missile, HardbodyHidesThePlumeBehindIt) {
  const double R = 1e3, r = 2e3, D = 1e9, T = 1000;
  const std::string stages = R"([{"length_m": 5e3, "radius_m": 1e3,
      "plume": {"temperature_K": 1000, "width_scale": 2, "length_scale": 2}}])";
  const double L = 0.99 * eoir::test::reference_band_radiance_8_12(T);
  const nlohmann::json far = {{"position_m", {7000e3, 0.0, D}}, {"patch_size_m", r / 100}};
  {
    nlohmann::json nose = far;
    nose["attitude"] = {{"type", "fixed_inertial"}, {"quaternion", {0.0, 1.0, 0.0, 0.0}}};  // +z toward the sensor
    ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages, nose));
    host.at(1.0);
    const double E = host.target_metric("Effective Target Irradiance", "Satellite2");
    const double visible = E / (L * kPi * r * r / (D * D));
    std::printf("nose-on: visible fraction %.5f, geometry %.5f\n", visible, (r * r - R * R) / (r * r));
    EXPECT_NEAR(visible, (r * r - R * R) / (r * r), 0.005 * 0.75);
  }
  {
    ScenarioHost host("valid_sens_uniform_ext_area_src.json", missile(stages, far));
    host.at(1.0);
    const double E = host.target_metric("Effective Target Irradiance", "Satellite2");
    std::printf("tail-on: E / (L pi r^2 / D^2) = %.5f\n", E / (L * kPi * r * r / (D * D)));
    EXPECT_NEAR(E / (L * kPi * r * r / (D * D)), 1.0, 0.005);
  }
}
