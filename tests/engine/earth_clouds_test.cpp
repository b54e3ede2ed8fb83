// The Earth's cloud layer (issue 20 item 7): seen from the Sun's direction
// the whole disc's visible reflectance (its geometric albedo) comes close to
// the observed one with clouds on; off (the default) the Earth is as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "engine.hpp"
#include "geo_host.hpp"

namespace {
using eoir::Engine;
using eoir::Value;
using eoir::universe::ObjectKind;

const double identity[4] = {1, 0, 0, 0};
const double zero[3] = {0, 0, 0};
constexpr double kPi = 3.14159265358979323846;
constexpr double a = 6378137.0, c = 6356752.314245;  // WGS84

// A visible (0.5-0.6 um, about Johnson V) sensor on a host at GEO radius
// looking at the Earth; the Earth in `scene_mode`.
std::unique_ptr<Engine> engine(const char* iso_time, const std::string& scene_mode) {
  auto e = eoir_test::geo_host_engine(iso_time);
  e->set_property("Sensor", "band_low_um", Value(0.5));
  e->set_property("Sensor", "band_high_um", Value(0.6));
  e->set_property("Sensor", "diffraction_wavelength_um", Value(0.55));
  e->set_property("Sensor", "scene_mode", Value(scene_mode));
  const double look[4] = {std::sqrt(0.5), 0, -std::sqrt(0.5), 0};
  e->push_state("Sensor", e->time(), 0, zero, zero, look);
  return e;
}

// The point of the WGS84 ellipsoid at geodetic (lat, lon), body frame.
Eigen::Vector3d on_earth(double lat_deg, double lon_deg) {
  const double f = lat_deg * kPi / 180, l = lon_deg * kPi / 180;
  const double e2 = 1 - (c / a) * (c / a), N = a / std::sqrt(1 - e2 * std::sin(f) * std::sin(f));
  return {N * std::cos(f) * std::cos(l), N * std::cos(f) * std::sin(l), N * (1 - e2) * std::sin(f)};
}

// Geometric albedo at zero phase: the band radiance L toward the Sun summed
// over the sunlit hemisphere, L cos(e) dA, over (F / pi) pi a^2, the same for
// a Lambertian disc of reflectance 1 facing the Sun (Russell 1916). F / pi
// is the gray Earth's (SRF 0.3, Lambertian) radiance at the subsolar point
// divided by 0.3. The sum runs on a 0.5-deg geodetic grid.
struct DiscSums {
  double sum = 0, subsolar_radiance = 0;
};

DiscSums disc_sum(Engine& e) {
  const auto world = e.world("Sensor");
  const eoir::scene::WorldObject& earth = *world->find("Earth");
  const Eigen::Vector3d sun_frame = (world->sun.position_m - earth.placed.position_m).normalized();
  const Eigen::Vector3d sun_body = earth.direction_to_body(sun_frame);
  DiscSums d;
  const double step = 0.5;
  for (double lat = -90 + step / 2; lat < 90; lat += step) {
    const double area = a * a * std::cos(lat * kPi / 180) * (step * kPi / 180) * (step * kPi / 180);
    for (double lon = -180 + step / 2; lon < 180; lon += step) {
      const Eigen::Vector3d p = on_earth(lat, lon), n = earth.normal_at(0, p);
      const double mu = n.dot(sun_body);
      if (mu <= 0) continue;
      const double L = earth.view().integrate(earth.spectral_radiance(0, p, n, sun_frame, true));
      d.sum += L * mu * area;
    }
  }
  const double lat_ss = std::asin(sun_body.z()) * 180 / kPi, lon_ss = std::atan2(sun_body.y(), sun_body.x()) * 180 / kPi;
  const Eigen::Vector3d p = on_earth(lat_ss, lon_ss), n = earth.normal_at(0, p);
  d.subsolar_radiance = earth.view().integrate(earth.spectral_radiance(0, p, n, sun_frame, true));
  return d;
}
}  // namespace

