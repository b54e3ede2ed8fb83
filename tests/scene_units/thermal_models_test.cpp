// The thermal models of spec 4.3.1.3: the Earth's land/water diurnal cycle
// (Ignatov and Gutman 1999 via the GOT01 equations), the airless bodies' day
// (eq. 12) and night (T^(1/4) decay tied to the reported minimum), and the
// satellites' eclipse law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/time.hpp"
#include "scene/thermal_models.hpp"
#include "universe/surface_climatology.hpp"

using namespace eoir::scene;
using eoir::universe::month_centre_day_of_year;
using eoir::universe::SurfaceClimatology;
using eoir::universe::SurfaceKind;

namespace {

constexpr double kPi = 3.14159265358979323846;

const SurfaceClimatology& climatology() {
  static const SurfaceClimatology c = SurfaceClimatology::load(EOIR_DATA_OUTPUT_DIR);
  return c;
}

struct Range {
  double min_K = 1e9, max_K = -1e9, t_of_min_h = 0, t_of_max_h = 0;
};
// Extremes of a cycle sampled every 30 s of local solar time.
Range sample(const DiurnalCycle& c) {
  Range r;
  for (int i = 0; i < 2880; ++i) {
    const double t = i / 120.0, T = c.temperature_K(t);
    if (T < r.min_K) {
      r.min_K = T;
      r.t_of_min_h = t;
    }
    if (T > r.max_K) {
      r.max_K = T;
      r.t_of_max_h = t;
    }
  }
  return r;
}

double slope_K_h(const DiurnalCycle& c, double t, double side) {
  const double h = 1e-5;
  return side < 0 ? (c.temperature_K(t) - c.temperature_K(t - h)) / h
                  : (c.temperature_K(t + h) - c.temperature_K(t)) / h;
}

// Hurley et al. (2015, Icarus 255, 159) fit of the Diviner equatorial night:
// T(lon) = sum a_i lon^i, lon the longitude from the subsolar point in
// [pi/2, 3 pi/2] rad, at the equator (where its latitude term vanishes).
double hurley_night_K(double lon_rad) {
  const double a[6] = {444.738, -448.937, 239.668, -63.8844, 8.34064, -0.423502};
  double T = 0, p = 1;
  for (double ai : a) {
    T += ai * p;
    p *= lon_rad;
  }
  return T;
}

}  // namespace

// ---- The Sun seen from the Earth --------------------------------------------

TEST(ThermalSun, DeclinationEquationOfTimeAndDaylight) {
  EXPECT_NEAR(solar_declination_deg(172.5), 23.44, 0.1);  // June solstice
  EXPECT_NEAR(solar_declination_deg(356.5), -23.44, 0.1);
  EXPECT_NEAR(solar_declination_deg(80.5), 0.0, 0.6);   // March equinox
  EXPECT_NEAR(equation_of_time_min(307.0), 16.4, 0.3);  // early November maximum
  EXPECT_NEAR(equation_of_time_min(43.0), -14.2, 0.3);  // mid-February minimum

  const SunriseSunset equinox = sunrise_sunset(0.0, 0.0);
  EXPECT_NEAR(equinox.length_h(), 12.0 + 2 * 0.833 / 15.0, 1e-9);  // refraction + semi-diameter
  EXPECT_NEAR(0.5 * (equinox.sunrise_h + equinox.sunset_h), 12.0, 1e-12);
  EXPECT_NEAR(sunrise_sunset(45.0, 23.44).length_h(), 15.6, 0.1);
  EXPECT_TRUE(sunrise_sunset(80.0, 23.44).polar_day());
  EXPECT_TRUE(sunrise_sunset(80.0, -23.44).polar_night());
  EXPECT_TRUE(sunrise_sunset(-80.0, 23.44).polar_night());
  EXPECT_EQ(sunrise_sunset(90.0, 10.0).sunrise_h, 0.0);
}

TEST(ThermalSun, CalendarAndLocalSolarTimeFromEngineTime) {
  const auto at = [](const char* iso) { return eoir::EngineTime::from(eoir::utc_from_iso(iso)); };
  CalendarInstant c = calendar_instant(at("2000-01-01T12:00:00Z"));
  EXPECT_NEAR(c.day_of_year, 1.5, 1e-9);
  EXPECT_NEAR(c.utc_hours, 12.0, 1e-6);
  c = calendar_instant(at("2024-12-31T18:00:00Z"));  // leap year
  EXPECT_NEAR(c.day_of_year, 366.75, 1e-9);
  c = calendar_instant(at("2023-03-01T06:00:00Z"));
  EXPECT_NEAR(c.day_of_year, 60.25, 1e-9);
  // Local solar time: UTC + longitude / 15 + equation of time.
  const auto t = at("2021-11-03T12:00:00Z");
  const double eot_h = equation_of_time_min(calendar_instant(t).day_of_year) / 60.0;
  EXPECT_NEAR(local_solar_time_h(t, 0.0), 12.0 + eot_h, 1e-6);
  EXPECT_NEAR(local_solar_time_h(t, -118.294), 12.0 - 118.294 / 15.0 + eot_h, 1e-6);
  EXPECT_NEAR(local_solar_time_h(t, 180.0), std::fmod(24.0 + eot_h, 24.0), 1e-6);
}

