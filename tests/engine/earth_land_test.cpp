// Land that looks like land (issue 20 item 7): in bitmap mode the SRF of a
// land-cover class follows the Blue Marble's brightness within the class
// (data/earth/README.md, "Land brightness"), keeping the class's spectral
// shape and mean.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "engine.hpp"
#include "geo_host.hpp"

namespace {
using eoir::Engine;
using eoir::Value;
using eoir::universe::ObjectKind;

const double identity[4] = {1, 0, 0, 0};
const double zero[3] = {0, 0, 0};
constexpr double kPi = 3.14159265358979323846;

// A visible (0.45-0.75 um) bitmap-mode sensor at GEO radius looking at the Earth.
std::unique_ptr<Engine> bitmap_engine() {
  auto e = eoir_test::geo_host_engine("2010-03-30T12:00:00Z");
  e->set_property("Sensor", "band_low_um", Value(0.45));
  e->set_property("Sensor", "band_high_um", Value(0.75));
  e->set_property("Sensor", "scene_mode", Value(std::string("bitmap")));
  const double look[4] = {std::sqrt(0.5), 0, -std::sqrt(0.5), 0};
  e->push_state("Sensor", e->time(), 0, zero, zero, look);
  return e;
}

Eigen::Vector3d on_earth(double lat_deg, double lon_deg) {
  const double a = 6378137.0, c = 6356752.314245;  // WGS84
  const double f = lat_deg * kPi / 180, l = lon_deg * kPi / 180;
  const double e2 = 1 - (c / a) * (c / a), N = a / std::sqrt(1 - e2 * std::sin(f) * std::sin(f));
  return {N * std::cos(f) * std::cos(l), N * std::cos(f) * std::sin(l), N * (1 - e2) * std::sin(f)};
}

// The band-mean SRF of a point (its layers blended).
double mean_srf(const eoir::scene::SurfaceModel& s, const eoir::scene::SurfacePoint& p, std::size_t n) {
  std::vector<double> srf(n, 0.0);
  s.add_srf(p, 1.0, srf);
  double sum = 0;
  for (double r : srf) sum += r;
  return sum / static_cast<double>(n);
}
}  // namespace

// Within a class the SRF is the class's spectrum times one factor (its shape
// kept to rounding), the factor's area-weighted mean over the class is 1
// within 0.05 (the map keeps each class's mean over the image's pixels to
// 0.01; here the cells of the engine's land cover, whose classes differ
// from the image pixel's at coasts, are sampled on a 0.5-deg grid), and the
// factor varies (the texture): at least one point of each large class is
// below 0.8 and one above 1.2.
TEST(EarthLand, ClassesFollowTheImageBrightnessKeepingShapeAndMean) {
  auto e = bitmap_engine();
  const auto world = e->world("Sensor");
  const eoir::scene::WorldObject& earth = *world->find("Earth");
  const eoir::scene::SurfaceModel& s = *earth.surface;
  const std::size_t n = earth.view().sample_wavelengths_um.size();
  struct Stats {
    double weight = 0, sum = 0, low = 1e9, high = 0;
    std::size_t count = 0;
  };
  std::map<const eoir::scene::SurfaceSpectrum*, Stats> classes;
  for (double lat = -59.75; lat < 80; lat += 0.5)
    for (double lon = -179.75; lon < 180; lon += 0.5) {
      const Eigen::Vector3d p = on_earth(lat, lon);
      const eoir::scene::SurfacePoint q = s.at(eoir::scene::SurfaceSite{0, p, earth.normal_at(0, p)});
      ASSERT_EQ(q.cloud_fraction, 0.0);  // clouds off by default
      const double k = q.reflectance_scale;
      if (k == 1.0) continue;  // water (and the rare cell exactly at its class's mean)
      // The shape: every interval's SRF is k times the class's.
      std::vector<double> srf(n, 0.0);
      s.add_srf(q, 1.0, srf);
      for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(srf[i], k * q.spectrum->srf()[i], 1e-15) << lat << " " << lon;
      ASSERT_LE(k * q.spectrum->max_srf(), 1.0 + 1e-12);
      Stats& st = classes[q.spectrum];
      const double w = std::cos(lat * kPi / 180);
      st.weight += w;
      st.sum += w * k;
      st.low = std::min(st.low, k);
      st.high = std::max(st.high, k);
      ++st.count;
    }
  int large = 0;
  for (const auto& [spectrum, st] : classes) {
    if (st.count < 2000) continue;
    ++large;
    EXPECT_NEAR(st.sum / st.weight, 1.0, 0.05) << st.count;
    EXPECT_LT(st.low, 0.8);
    EXPECT_GT(st.high, 1.2);
  }
  EXPECT_GE(large, 4);
}

// A desert brighter than a forest, and within the desert class the pale
// sand of the Rub al Khali (20.5 N, 50.5 E) brighter than the stony Hamada
// du Draa (29 N, 6 W) by the Blue Marble's ratio of their luminances (1.47
// / 0.94 in the map, make_land_brightness.py), as in the image; the Amazon
// forest (5 S, 62 W) darker than either.
TEST(EarthLand, SandBrighterThanRockBrighterThanForest) {
  auto e = bitmap_engine();
  const auto world = e->world("Sensor");
  const eoir::scene::WorldObject& earth = *world->find("Earth");
  const eoir::scene::SurfaceModel& s = *earth.surface;
  const std::size_t n = earth.view().sample_wavelengths_um.size();
  const auto point = [&](double lat, double lon) {
    const Eigen::Vector3d p = on_earth(lat, lon);
    return s.at(eoir::scene::SurfaceSite{0, p, earth.normal_at(0, p)});
  };
  const eoir::scene::SurfacePoint sand = point(20.5, 50.5), rock = point(29.0, -6.0), forest = point(-5.0, -62.0);
  ASSERT_EQ(sand.spectrum, rock.spectrum);  // both barren
  EXPECT_NEAR(mean_srf(s, sand, n) / mean_srf(s, rock, n), 1.46875 / 0.9375, 1e-9);
  EXPECT_GT(mean_srf(s, rock, n), 2.0 * mean_srf(s, forest, n));
}