// Allen's Astrophysical Quantities (4th ed., Cox 2000, Table 12.x "the
// Earth"): visual geometric albedo 0.367. The engine's Earth in bitmap mode
// with clouds on, averaged over four times six hours apart (the Earth turns
// under the Sun: Americas, Pacific, Asia, Africa and Europe), comes within
// 0.05 of it: the Earth's own daily and seasonal changes of reflectance are
// of that size (Palle et al. 2004, Science 304, 1299: earthshine albedo
// varies by ~10 % from day to day), and the cloud map is one snapshot. Its
// normalisation is checked on the gray Lambertian Earth (geometric albedo
// 2/3 x 0.3 = 0.2, Russell 1916) to 1 %. Clouds off, bitmap mode is far
// below (the clouds make the difference the test looks for).
TEST(EarthClouds, WholeDiscGeometricAlbedoNearTheObserved) {
  const char* times[] = {"2010-03-30T00:00:00Z", "2010-03-30T06:00:00Z", "2010-03-30T12:00:00Z",
                         "2010-03-30T18:00:00Z"};
  double with_clouds = 0, without = 0;
  for (const char* t : times) {
    auto gray = engine(t, "smooth");
    const DiscSums g = disc_sum(*gray);
    const double F_over_pi = g.subsolar_radiance / 0.3;
    const double disc = F_over_pi * kPi * a * a;
    EXPECT_NEAR(g.sum / disc, 0.2, 0.002) << t;
    auto e = engine(t, "bitmap");
    without += disc_sum(*e).sum / disc / 4;
    e->set_property("Earth", "clouds", Value(true));
    with_clouds += disc_sum(*e).sum / disc / 4;
  }
  std::printf("geometric albedo (0.5-0.6 um): clouds off %.4f, on %.4f (Allen 0.367)\n", without, with_clouds);
  EXPECT_NEAR(with_clouds, 0.367, 0.05);
  EXPECT_LT(without, 0.367 - 0.1);
}

// Off by default; on, only the Earth's, with its fields in range; the
// default Earth renders exactly as with clouds set off explicitly.
TEST(EarthClouds, OffByDefaultAndTheEarthsOnly) {
  auto e = engine("2010-03-30T12:00:00Z", "bitmap");
  EXPECT_FALSE(e->universe().get("Earth").clouds.enabled);
  const std::vector<double> before = e->render("Sensor").sensor.mean_electrons;
  e->set_property("Earth", "clouds", Value(false));
  e->set_property("Earth", "cloud_top_temperature_K", Value(200.0));  // unread while off
  EXPECT_EQ(e->render("Sensor").sensor.mean_electrons, before);
  e->set_property("Earth", "clouds", Value(true));
  EXPECT_NE(e->render("Sensor").sensor.mean_electrons, before);
  e->add_object(ObjectKind::central_body, "Moon");
  try {
    e->set_property("Moon", "clouds", Value(true));
    FAIL() << "the Moon took clouds";
  } catch (const eoir::Error& err) {
    EXPECT_EQ(err.status(), eoir::Status::not_allowed);
    EXPECT_NE(std::string(err.what()).find("clouds"), std::string::npos);
  }
  try {
    e->set_property("Earth", "cloud_top_altitude_km", Value(25.0));
    FAIL() << "25 km taken";
  } catch (const eoir::Error& err) {
    EXPECT_NE(std::string(err.what()).find("cloud_top_altitude_km"), std::string::npos);
  }
}