// ---- 1. Earth land and water ------------------------------------------------

// Every table latitude and month, land and water: the curve's daily maximum
// and minimum are the table's (at mid-month, where interpolation returns
// the entry), at t_m and at sunrise.
TEST(ThermalEarth, DailyExtremesEqualTheTable) {
  for (SurfaceKind kind : {SurfaceKind::land, SurfaceKind::water}) {
    const auto& table = climatology().table(kind);
    for (std::size_t b = 0; b < table.band_centres_deg().size(); ++b)
      for (int m = 1; m <= 12; ++m) {
        const double lat = table.band_centres_deg()[b], day = month_centre_day_of_year(m);
        const auto entry = table.entry(b, m);
        const DiurnalCycle c(entry.t_min_K, entry.t_max_K, lat, solar_declination_deg(day));
        const Range r = sample(c);
        EXPECT_NEAR(r.max_K, entry.t_max_K, 0.1) << lat << " " << m;
        EXPECT_NEAR(r.min_K, entry.t_min_K, 0.1) << lat << " " << m;
        EXPECT_GE(r.min_K, entry.t_min_K - 1e-9);
        EXPECT_LE(r.max_K, entry.t_max_K + 1e-9);
        EXPECT_NEAR(c.temperature_K(c.time_of_max_h()), entry.t_max_K, 1e-9);
        EXPECT_NEAR(c.temperature_K(c.sunrise_h()), entry.t_min_K, 1e-9);
        // The same through the table lookup and the declination of the day.
        EXPECT_NEAR(surface_temperature_K(climatology(), kind, lat, day, c.time_of_max_h()), entry.t_max_K, 1e-9);
      }
  }
}

TEST(ThermalEarth, ShapeAtTheEquinox) {
  const DiurnalCycle c(290.0, 310.0, 0.0, 0.0);
  EXPECT_NEAR(c.time_of_max_h(), 13.5, 1e-3);  // 12 h + 1.5 h for a 12-hour day (12.1 h here)
  EXPECT_NEAR(c.sunrise_h(), 12.0 - 6.0 - 0.833 / 15.0, 1e-9);
  EXPECT_GT(c.decay_h(), 1.0);  // GOT01 attenuation constant: a few hours
  EXPECT_LT(c.decay_h(), 10.0);
  EXPECT_LT(c.asymptote_K(), 290.0);
  // Rising from sunrise to t_m, falling through the evening and the night.
  double previous = c.temperature_K(c.sunrise_h());
  for (double t = c.sunrise_h() + 0.01; t < c.sunrise_h() + 24.0; t += 0.01) {
    const double T = c.temperature_K(t);
    if (t < c.time_of_max_h() - 0.01) {
      EXPECT_GT(T, previous) << t;
    } else if (t > c.time_of_max_h() + 0.01) {
      EXPECT_LT(T, previous) << t;
    }
    previous = T;
  }
  // Periodic in local time.
  EXPECT_NEAR(c.temperature_K(3.0), c.temperature_K(27.0), 1e-9);
  EXPECT_NEAR(c.temperature_K(-2.0), c.temperature_K(22.0), 1e-9);
}

// Value and slope continuous at sunset (GOT01's k), value at sunrise.
TEST(ThermalEarth, ContinuousAtSunriseAndSunset) {
  for (double lat : {-60.0, -30.0, 0.0, 20.0, 45.0, 60.0})
    for (double dec : {-23.0, 0.0, 23.0}) {
      const DiurnalCycle c(280.0, 300.0, lat, dec);
      const double e = 1e-9;
      EXPECT_NEAR(c.temperature_K(c.sunset_h() - e), c.temperature_K(c.sunset_h() + e), 1e-6) << lat << " " << dec;
      EXPECT_NEAR(c.temperature_K(c.sunrise_h() - e), c.temperature_K(c.sunrise_h() + e), 1e-6) << lat << " " << dec;
      const double before = slope_K_h(c, c.sunset_h(), -1), after = slope_K_h(c, c.sunset_h(), +1);
      EXPECT_LT(before, 0.0);
      EXPECT_NEAR(after / before, 1.0, 1e-3) << lat << " " << dec;
    }
}

