// Stability of the sky's terms where methods fail (issue 20 item 9; spec
// 4.1.5.3 eq. 9's L_scatter and L_path over lines of sight, SkyView): with
// no water and saturated air (0 and 2.15 x the profile's water: 0 % and
// ~99 % at the ground), visibility 0.5 km and 300 km, every sky radiance is
// finite and non-negative and changes continuously
//  - along the limb seen from GEO, tangent altitude 0.1-100 km (10 m apart:
//    within 2 % of the largest value);
//  - at the zenith of a ground observer as the Sun sets through the
//    horizon (+3 to -3 deg, 0.05 deg apart: no step over 25 % while the sky
//    is above 1e-4 of its value with the Sun 3 deg up);
//  - for an observer at the top of the atmosphere, 1 m below it (inside:
//    lines tabulated by elevation) and at it (above: by impact parameter),
//    the nadir and a line grazing at 20 km agree within 3 %.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "atmosphere/path_optics.hpp"
#include "atmosphere/profile.hpp"
#include "atmosphere/single_scatter.hpp"
#include "core/constants.hpp"
#include "core/data_dir.hpp"
#include "scene/sight_lines.hpp"

namespace eoir::atmosphere {
namespace {

const EarthFigure kEarth;  // pole +z; observers on +x
const double kA = kEarth.equatorial_radius_m;

struct Sky {
  std::shared_ptr<const PathOptics> optics;
  std::shared_ptr<const SunlightTable> sunlight;
  mutable std::map<double, std::shared_ptr<const scene::SightLines>> lines_;  // per observer altitude
  Sky(double water, double visibility, double low_um, double high_um) {
    universe::AtmosphereSettings s;
    s.model = universe::AtmosphereModel::simple;
    s.aerosol = universe::AerosolModel::rural;
    s.water_vapor_scale = water;
    s.visibility_km = visibility;
    const std::string data = resolve_data_dir("");
    radiometry::SpectralBand b;
    b.low_um = low_um;
    b.high_um = high_um;
    b.intervals = 4;
    optics = std::make_shared<PathOptics>(AtmosphereProfile::make(s, data), s, data, b);
    sunlight = std::make_shared<SunlightTable>(*optics, kEarth);
  }
  // The sky of an observer at altitude h on +x, the Sun along to_sun.
  scene::SkyView view(double h, const Vec3& to_sun) const {
    EarthFigure e = kEarth;
    e.centre_m = Vec3(-(kA + h), 0, 0);
    const radiometry::SpectralView v =
        radiometry::SpectralView::make(optics->band().low_um, optics->band().high_um, 4, BandIntegration::grid,
                                       SpectralQuadrature::interval_midpoint);
    auto& lines = lines_[h];
    if (!lines) lines = std::make_shared<const scene::SightLines>(scene::SightLines::make(*optics, kEarth, h));
    return scene::SkyView(lines, sunlight, e, to_sun, std::vector<double>(4, 1e-3), {}, {}, v);
  }
};

TEST(SkyStability, ExtremesAreFiniteAndContinuous) {
  for (const double water : {0.0, 2.15})
    for (const double visibility : {0.5, 300.0})
      for (const bool visible : {true, false}) {
        const Sky sky(water, visibility, visible ? 0.4 : 8.0, visible ? 0.8 : 12.0);
        const std::string what = std::string(visible ? "0.4-0.8 um" : "8-12 um") + ", water x" +
                                 std::to_string(water) + ", visibility " + std::to_string(visibility) + " km";
        // The limb from GEO, the Sun behind the observer's left shoulder.
        const double H = 35786e3, r = kA + H;
        const scene::SkyView geo = sky.view(H, Vec3(0.3, 0.9, 0.3).normalized());
        const auto limb = [&](double h) {
          const double p = kA + h, mu = -std::sqrt(1.0 - (p / r) * (p / r));
          double L = -1;
          EXPECT_TRUE(geo.sky_band(Vec3(mu, std::sqrt(1.0 - mu * mu), 0.0), L)) << what << " at " << h;
          return L;
        };
        double largest = 0;
        std::vector<std::pair<double, double>> steps;
        for (double h = 100.0; h <= 100e3; h += 250.0) {
          const double a = limb(h), b = limb(h + 10.0);
          ASSERT_TRUE(std::isfinite(a) && a >= 0) << what << " at " << h;
          largest = std::max(largest, a);
          steps.emplace_back(a, b);
        }
        for (const auto& [a, b] : steps) EXPECT_LE(std::fabs(a - b), 0.02 * largest) << what;
        if (!visible) continue;
        // Sunset over a ground observer (the sky's zenith).
        const auto zenith = [&](double sun_deg) {
          const double e = sun_deg * constants::pi / 180.0;
          double L = -1;
          EXPECT_TRUE(sky.view(0.0, Vec3(std::sin(e), std::cos(e), 0.0)).sky_band(Vec3::UnitX(), L));
          return L;
        };
        const double day = zenith(3.0);
        double previous = day;
        for (double e = 2.95; e >= -3.0; e -= 0.05) {
          const double L = zenith(e);
          ASSERT_TRUE(std::isfinite(L) && L >= 0) << what << " Sun at " << e;
          if (L > 1e-4 * day) {
            EXPECT_GE(L, 0.75 * previous) << what << " Sun at " << e;
          }
          previous = L;
        }
        // An observer at the top, just inside and at it.
        const double top = sky.optics->profile().top_altitude_m();
        const Vec3 sun = Vec3(0.6, 0.8, 0.0);
        const scene::SkyView inside = sky.view(top - 1.0, sun), above = sky.view(top, sun);
        const double grazing_mu = -std::sqrt(1.0 - std::pow((kA + 20e3) / (kA + top), 2.0));
        for (const Vec3& d : {Vec3(-1, 0, 0), Vec3(grazing_mu, std::sqrt(1.0 - grazing_mu * grazing_mu), 0.0)}) {
          const double a = inside.scatter_band(d), b = above.scatter_band(d);
          EXPECT_NEAR(a / b, 1.0, 0.03) << what << " looking " << d.transpose();
        }
      }
}

}  // namespace
}  // namespace eoir::atmosphere
