// Issue 23 item 1 with spec 4.1.6.1 and the energy check of 6.2.5.1 (area
// source, detailed point source agree): an object's light in the image is
// its own point-source irradiance, the detailed sum of ERRATA eq. 11, at
// every range and through the point/extended transition, however thin its
// parts. scenarios/validation/v_small_objects.json: Satellite2, each of the
// three predefined composite satellites and a 1 m sphere, sunlit in
// 0.4-0.7 um and in the Earth's umbra in 8-12 um (thermal emission only),
// seen from Satellite1 at ranges from 1 to 40,000 km along one line of sight.
//
// Measured: Sensor1's noise-free image (EOIR_IMAGE_SENSOR_MEAN) summed and
// converted to irradiance, times the IFOV solid angle over the peak radiance
// responsivity (eqs. 31, 49-50). Expected: the point irradiance of the same
// object at the same instant in the target metrics of Sensor2, whose pixels
// (2.5 deg) make it a point target at every range (eq. 61), within 1 %; and
// the ratio continuous (within 0.5 % between neighbouring ranges 1.5x
// apart, where Sensor1's imaging moves from small extended to point source).
// Independent anchor: the sphere in the umbra against eps B(T) pi r^2 / R^2
// (Planck's law by Simpson, validation_support), within 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr const char* kScenario = "v_small_objects.json";
constexpr const char* kEpoch = "2010-06-01T00:00:00Z";
constexpr const char* kStop = "2010-06-01T00:01:00Z";
constexpr double kGeo = 42164.2e3;
constexpr double kSphereRadius = 0.5, kSphereReflectance = 0.5, kSphereTemperature = 300.0;

struct Case {
  std::string target;  // a predefined composite, or "sphere"
  bool lit = true;     // sunlit in 0.4-0.7 um, else in the umbra in 8-12 um
};

// The target at GEO radius on the dawn-dusk line (lit) or on the anti-Sun
// axis (deep in the umbra); the unit line of sight from the target toward
// the observer, away from the Earth.
void geometry(bool lit, v::V3& target, v::V3& toward_observer) {
  const v::V3 s = v::unit(v::sun_geocentric_m(kEpoch));
  const v::V3 e = v::unit(v::cross({0, 0, 1}, s));
  const v::V3 n = v::cross(s, e);
  if (lit) {
    target = kGeo * e;
    toward_observer = v::unit(0.6 * e + 0.5 * s + 0.62 * n);
  } else {
    target = -kGeo * s;
    toward_observer = v::unit(-0.7 * s + 0.5 * e + 0.45 * n);
  }
}

void set_observer(ScenarioHost& host, const v::V3& position) {
  eoir_state st{};
  st.struct_size = sizeof st;
  st.frame = EOIR_FRAME_J2000;
  for (int i = 0; i < 3; ++i) st.position[i] = position[static_cast<std::size_t>(i)];
  st.attitude[0] = 1.0;
  const eoir_status status = host.api().object_set_state(host.handle(), "Satellite1", nullptr, &st);
  ASSERT_EQ(status, EOIR_OK) << host.api().last_error();
}

void run(const Case& c) {
  v::V3 target{}, toward{};
  geometry(c.lit, target, toward);
  ScenarioHost host(kScenario, [&](nlohmann::json& doc) {
    v::set_fixed_j2000(v::object_named(doc, "Satellite1"), kEpoch, kStop, target + 1e6 * toward);
    nlohmann::json& sat2 = v::object_named(doc, "Satellite2");
    v::set_fixed_j2000(sat2, kEpoch, kStop, target);
    if (c.target == "sphere")
      sat2["properties"] = {{"shape", "sphere"},
                            {"dimensions_m", {kSphereRadius}},
                            {"reflectance", kSphereReflectance},
                            {"temperature_K", kSphereTemperature}};
    else
      sat2["properties"] = {{"shape", "composite"}, {"composite", c.target}};
    for (auto& sensor : doc["sensors"]) {
      sensor["parameters"]["band_low_um"] = c.lit ? 0.4 : 8.0;
      sensor["parameters"]["band_high_um"] = c.lit ? 0.7 : 12.0;
    }
  });
  host.at(0.0);
  const double omega = host.metric("EOIR Sensor Spatial Performance", "IFOV Solid Angle", "Sensor1");
  const double R_L = host.metric("EOIR Radiometric Performance", "Peak Radiance Responsivity", "Sensor1");
  double previous = 0;
  int count = 0;
  for (double r_km = 1.0; r_km <= 40000.0 * 1.0001; r_km *= 1.5, ++count) {
    set_observer(host, target + r_km * 1e3 * toward);
    ASSERT_EQ(host.target_metric("Target Is Point Source", "Satellite2", "Sensor2"), 1.0) << r_km;
    const double expected = host.target_metric("Effective Target Irradiance", "Satellite2", "Sensor2");
    ASSERT_GT(expected, 0.0) << c.target << " " << r_km << " km";
    host.render("Sensor1");
    const double measured = host.image(EOIR_IMAGE_SENSOR_MEAN, "Sensor1").sum() * omega / R_L;
    const double ratio = measured / expected;
    if (count % 3 == 0 || std::fabs(ratio - 1.0) > 1e-3)
      std::printf("%-20s %s r = %9.2f km: image %.6e W/cm^2, point %.6e W/cm^2, ratio %.5f\n", c.target.c_str(),
                  c.lit ? "lit    " : "eclipse", r_km, measured, expected, ratio);
    EXPECT_NEAR(ratio, 1.0, 1e-2) << c.target << (c.lit ? " lit " : " eclipsed ") << r_km << " km";
    if (previous > 0) {
      EXPECT_NEAR(ratio / previous, 1.0, 5e-3) << c.target << (c.lit ? " lit " : " eclipsed ") << r_km << " km";
    }
    previous = ratio;
    if (c.target == "sphere" && !c.lit) {
      const double r = r_km * 1e3;
      const double closed = (1.0 - kSphereReflectance) * v::planck_band(8.0, 12.0, kSphereTemperature) * v::kPi *
                            kSphereRadius * kSphereRadius / (r * r);
      EXPECT_NEAR(expected / closed, 1.0, 1e-2) << r_km << " km";
    }
  }
}

}  // namespace

TEST(SmallObjects_6_2_5_1, GeoCommunicationsLit) { run({"geo_communications", true}); }
TEST(SmallObjects_6_2_5_1, GeoCommunicationsEclipsed) { run({"geo_communications", false}); }
TEST(SmallObjects_6_2_5_1, LeoCommunicationsLit) { run({"leo_communications", true}); }
TEST(SmallObjects_6_2_5_1, LeoCommunicationsEclipsed) { run({"leo_communications", false}); }
TEST(SmallObjects_6_2_5_1, LeoEarthObservingLit) { run({"leo_earth_observing", true}); }
TEST(SmallObjects_6_2_5_1, LeoEarthObservingEclipsed) { run({"leo_earth_observing", false}); }
TEST(SmallObjects_6_2_5_1, SphereLit) { run({"sphere", true}); }
TEST(SmallObjects_6_2_5_1, SphereEclipsed) { run({"sphere", false}); }