// The night decay k solves k (1 - exp(-n/k)) = q (GOT01: the exponential
// meets the cosine with the same value and slope at sunset): the residual of
// the solved k, and the one-time evaluation (night solved only at night) equal
// to the whole cycle at every hour.
TEST(ThermalEarth, NightDecaySolvedToRoundingAndOnlyAtNight) {
  int solved = 0;
  for (double lat : {-66.0, -45.0, 0.0, 30.0, 60.0, 66.0})
    for (double dec : {-23.4, -10.0, 0.0, 10.0, 23.4}) {
      const DiurnalCycle c(270.0, 305.0, lat, dec);
      const double night_h = 24.0 - (c.sunset_h() - c.sunrise_h());
      if (std::isfinite(c.decay_h()) && c.decay_h() > 0) {
        const double q_h = (c.sunset_K() - 270.0) / ((c.sunset_K() - c.asymptote_K()) / c.decay_h());
        EXPECT_NEAR(c.decay_h() * -std::expm1(-night_h / c.decay_h()), q_h, 1e-12 * q_h) << lat << " " << dec;
        ++solved;
      }
      for (double t = 0.0; t < 24.0; t += 0.25)
        EXPECT_EQ(DiurnalCycle::temperature_K(270.0, 305.0, lat, dec, t), c.temperature_K(t)) << lat << " " << dec;
    }
  EXPECT_GE(solved, 20);  // most of the 30 cycles have an exponential night
}

// The night decay's x = n/k, the positive root of 1 - exp(-x) = r x, against
// bisection in long double (F > 0 left of the root, < 0 right of it) from
// r = 1e-4 (x ~ 1e4) to 1 - 1e-6 (x ~ 2e-6), to a few units of rounding of
// F in double: |dx/x| <= eps / |F'(x) x| -> eps / (1 - r) as r -> 1 (F' ->
// r - 1 there; the r of the defaults' days, 0.1-0.4, is far from it).
TEST(ThermalEarth, NightDecayRootEqualsBisection) {
  auto bisect = [](long double r) {
    long double lo = 1e-12L, hi = 2.0L / r;  // F(lo) > 0 for r < 1, F(2/r) < 0
    for (int i = 0; i < 200; ++i) {
      const long double mid = 0.5L * (lo + hi);
      (-std::expm1(-mid) - r * mid > 0 ? lo : hi) = mid;
    }
    return 0.5L * (lo + hi);
  };
  double worst = 0;
  for (int i = 0; i <= 4000; ++i) {
    const double r = i == 0 ? 1e-4 : i == 4000 ? 1.0 - 1e-6 : i / 4000.0 + 1e-7 * std::sin(i);
    const double x = night_decay_root(r);
    const double reference = static_cast<double>(bisect(r));
    worst = std::max(worst, std::fabs(x - reference) / reference * (1.0 - r));
  }
  EXPECT_LT(worst, 1e-15);
  EXPECT_THROW(night_decay_root(0.0), eoir::Error);
  EXPECT_THROW(night_decay_root(1.0), eoir::Error);
  EXPECT_THROW(night_decay_root(NAN), eoir::Error);
}

TEST(ThermalEarth, InterpolatesBetweenBandsAndMonths) {
  const auto& land = climatology().land;
  // 40 N halfway between mid-July and mid-August: the cycle of the bilinear extremes.
  const double day = 0.5 * (month_centre_day_of_year(7) + month_centre_day_of_year(8));
  const auto x = land.at(40.0, day);
  const double expected_max = 0.25 * (land.entry(12, 7).t_max_K + land.entry(13, 7).t_max_K +
                                      land.entry(12, 8).t_max_K + land.entry(13, 8).t_max_K);
  EXPECT_NEAR(x.t_max_K, expected_max, 1e-9);
  const DiurnalCycle c(x.t_min_K, x.t_max_K, 40.0, solar_declination_deg(day));
  const Range r = sample(c);
  EXPECT_NEAR(r.max_K, x.t_max_K, 0.1);
  EXPECT_NEAR(r.min_K, x.t_min_K, 0.1);
  for (double t = 0; t < 24; t += 0.5)
    EXPECT_NEAR(surface_temperature_K(climatology(), SurfaceKind::land, 40.0, day, t), c.temperature_K(t), 1e-9);
}