// The cloud top emits at its own temperature: in 8-12 um a clouded point of
// the Earth blends the cloud material at cloud_top_temperature_K
// (fine_snow's emissivity ~0.99) with the surface beneath at its own
// temperature, by the cloud fraction; within the surface model's bounds.
TEST(EarthClouds, CloudTopsEmitAtTheirTemperature) {
  auto e = engine("2010-03-30T12:00:00Z", "smooth");
  e->set_property("Sensor", "band_low_um", Value(8.0));
  e->set_property("Sensor", "band_high_um", Value(12.0));
  e->set_property("Sensor", "diffraction_wavelength_um", Value(10.0));
  e->set_property("Earth", "clouds", Value(true));
  const auto world = e->world("Sensor");
  const eoir::scene::WorldObject& earth = *world->find("Earth");
  const eoir::scene::SurfaceModel& s = *earth.surface;
  // The cloudiest and the clearest point of a 1-degree scan.
  eoir::scene::SurfacePoint cloudy, clear;
  cloudy.cloud_fraction = -1;
  clear.cloud_fraction = 2;
  for (double lat = -60.5; lat < 60; lat += 1.0)
    for (double lon = -179.5; lon < 180; lon += 1.0) {
      const Eigen::Vector3d p = on_earth(lat, lon);
      const eoir::scene::SurfacePoint q = s.at(eoir::scene::SurfaceSite{0, p, earth.normal_at(0, p)});
      if (q.cloud_fraction > cloudy.cloud_fraction) cloudy = q;
      if (q.cloud_fraction < clear.cloud_fraction) clear = q;
    }
  ASSERT_GT(cloudy.cloud_fraction, 0.95);
  ASSERT_LT(clear.cloud_fraction, 0.05);
  const double planck_255 = earth.view().gray_body_radiance(255.7, 0.0);  // black body at the cloud tops
  // Expected: f eps_cloud B(255.7 K) + (1 - f) 0.7 B(T) (the gray Earth: SRF
  // 0.3, at its climatology's T there), the cloud's emissivity between 0.95
  // and 1 (fine_snow in 8-12 um: SRF 0.002-0.011, data/materials).
  for (const eoir::scene::SurfacePoint& q : {cloudy, clear}) {
    const double f = q.cloud_fraction, L = s.emission_radiance(q);
    const double ground = 0.7 * earth.view().gray_body_radiance(s.temperature_K(q), 0.0);
    EXPECT_GE(L, (f * 0.95 * planck_255 + (1 - f) * ground) * (1 - 1e-9)) << f;
    EXPECT_LE(L, (f * planck_255 + (1 - f) * ground) * (1 + 1e-9)) << f;
  }
  const double L_cloudy = s.emission_radiance(cloudy);
  EXPECT_LE(L_cloudy, s.emission_bound());
  EXPECT_GE(L_cloudy, s.emission_floor());
  // Colder cloud tops (220 K) emit less there.
  e->set_property("Earth", "cloud_top_temperature_K", Value(220.0));
  const auto colder = e->world("Sensor");
  const eoir::scene::WorldObject& earth2 = *colder->find("Earth");
  EXPECT_LT(earth2.surface->emission_radiance(earth2.surface->at(cloudy.site)), 0.8 * L_cloudy);
}

// The cloud fraction is read bilinearly between the map's cell centres
// (universe/surface_map.hpp): at a centre the cell's value, halfway between
// two centres their mean, across the date line too (columns 511 and 0).
TEST(EarthClouds, CloudFractionBilinearBetweenCellCentres) {
  Engine e;
  const eoir::universe::RasterLevel& m =
      e.library().maps_of(eoir::universe::CentralBody::earth)->clouds->finest();
  const double cell = 360.0 / 512, scale = 1.0 / 255;
  for (const auto& [i, j] : {std::pair{40, 100}, std::pair{128, 300}, std::pair{200, 511}}) {
    const double lat = 90 - (i + 0.5) * cell, lon = -180 + (j + 0.5) * cell;
    const double here = scale * m.at(lat, lon), east = scale * m.at(lat, lon + cell),
                 south = scale * m.at(lat - cell, lon);
    EXPECT_NEAR(m.interpolated(lat, lon), here, 1e-12);
    EXPECT_NEAR(m.interpolated(lat, lon + cell / 2), 0.5 * (here + east), 1e-12) << i << " " << j;
    EXPECT_NEAR(m.interpolated(lat - cell / 4, lon), 0.75 * here + 0.25 * south, 1e-12);
  }
}