TEST(ThermalEarth, PeriodicAcrossTheYearEnd) {
  for (double t : {0.0, 6.0, 13.5, 20.0}) {
    const double year_end = 1.0 + eoir::universe::kYear_days;
    EXPECT_NEAR(surface_temperature_K(climatology(), SurfaceKind::land, 65.0, year_end - 1e-6, t),
                surface_temperature_K(climatology(), SurfaceKind::land, 65.0, 1.0, t), 1e-3)
        << t;
  }
}

// Polar day: the Sun never sets; the minimum at local midnight, the maximum
// at noon, continuous across midnight. Polar night: the shape of a
// min_day_length_h day keeps the table's extremes.
TEST(ThermalEarth, PolarDayAndPolarNight) {
  const auto& land = climatology().land;
  const double july = month_centre_day_of_year(7), january = month_centre_day_of_year(1);
  {
    const auto e = land.entry(17, 7);  // 85 N in July
    const DiurnalCycle c(e.t_min_K, e.t_max_K, 85.0, solar_declination_deg(july));
    EXPECT_EQ(c.sunrise_h(), 0.0);
    EXPECT_EQ(c.sunset_h(), 24.0);
    EXPECT_NEAR(c.time_of_max_h(), 12.0, 1e-9);
    EXPECT_NEAR(c.temperature_K(0.0), e.t_min_K, 1e-9);
    EXPECT_NEAR(c.temperature_K(1e-9), c.temperature_K(24.0 - 1e-9), 1e-6);
    EXPECT_NEAR(sample(c).max_K, e.t_max_K, 0.1);
  }
  {
    const auto e = land.entry(17, 1);  // 85 N in January
    const DiurnalCycle c(e.t_min_K, e.t_max_K, 85.0, solar_declination_deg(january));
    EXPECT_NEAR(c.sunset_h() - c.sunrise_h(), DiurnalShape{}.min_day_length_h, 1e-12);
    const Range r = sample(c);
    EXPECT_NEAR(r.max_K, e.t_max_K, 0.1);
    EXPECT_NEAR(r.min_K, e.t_min_K, 0.1);
  }
  // Across the polar circle near the June solstice the curve changes little:
  // the night shrinks to nothing and the sunset temperature falls to t_min.
  const double dec = 23.44;
  // The Sun's centre at -0.833 deg at midnight: latitude 90 - 0.833 - 23.44 = 65.727 deg.
  const double circle = 90.0 - 0.833 - dec;
  const DiurnalCycle above(280.0, 290.0, circle + 0.01, dec);
  EXPECT_TRUE(sunrise_sunset(circle + 0.01, dec).polar_day());
  double previous_gap = 1e9;
  for (double below_by : {0.3, 0.03, 0.003, 0.0003}) {
    const DiurnalCycle below(280.0, 290.0, circle - below_by, dec);
    EXPECT_FALSE(sunrise_sunset(circle - below_by, dec).polar_day());
    double gap = 0;
    for (double t = 0; t < 24; t += 0.05)
      gap = std::max(gap, std::abs(below.temperature_K(t) - above.temperature_K(t)));
    EXPECT_LT(gap, previous_gap) << below_by;
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 0.1);  // 1 % of the range
}

// Water: COADS sea-surface climatology with a modelled 0.1-0.5 K diurnal
// range, so its cycle is small against the land's.
TEST(ThermalEarth, WaterHasASmallAmplitude) {
  const auto& water = climatology().water;
  const auto& land = climatology().land;
  const double july = month_centre_day_of_year(7);
  for (std::size_t b = 0; b < water.band_centres_deg().size(); ++b)
    for (int m = 1; m <= 12; ++m) {
      const auto e = water.entry(b, m);
      EXPECT_LE(e.t_max_K - e.t_min_K, 1.0) << b << " " << m;
      EXPECT_GE(e.t_min_K, 271.0) << b << " " << m;
    }
  // 45 N in July: water 0.8 K, land 10 K.
  double water_range = 0, land_range = 0;
  for (SurfaceKind kind : {SurfaceKind::land, SurfaceKind::water}) {
    double lo = 1e9, hi = -1e9;
    for (double t = 0; t < 24; t += 1.0 / 60) {
      const double T = surface_temperature_K(climatology(), kind, 45.0, july, t);
      lo = std::min(lo, T);
      hi = std::max(hi, T);
    }
    if (kind == SurfaceKind::land) {
      land_range = hi - lo;
    } else {
      water_range = hi - lo;
    }
  }
  EXPECT_NEAR(water_range, water.entry(13, 7).t_max_K - water.entry(13, 7).t_min_K, 0.02);
  EXPECT_NEAR(land_range, land.entry(13, 7).t_max_K - land.entry(13, 7).t_min_K, 0.1);
  EXPECT_LT(water_range, 0.1 * land_range);
}

TEST(ThermalEarth, FromEngineTimeAndLongitude) {
  const auto t = eoir::EngineTime::from(eoir::utc_from_iso("2021-07-16T20:00:00Z"));
  const CalendarInstant c = calendar_instant(t);
  const double lon = -93.3;  // Minneapolis: ~13.8 h local solar time
  const double lst = local_solar_time_h(c.utc_hours, lon, c.day_of_year);
  EXPECT_NEAR(surface_temperature_K(climatology(), SurfaceKind::land, 45.0, lon, t),
              surface_temperature_K(climatology(), SurfaceKind::land, 45.0, c.day_of_year, lst), 1e-9);
  EXPECT_GT(surface_temperature_K(climatology(), SurfaceKind::land, 45.0, lon, t), 300.0);  // near the July maximum
}

TEST(ThermalEarth, RefusesBadArguments) {
  EXPECT_THROW(DiurnalCycle(300.0, 290.0, 0.0, 0.0), eoir::Error);
  EXPECT_THROW(DiurnalCycle(std::nan(""), 290.0, 0.0, 0.0), eoir::Error);
  EXPECT_THROW(DiurnalCycle(280.0, 290.0, 91.0, 0.0), eoir::Error);
  EXPECT_THROW(DiurnalCycle(280.0, 290.0, 0.0, 0.0).temperature_K(INFINITY), eoir::Error);
  EXPECT_THROW(surface_temperature_K(climatology(), SurfaceKind::land, 0.0, std::nan(""), 12.0), eoir::Error);
  // Equal extremes: a constant.
  EXPECT_DOUBLE_EQ(DiurnalCycle(280.0, 280.0, 0.0, 0.0).temperature_K(3.0), 280.0);
}

// A frame's temperatures come from latitude tables (issue 23 item 6: results
// within 1e-9 of the exact ones, relative; a radiance moves some 5 (10 um)
// to 12 (4 um) times its temperature's relative change at 300 K, so the
// table is held to 1e-11): the exact cycle at every latitude 0.0137 deg apart, on the
// first of every month, the solstices and the equinoxes, at four times and
// four longitudes.
TEST(ThermalEarth, LatitudeTableMatchesTheExactCycleToOnePartIn1e11) {
  double worst = 0;
  for (double day : {1.0, 32.0, 60.0, 80.3, 91.0, 121.0, 152.0, 172.5, 182.0, 213.0, 244.0, 266.0, 274.0, 305.0,
                     335.0, 355.7})
    for (double utc : {0.3, 7.2, 13.9, 19.6}) {
      CalendarInstant c;
      c.day_of_year = day;
      c.utc_hours = utc;
      const ClimatologyInstant now(climatology(), c);
      for (SurfaceKind kind : {SurfaceKind::land, SurfaceKind::water}) {
        // Most latitudes interpolate (the fallback alone would pass the
        // comparison): all within some 55 deg of the equator at a solstice.
        const DiurnalLatitudeTable& table = now.latitude_table(kind);
        EXPECT_GT(static_cast<double>(table.regular_nodes()), 0.6 * static_cast<double>(table.nodes()));
        for (double lat = -90.0; lat <= 90.0; lat += 0.0137)
          for (double lon : {-170.0, -60.0, 35.0, 120.0}) {
            const double s = std::sin(lat * kPi / 180.0), co = std::cos(lat * kPi / 180.0);
            const double exact = now.temperature_K(kind, lat, s, co, lon);
            worst = std::max(worst, std::fabs(now.tabulated_temperature_K(kind, lat, s, co, lon) - exact) / exact);
          }
      }
    }
  EXPECT_LT(worst, 1e-11);
}

// The same, finely, where stencils switch between the table and the exact
// cycle (the sunrise's |cos h0| reaching 0.8, near 61.5 deg at the
// solstices; the latitude bound, 72.5 deg): around every switch, found by a
// scan, neither side is off.
TEST(ThermalEarth, LatitudeTableAcrossTheSwitchesToTheExactCycle) {
  for (double day : {80.3, 121.0, 172.5, 355.7}) {
    CalendarInstant c;
    c.day_of_year = day;
    c.utc_hours = 3.0;
    const ClimatologyInstant now(climatology(), c);
    const DiurnalLatitudeTable& table = now.latitude_table(SurfaceKind::land);
    std::vector<double> switches;
    for (double lat = -89.99; lat < 89.99; lat += 0.01)
      if (table.interpolates(lat) != table.interpolates(lat + 0.01)) switches.push_back(lat);
    EXPECT_GE(switches.size(), 2u) << "day " << day;  // one each side of the equator at least
    for (double at : switches) {
      double worst = 0;
      for (double lat = at - 0.3; lat <= at + 0.3; lat += 1.1e-4)
        for (double lon : {-100.0, 80.0}) {
          const double s = std::sin(lat * kPi / 180.0), co = std::cos(lat * kPi / 180.0);
          const double e = now.temperature_K(SurfaceKind::land, lat, s, co, lon);
          worst = std::max(worst, std::fabs(now.tabulated_temperature_K(SurfaceKind::land, lat, s, co, lon) - e) / e);
        }
      EXPECT_LT(worst, 1e-11) << "day " << day << " near " << at;
    }
  }
  // The ends of the table: the poles themselves.
  CalendarInstant c;
  c.day_of_year = 80.3;
  const ClimatologyInstant now(climatology(), c);
  for (double lat : {-90.0, 90.0})
    EXPECT_NEAR(now.tabulated_temperature_K(SurfaceKind::water, lat, lat < 0 ? -1.0 : 1.0, 0.0, 10.0),
                now.temperature_K(SurfaceKind::water, lat, lat < 0 ? -1.0 : 1.0, 0.0, 10.0), 1e-9);
}

// Many points' temperatures at once (temperature_terms_K: the batch's
// cosines and exponentials by vector maths, core/vector_math.hpp) are each
// point's temperature_K to rounding (glibc's 4 ulp bound on both functions,
// carried through T = offset + scale f: a few parts in 1e16 of T), a
// constant term exactly; each branch occurs (day, night decay, the exact
// cycle's constants near the poles).
TEST(ThermalEarth, TemperatureTermsOfABatchAreEachPointsTemperature) {
  CalendarInstant c;
  c.day_of_year = 172.5;
  c.utc_hours = 7.2;
  const ClimatologyInstant now(climatology(), c);
  const DiurnalLatitudeTable& table = now.latitude_table(SurfaceKind::land);
  std::vector<TemperatureTerm> terms;
  for (double lat = -89.5; lat <= 89.5; lat += 0.37)
    for (double lon = -180.0; lon < 180.0; lon += 7.3) {
      const double s = std::sin(lat * kPi / 180.0), co = std::cos(lat * kPi / 180.0);
      terms.push_back(table.temperature_term(lat, s, co, lon));
    }
  int counts[3] = {0, 0, 0};
  for (const TemperatureTerm& t : terms) ++counts[static_cast<int>(t.function)];
  EXPECT_GT(counts[static_cast<int>(TemperatureTerm::Function::none)], 100);
  EXPECT_GT(counts[static_cast<int>(TemperatureTerm::Function::cos)], 1000);
  EXPECT_GT(counts[static_cast<int>(TemperatureTerm::Function::exp)], 1000);
  std::vector<double> batch(terms.size());
  temperature_terms_K(terms.data(), terms.size(), batch.data());
  double worst = 0;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const double one = terms[i].value_K();
    if (terms[i].function == TemperatureTerm::Function::none) {
      EXPECT_EQ(batch[i], one);
    }
    worst = std::max(worst, std::fabs(batch[i] - one) / one);
  }
  EXPECT_LT(worst, 1e-14);
}

// ---- 2. Airless central bodies ----------------------------------------------

TEST(ThermalAirless, SolarDayLengths) {
  EXPECT_NEAR(kMoonSolarDay_s / 86400.0, 29.53, 0.01);
  EXPECT_NEAR(kMercurySolarDay_s / 86400.0, 175.94, 0.01);
  EXPECT_NEAR(kMarsSolarDay_s / 86400.0, 1.0275, 0.0001);
}

TEST(ThermalAirless, DaySideFollowsEquation12) {
  const AirlessThermal moon;  // T_ss 390 K, minimum 95 K
  EXPECT_NEAR(airless_surface_point(moon, 0.0, 0.0, 0.0).temperature_K, 390.0, 1e-9);
  EXPECT_NEAR(airless_surface_point(moon, 0.0, 60.0, 0.0).temperature_K, 390.0 * std::pow(0.5, 0.25), 1e-9);
  EXPECT_NEAR(airless_surface_point(moon, 60.0, -60.0, 0.0).temperature_K, 390.0 * std::pow(0.25, 0.25), 1e-9);
  EXPECT_FALSE(airless_surface_point(moon, 0.0, 80.0, 0.0).night);
  EXPECT_EQ(subsolar_temperature_K(390.0, -0.5), 0.0);
  EXPECT_NEAR(dusk_temperature_K(moon), 390.0 * std::pow(std::sin(0.7 * kPi / 180), 0.25), 1e-9);
  EXPECT_NEAR(dusk_temperature_K(moon), 129.7, 0.1);
}

// Dusk: eq. 12 meets the night law; dawn: the night law ends at the reported
// minimum (95 K), where eq. 12 takes over.
TEST(ThermalAirless, NightJoinsEquation12AndReachesTheMinimumAtDawn) {
  const AirlessThermal moon;
  for (double lat : {0.0, 30.0, -60.0, 80.0}) {
    const double dec = 1.54;  // the Moon's equator to the ecliptic
    const double l = lat * kPi / 180, d = dec * kPi / 180;
    const double a = std::sin(l) * std::sin(d), b = std::cos(l) * std::cos(d);
    const double dusk_h = std::acos((std::sin(0.7 * kPi / 180) - a) / b) * 180 / kPi;
    const double rise_h = -std::acos(-a / b) * 180 / kPi;
    const double e = 1e-7;
    const auto before = airless_surface_point(moon, lat, dusk_h - e, dec);
    const auto after = airless_surface_point(moon, lat, dusk_h + e, dec);
    EXPECT_FALSE(before.night);
    EXPECT_TRUE(after.night);
    EXPECT_NEAR(before.temperature_K, after.temperature_K, 1e-3) << lat;
    EXPECT_NEAR(after.temperature_K, dusk_temperature_K(moon), 1e-3) << lat;
    const auto dawn = airless_surface_point(moon, lat, rise_h - e, dec);
    EXPECT_TRUE(dawn.night);
    EXPECT_NEAR(dawn.temperature_K, 95.0, 1e-6) << lat;
    EXPECT_NEAR(airless_surface_point(moon, lat, rise_h + e, dec).temperature_K, 95.0, 1e-6) << lat;
    // Cooling all night long.
    double previous = after.temperature_K;
    for (double h = dusk_h + 1; h < 360 + rise_h; h += 1) {
      const double T = airless_surface_point(moon, lat, h, dec).temperature_K;
      EXPECT_LT(T, previous) << lat << " " << h;
      previous = T;
    }
  }
}

// The time since dusk is the angle past the dusk hour angle over 360 deg
// times the solar day; T^-4 grows linearly with it.
TEST(ThermalAirless, TimeInShadowIsGeometric) {
  const AirlessThermal moon;
  const auto midnight = airless_surface_point(moon, 0.0, 180.0, 0.0);
  ASSERT_TRUE(midnight.night);
  EXPECT_NEAR(midnight.time_since_dusk_s, (180.0 - 89.3) / 360.0 * kMoonSolarDay_s, 1e-3);
  EXPECT_NEAR(midnight.night_length_s, (270.0 - 89.3) / 360.0 * kMoonSolarDay_s, 1e-3);
  EXPECT_NEAR(midnight.night_length_s / 86400.0, 14.82, 0.01);
  const double T_d = dusk_temperature_K(moon);
  const double n = midnight.night_length_s;
  for (double x : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    const double inv4 = std::pow(night_surface_temperature_K(x * n, n, T_d, 95.0), -4);
    EXPECT_NEAR(inv4 / std::pow(T_d, -4), 1.0 + x * (std::pow(T_d / 95.0, 4) - 1.0), 1e-9) << x;
  }
  EXPECT_NEAR(night_surface_temperature_K(2 * n, n, T_d, 95.0), 95.0, 1e-9);  // held after dawn
  EXPECT_NEAR(night_surface_temperature_K(-1.0, n, T_d, 95.0), T_d, 1e-9);
  // The same hour angle on a body with a different solar day gives the same
  // temperature (the law depends on the fraction of the night).
  AirlessThermal mercury_like = moon;
  mercury_like.solar_day_s = kMercurySolarDay_s;
  EXPECT_NEAR(airless_surface_point(mercury_like, 0.0, 180.0, 0.0).temperature_K, midnight.temperature_K, 1e-9);
  EXPECT_THROW(night_surface_temperature_K(1.0, 0.0, 130.0, 95.0), eoir::Error);
  EXPECT_THROW(night_surface_temperature_K(1.0, 10.0, 90.0, 95.0), eoir::Error);
}

// Against the Diviner equatorial night (Hurley et al. 2015 fit: 130 K at the
// terminator to 95 K before dawn).
TEST(ThermalAirless, MoonNightCloseToDiviner) {
  const AirlessThermal moon;
  double worst = 0;
  for (double h = 90.0; h <= 270.0; h += 1.0) {
    const double T = airless_surface_point(moon, 0.0, h, 0.0).temperature_K;
    worst = std::max(worst, std::abs(T - hurley_night_K(h * kPi / 180)));
  }
  EXPECT_LT(worst, 7.0);  // 6.8 K at 130 deg: the law cools more slowly early in the night
  EXPECT_NEAR(hurley_night_K(1.5 * kPi), 95.0, 0.1);
}

// Near the poles the Sun may never set (it dips below the dusk elevation
// only): the decay ends at midnight at eq. 12 there; above the dusk
// elevation all day: eq. 12 only; never up: the minimum.
TEST(ThermalAirless, PolarDayAndNight) {
  const AirlessThermal moon;
  const double dec = 1.54;
  // 89.5 N: elevation 1.04-2.04 deg, always above dusk.
  for (double h = -180; h <= 180; h += 10) {
    const auto p = airless_surface_point(moon, 89.5, h, dec);
    EXPECT_FALSE(p.night);
    EXPECT_NEAR(p.temperature_K, 390.0 * std::pow(std::sin(p.sun_elevation_deg * kPi / 180), 0.25), 1e-9);
  }
  // 88.9 N: elevation 0.44-2.64 deg: dips below dusk, never sets.
  const auto late = airless_surface_point(moon, 88.9, 180.0, dec);
  const auto early = airless_surface_point(moon, 88.9, -180.0 + 1e-9, dec);
  EXPECT_TRUE(late.night);
  EXPECT_FALSE(early.night);
  EXPECT_NEAR(late.temperature_K, early.temperature_K, 1e-4);
  EXPECT_GT(late.temperature_K, 95.0);
  // 89.5 S: the Sun never rises.
  for (double h = -180; h <= 180; h += 30)
    EXPECT_NEAR(airless_surface_point(moon, -89.5, h, dec).temperature_K, 95.0, 1e-9);
}

TEST(ThermalAirless, FromBodyFrameVectors) {
  const AirlessThermal moon;
  const Eigen::Vector3d sun(1, 0, 0), pole(0, 0, 1);
  const auto at = [&](double lat_deg, double lon_deg) {
    const double l = lat_deg * kPi / 180, o = lon_deg * kPi / 180;
    return Eigen::Vector3d(std::cos(l) * std::cos(o), std::cos(l) * std::sin(o), std::sin(l));
  };
  // East of the subsolar meridian is the afternoon (positive hour angle).
  for (double lon : {-170.0, -95.0, -30.0, 0.0, 45.0, 89.0, 91.0, 135.0, 179.0})
    for (double lat : {-40.0, 0.0, 20.0})
      EXPECT_NEAR(airless_surface_temperature_K(moon, at(lat, lon), sun, pole),
                  airless_surface_point(moon, lat, lon, 0.0).temperature_K, 1e-9)
          << lat << " " << lon;
  EXPECT_TRUE(airless_surface_point(moon, 0.0, 91.0, 0.0).night);
  EXPECT_FALSE(airless_surface_point(moon, 0.0, -89.0, 0.0).night);
  EXPECT_THROW(airless_surface_temperature_K(moon, Eigen::Vector3d::Zero(), sun, pole), eoir::Error);
}

// ---- 3. Satellites in eclipse -----------------------------------------------

TEST(ThermalEclipse, LimitsAndMonotonic) {
  EXPECT_DOUBLE_EQ(eclipse_temperature_K(300.0, 200.0, 1.0), 300.0);
  EXPECT_DOUBLE_EQ(eclipse_temperature_K(300.0, 200.0, 0.0), 200.0);
  EXPECT_NEAR(eclipse_temperature_K(300.0, 200.0, 0.5), std::pow(0.5 * (std::pow(300.0, 4) + std::pow(200.0, 4)), 0.25),
              1e-9);
  EXPECT_DOUBLE_EQ(eclipse_temperature_K(300.0, 200.0, 1.5), 300.0);  // clamped
  EXPECT_DOUBLE_EQ(eclipse_temperature_K(300.0, 200.0, -0.1), 200.0);
  EXPECT_DOUBLE_EQ(eclipse_temperature_K(300.0, 0.0, 0.0), 0.0);
  double previous = 200.0;
  for (double f = 0.01; f <= 1.0; f += 0.01) {
    const double T = eclipse_temperature_K(300.0, 200.0, f);
    EXPECT_GT(T, previous);
    previous = T;
  }
  EXPECT_THROW(eclipse_temperature_K(300.0, -1.0, 0.5), eoir::Error);
  EXPECT_THROW(eclipse_temperature_K(300.0, 200.0, std::nan("")), eoir::Error);
}
