#include "scene/thermal_models.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/vector_math.hpp"

namespace eoir::scene {
namespace {

using constants::deg_per_rad;
using constants::pi;
using constants::rad_per_deg;

constexpr double kHoursPerDay = 24.0;

[[noreturn]] void throw_out_of_range(double value, double lo, double hi, std::string_view field) {
  require_finite(value, field);
  throw Error(Status::out_of_range, std::string(field) + ": " + std::to_string(value) + " outside [" +
                                        std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// A compare unless it fails (NaN fails it too).
inline void require_range(double value, double lo, double hi, std::string_view field) {
  if (!(value >= lo && value <= hi)) throw_out_of_range(value, lo, hi, field);
}

// x wrapped into [0, period).
double wrap(double x, double period) {
  // (fmod is exact: within one period either side it is x or x - period,
  // which are exact there too, Sterbenz)
  double r = x >= 0.0 && x < period           ? x
             : x >= period && x < 2.0 * period ? x - period
             : x < 0.0 && x > -period          ? x
                                               : std::fmod(x, period);
  if (r < 0.0) r += period;
  return r >= period ? 0.0 : r;
}

// Hour angle wrapped into (-180, 180] deg.
double wrap_hour_angle_deg(double h) {
  double r = wrap(h, 360.0);
  return r > 180.0 ? r - 360.0 : r;
}

double local_solar_time_from_eot_h(double utc_hours, double longitude_deg, double equation_of_time_min) {
  require_finite(utc_hours, "utc_hours");
  require_finite(longitude_deg, "longitude_deg");
  return wrap(utc_hours + longitude_deg / 15.0 + equation_of_time_min / 60.0, kHoursPerDay);
}

void check_body(const AirlessThermal& body) {
  require_positive(body.subsolar_K, "subsolar_temperature_K");
  require_positive(body.night_min_K, "night_temperature_K");
  require_positive(body.solar_day_s, "solar_day_s");
  require_range(body.dusk_elevation_deg, 1e-6, 90.0, "dusk_elevation_deg");
}

}  // namespace

// ---- The Sun seen from the Earth --------------------------------------------

double solar_declination_deg(double day_of_year) {
  require_finite(day_of_year, "day_of_year");
  const double g = 2.0 * pi * (day_of_year - 1.0) / 365.0;  // Spencer's day angle
  const double rad = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) - 0.006758 * std::cos(2 * g) +
                     0.000907 * std::sin(2 * g) - 0.002697 * std::cos(3 * g) + 0.001480 * std::sin(3 * g);
  return rad * deg_per_rad;
}

double equation_of_time_min(double day_of_year) {
  require_finite(day_of_year, "day_of_year");
  const double g = 2.0 * pi * (day_of_year - 1.0) / 365.0;
  return 229.18 * (0.000075 + 0.001868 * std::cos(g) - 0.032077 * std::sin(g) - 0.014615 * std::cos(2 * g) -
                   0.040849 * std::sin(2 * g));
}

CalendarInstant calendar_instant(const EngineTime& time) {
  const JulianDate utc = time.to(TimeScale::utc);
  // Whole days Z and fraction F of JD + 0.5, kept apart for precision.
  const double a = utc.jd1 + 0.5;
  double z = std::floor(a) + std::floor(utc.jd2);
  double f = (a - std::floor(a)) + (utc.jd2 - std::floor(utc.jd2));
  if (f >= 1.0) {
    f -= 1.0;
    z += 1.0;
  }
  // Gregorian calendar date (Meeus 1998, Astronomical Algorithms, ch. 7).
  double big_a = z;
  if (z >= 2299161.0) {
    const double alpha = std::floor((z - 1867216.25) / 36524.25);
    big_a = z + 1.0 + alpha - std::floor(alpha / 4.0);
  }
  const double b = big_a + 1524.0;
  const double c = std::floor((b - 122.1) / 365.25);
  const double d = std::floor(365.25 * c);
  const double e = std::floor((b - d) / 30.6001);
  const double day = b - d - std::floor(30.6001 * e);
  const double month = e < 14.0 ? e - 1.0 : e - 13.0;
  const long year = static_cast<long>(month > 2.0 ? c - 4716.0 : c - 4715.0);
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  const double k = leap ? 1.0 : 2.0;
  const double n = std::floor(275.0 * month / 9.0) - k * std::floor((month + 9.0) / 12.0) + day - 30.0;
  return {n + f, kHoursPerDay * f};
}

double local_solar_time_h(double utc_hours, double longitude_deg, double day_of_year) {
  return local_solar_time_from_eot_h(utc_hours, longitude_deg, equation_of_time_min(day_of_year));
}

double local_solar_time_h(const EngineTime& time, double longitude_deg) {
  const CalendarInstant c = calendar_instant(time);
  return local_solar_time_h(c.utc_hours, longitude_deg, c.day_of_year);
}

SunPathAngles SunPathAngles::from_deg(double latitude_deg, double declination_deg, double horizon_elevation_deg) {
  require_range(latitude_deg, -90.0, 90.0, "latitude_deg");
  require_range(declination_deg, -90.0, 90.0, "declination_deg");
  require_range(horizon_elevation_deg, -90.0, 90.0, "horizon_elevation_deg");
  const double lat = latitude_deg * rad_per_deg, dec = declination_deg * rad_per_deg;
  return {std::sin(lat), std::cos(lat), std::sin(dec), std::cos(dec), std::sin(horizon_elevation_deg * rad_per_deg)};
}

namespace {

// Half the Sun's arc above the horizon: cos h0 = (sin e0 - sin(lat) sin(decl))
// / (cos(lat) cos(decl)); h0 in (0, pi) rad and its sine, or a polar day or night.
struct HalfDay {
  enum Kind { arc, polar_day, polar_night } kind = arc;
  double h0_rad = 0.0, sin_h0 = 0.0;
};
void check_shape(const DiurnalShape& shape) {
  require_range(shape.max_lag_h, 0.0, 3.0, "max_lag_h");
  require_range(shape.min_day_length_h, 1e-3, 12.0, "min_day_length_h");
}

// The day's Sun path (declination, horizon) at a latitude given as sine and cosine.
SunPathAngles at_latitude(SunPathAngles sun, double sin_latitude, double cos_latitude) {
  sun.sin_latitude = sin_latitude;
  sun.cos_latitude = cos_latitude;
  return sun;
}

HalfDay half_day(const SunPathAngles& s) {
  // Elevation over the day: sin e = a + b cos h.
  const double a = s.sin_latitude * s.sin_declination, b = s.cos_latitude * s.cos_declination;
  if (b <= 1e-12 || (s.sin_horizon - a) / b <= -1.0)
    return {a + b > s.sin_horizon ? HalfDay::polar_day : HalfDay::polar_night, 0.0, 0.0};
  const double c = (s.sin_horizon - a) / b;
  if (c >= 1.0) return {HalfDay::polar_night, 0.0, 0.0};
  return {HalfDay::arc, std::acos(c), std::sqrt((1.0 - c) * (1.0 + c))};
}

SunriseSunset sunrise_sunset(const HalfDay& d) {
  if (d.kind == HalfDay::polar_day) return {0.0, 24.0};
  if (d.kind == HalfDay::polar_night) return {12.0, 12.0};
  const double h0_h = d.h0_rad * deg_per_rad / 15.0;
  return {12.0 - h0_h, 12.0 + h0_h};
}

}  // namespace

SunriseSunset sunrise_sunset(double latitude_deg, double declination_deg, double horizon_elevation_deg) {
  return sunrise_sunset(half_day(SunPathAngles::from_deg(latitude_deg, declination_deg, horizon_elevation_deg)));
}

// ---- 1. Earth land and water ------------------------------------------------

namespace {

// F(x) = 1 - exp(-x) - r x is concave with F(0) = 0, F'(0) = 1 - r > 0, so
// its positive root x* lies where F falls (F' < 0). Newton's step F / F'
// from x; expm1 keeps 1 - exp(-x) exact at small x.
double night_decay_newton_step(double x, double r) {
  const double e_minus_1 = std::expm1(-x);
  return (-e_minus_1 - r * x) / (1.0 + e_minus_1 - r);
}

// The root by Newton from x0 = 1/r (F(x0) = -exp(-1/r) < 0, right of x*:
// the steps fall monotonically, the tangent of a concave F lying above it)
// until they stop changing x.
double night_decay_root_from_the_right(double r) {
  double x = 1.0 / r;
  for (int i = 0; i < 200; ++i) {
    const double step = night_decay_newton_step(x, r);
    x -= step;
    if (!(step > 1e-16 * x)) break;
  }
  return x;
}

// y(r) = r x*(r) on r in [0, 1] (smooth: 1 - exp(-1/r) + ... as r -> 0,
// 2 (1 - r) + ... as r -> 1), cubic Hermite on kIntervals intervals with the
// implicit derivative dx/dr = x / (exp(-x) - r): a start within ~1e-12 of
// the root, so that one Newton step leaves it exact.
class NightDecayStart {
 public:
  static constexpr int kIntervals = 2048;
  NightDecayStart() {
    for (int k = 0; k <= kIntervals; ++k) {
      const double r = static_cast<double>(k) / kIntervals;
      if (k == 0) {
        y_[0] = 1.0;
        dy_dr_[0] = 0.0;
      } else if (k == kIntervals) {
        y_[k] = 0.0;
        dy_dr_[k] = -2.0;
      } else {
        const double x = night_decay_root_from_the_right(r);
        y_[k] = r * x;
        dy_dr_[k] = x + r * x / ((1.0 - r) + std::expm1(-x));  // exp(-x) - r
      }
    }
  }
  double x0(double r) const {
    const double u = std::clamp(r, 0.0, 1.0) * kIntervals;
    const int k = std::min(static_cast<int>(u), kIntervals - 1);
    const double t = u - k, h = 1.0 / kIntervals;
    const double t2 = t * t, t3 = t2 * t;
    const double y = (2 * t3 - 3 * t2 + 1) * y_[k] + (t3 - 2 * t2 + t) * h * dy_dr_[k] +
                     (-2 * t3 + 3 * t2) * y_[k + 1] + (t3 - t2) * h * dy_dr_[k + 1];
    return y / r;
  }

 private:
  double y_[kIntervals + 1], dy_dr_[kIntervals + 1];
};

}  // namespace

double night_decay_root(double r) {
  if (!(r > 0.0 && r < 1.0))
    throw Error(Status::out_of_range, "night_decay_root r: " + std::to_string(r) + " outside (0, 1)");
  static const NightDecayStart start;
  double x = start.x0(r);
  // Quadratic convergence: the error after a step is ~ M step^2, M =
  // |F''/2F'| = exp(-x) / 2|F'|, and M x* <= 1 for every r in (0, 1) (0.4 at
  // r = 0.4, -> 1 as r -> 1), so a step below 1e-8 x leaves an error below
  // 1e-16 x: it is the last (one step from the table's start).
  for (int i = 0; i < 100; ++i) {
    const double step = night_decay_newton_step(x, r);
    x -= step;
    if (!(std::fabs(step) > 1e-8 * x)) break;
  }
  return x;
}

DiurnalCycle::DiurnalCycle(double t_min_K, double t_max_K, double latitude_deg, double declination_deg,
                           const DiurnalShape& shape)
    : DiurnalCycle(t_min_K, t_max_K,
                   SunPathAngles::from_deg(latitude_deg, declination_deg, shape.horizon_elevation_deg), shape) {
  solve_night();
}

DiurnalCycle::DiurnalCycle(double t_min_K, double t_max_K, const SunPathAngles& sun, const DiurnalShape& shape)
    : t_min_K_(t_min_K), t_max_K_(t_max_K) {
  require_finite(t_min_K, "t_min_K");
  require_finite(t_max_K, "t_max_K");
  if (t_min_K > t_max_K)
    throw Error(Status::out_of_range,
                "t_min_K: " + std::to_string(t_min_K) + " above t_max_K " + std::to_string(t_max_K));
  check_shape(shape);

  const HalfDay half = half_day(sun);
  const double length_h = sunrise_sunset(half).length_h();
  const double day_h = std::clamp(length_h, shape.min_day_length_h, kHoursPerDay);
  sunrise_h_ = 12.0 - 0.5 * day_h;
  sunset_h_ = 12.0 + 0.5 * day_h;
  // sin(pi D / 24 h) = sin h0 for the Sun's own day (pi D / 24 h = h0).
  const bool own_day = half.kind == HalfDay::arc && day_h == length_h;
  const double lag_h = shape.max_lag_h * (own_day ? half.sin_h0 : std::sin(pi * day_h / kHoursPerDay));
  time_of_max_h_ = 12.0 + lag_h;
  half_period_h_ = 2.0 * (time_of_max_h_ - sunrise_h_);  // cos = 0 at sunrise: T(t_sr) = t_min
  const double range_K = t_max_K - t_min_K;
  const double theta_s = pi * (sunset_h_ - time_of_max_h_) / half_period_h_;  // in (0, pi/2) for a day < 24 h
  sunset_K_ = t_min_K + range_K * std::cos(theta_s);
  sunset_slope_K_h_ = range_K * pi / half_period_h_ * std::sin(theta_s);  // -dT/dt at sunset
  asymptote_K_ = t_min_K;
}

void DiurnalCycle::solve_night() {
  decay_h_ = 0.0;
  const double night_h = kHoursPerDay - (sunset_h_ - sunrise_h_);
  const double drop_K = sunset_K_ - t_min_K_;
  if (night_h <= 0.0 || drop_K <= 0.0 || sunset_slope_K_h_ <= 0.0) return;  // no night, or a flat one at t_min
  // k (1 - exp(-n/k)) = q: increasing in k from 0 to n, so a root exists iff q < n.
  const double q_h = drop_K / sunset_slope_K_h_;
  if (q_h >= night_h) {
    linear_night_ = true;
    decay_h_ = std::numeric_limits<double>::infinity();
    return;
  }
  // With x = n/k and r = q/n in (0, 1): 1 - exp(-x) = r x.
  decay_h_ = night_h / night_decay_root(q_h / night_h);
  asymptote_K_ = sunset_K_ - decay_h_ * sunset_slope_K_h_;
}

double DiurnalCycle::temperature_K(double t_min_K, double t_max_K, double latitude_deg, double declination_deg,
                                   double local_solar_time_h, const DiurnalShape& shape) {
  return temperature_K(t_min_K, t_max_K,
                       SunPathAngles::from_deg(latitude_deg, declination_deg, shape.horizon_elevation_deg), shape,
                       local_solar_time_h);
}

double DiurnalCycle::temperature_K(double t_min_K, double t_max_K, const SunPathAngles& sun, const DiurnalShape& shape,
                                   double local_solar_time_h) {
  return DiurnalCycle(t_min_K, t_max_K, sun, shape).temperature_solving_night_K(local_solar_time_h);
}

double DiurnalCycle::temperature_solving_night_K(double local_solar_time_h) {
  const double u = from_sunrise_h(local_solar_time_h);
  if (u > sunset_h_) solve_night();  // only a night-time point needs the decay
  return temperature_at_K(u);
}

double DiurnalCycle::temperature_K(double local_solar_time_h) const {
  return temperature_at_K(from_sunrise_h(local_solar_time_h));
}

double DiurnalCycle::from_sunrise_h(double local_solar_time_h) const {
  require_finite(local_solar_time_h, "local_solar_time_h");
  return sunrise_h_ + wrap(local_solar_time_h - sunrise_h_, kHoursPerDay);  // [t_sr, t_sr + 24)
}

double TemperatureTerm::value_K() const {
  switch (function) {
    case Function::cos: return offset_K + scale_K * std::cos(argument);
    case Function::exp: return offset_K + scale_K * std::exp(argument);
    case Function::none: break;
  }
  return offset_K;
}

void temperature_terms_K(const TemperatureTerm* terms, std::size_t n, double* out_K) {
  constexpr std::size_t kBatch = 64;
  double argument[2][kBatch], value[2][kBatch];
  std::size_t at[2][kBatch];
  for (std::size_t first = 0; first < n; first += kBatch) {
    const std::size_t m = std::min(kBatch, n - first);
    std::size_t count[2] = {0, 0};  // cosines, exponentials
    for (std::size_t k = 0; k < m; ++k) {
      const TemperatureTerm& t = terms[first + k];
      if (t.function == TemperatureTerm::Function::none) {
        out_K[first + k] = t.offset_K;
        continue;
      }
      const int f = t.function == TemperatureTerm::Function::cos ? 0 : 1;
      argument[f][count[f]] = t.argument;
      at[f][count[f]++] = first + k;
    }
    vector_math::cos(argument[0], value[0], count[0]);
    vector_math::exp(argument[1], value[1], count[1]);
    for (int f = 0; f < 2; ++f)
      for (std::size_t j = 0; j < count[f]; ++j) {
        const TemperatureTerm& t = terms[at[f][j]];
        out_K[at[f][j]] = t.offset_K + t.scale_K * value[f][j];
      }
  }
}

TemperatureTerm DiurnalCycle::temperature_term_at(double u) const {
  using F = TemperatureTerm::Function;
  const double range_K = t_max_K_ - t_min_K_;
  if (range_K <= 0.0) return TemperatureTerm::constant(t_min_K_);
  if (u <= sunset_h_) return {t_min_K_, range_K, pi * (u - time_of_max_h_) / half_period_h_, F::cos};
  const double since_sunset_h = u - sunset_h_;
  if (linear_night_) {
    const double night_h = kHoursPerDay - (sunset_h_ - sunrise_h_);
    return TemperatureTerm::constant(sunset_K_ - (sunset_K_ - t_min_K_) * std::min(since_sunset_h / night_h, 1.0));
  }
  if (decay_h_ <= 0.0) return TemperatureTerm::constant(t_min_K_);
  return {asymptote_K_, sunset_K_ - asymptote_K_, -since_sunset_h / decay_h_, F::exp};
}

double surface_temperature_K(const universe::SurfaceClimatology& climatology, universe::SurfaceKind kind,
                             double latitude_deg, double day_of_year, double local_solar_time_h,
                             const DiurnalShape& shape) {
  const universe::DailyExtremes x = climatology.table(kind).at(latitude_deg, day_of_year);
  return DiurnalCycle::temperature_K(x.t_min_K, x.t_max_K, latitude_deg, solar_declination_deg(day_of_year),
                                     local_solar_time_h, shape);
}

double surface_temperature_K(const universe::SurfaceClimatology& climatology, universe::SurfaceKind kind,
                             double latitude_deg, double longitude_deg, const EngineTime& time,
                             const DiurnalShape& shape) {
  const ClimatologyInstant now(climatology, calendar_instant(time), shape);
  return now.temperature_K(kind, latitude_deg, longitude_deg);
}

ClimatologyInstant::ClimatologyInstant(const universe::SurfaceClimatology& climatology,
                                       const CalendarInstant& calendar, const DiurnalShape& shape)
    : land_(climatology.land.day(calendar.day_of_year)),
      water_(climatology.water.day(calendar.day_of_year)),
      calendar_(calendar),
      shape_(shape),
      equation_of_time_min_(equation_of_time_min(calendar.day_of_year)),
      sun_(SunPathAngles::from_deg(0.0, solar_declination_deg(calendar.day_of_year), shape.horizon_elevation_deg)) {
  check_shape(shape);  // (here, not in the latitude tables' first use inside a frame)
}

double ClimatologyInstant::temperature_K(universe::SurfaceKind kind, double latitude_deg, double longitude_deg) const {
  require_range(latitude_deg, -90.0, 90.0, "latitude_deg");
  const double lat = latitude_deg * rad_per_deg;
  return temperature_K(kind, latitude_deg, std::sin(lat), std::cos(lat), longitude_deg);
}

double ClimatologyInstant::temperature_K(universe::SurfaceKind kind, double latitude_deg, double sin_latitude,
                                         double cos_latitude, double longitude_deg) const {
  const universe::DailyExtremes x = (kind == universe::SurfaceKind::land ? land_ : water_).at(latitude_deg);
  return DiurnalCycle::temperature_K(x.t_min_K, x.t_max_K, at_latitude(sun_, sin_latitude, cos_latitude), shape_,
                                     local_solar_time_from_eot_h(calendar_.utc_hours, longitude_deg, equation_of_time_min_));
}

const DiurnalLatitudeTable& ClimatologyInstant::latitude_table(universe::SurfaceKind kind) const {
  const int k = kind == universe::SurfaceKind::land ? 0 : 1;
  tables_->built[k].call([&] {
    tables_->table[k] = std::make_unique<DiurnalLatitudeTable>(k == 0 ? land_ : water_, sun_, shape_,
                                                               calendar_.utc_hours, equation_of_time_min_);
  });
  return *tables_->table[k];
}

bool DiurnalLatitudeTable::interpolates(double latitude_deg) const { return stencil(latitude_deg).regular; }

std::size_t DiurnalLatitudeTable::regular_nodes() const {
  for (std::size_t s = 0; s < segments_.size(); ++s) segment_built_[s].call([&] { build_segment(s); });
  return static_cast<std::size_t>(std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.regular; }));
}

namespace {

// Node spacing of the latitude tables (at most; an interval between band
// centres takes a whole number of steps): the cubic's error is about
// 0.02 h^4 |f''''| (0.04 h^4 |f''''| in an interval's end cells), below
// 1e-12 of the cycle's parameters at 0.025 deg.
constexpr double kTableStep_deg = 0.025;
// A node is regular (its stencils interpolate) only well inside its regime:
// |cos h0| at most kMaxCosHalfDay (acos and its derivatives steep near
// +-1), the latitude's cosine at least kMinCosLatitude (cos h0 = (sin e0 -
// sin phi sin delta) / (cos phi cos delta) steep near the poles: 1e-11 off
// at 77 deg with 0.2), and the night decay's r = q / n at most
// kMaxNightDecayRatio (k and T_inf diverge as r -> 1).
constexpr double kMaxCosHalfDay = 0.8;
constexpr double kMinCosLatitude = 0.3;
constexpr double kMaxNightDecayRatio = 0.9;

}  // namespace

DiurnalLatitudeTable::DiurnalLatitudeTable(const universe::ClimatologyDay& day, const SunPathAngles& sun,
                                           const DiurnalShape& shape, double utc_hours, double equation_of_time_min)
    : day_(day),
      sun_(sun),
      shape_(shape),
      utc_hours_(utc_hours),
      equation_of_time_h_(equation_of_time_min / 60.0) {
  // Segments between -90, the band centres and 90 deg.
  std::vector<double> edges{-90.0};
  for (double c : day.band_centres_deg())
    if (c > edges.back() && c < 90.0) edges.push_back(c);
  edges.push_back(90.0);
  std::int64_t count = 0;
  for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
    const double width = edges[s + 1] - edges[s];
    const auto intervals = std::max<std::int64_t>(3, static_cast<std::int64_t>(std::ceil(width / kTableStep_deg - 1e-9)));
    segments_.push_back({edges[s], width, intervals, count, static_cast<double>(intervals) / width});
    segment_tops_deg_.push_back(edges[s + 1]);
    count += intervals + 1;
  }
  nodes_.resize(static_cast<std::size_t>(count));
  for (int d = 0; d <= 180; ++d) {  // the first segment reaching each whole degree
    std::size_t s = 0;
    while (s + 1 < segments_.size() && segment_tops_deg_[s] < static_cast<double>(d - 90)) ++s;
    segment_of_degree_[static_cast<std::size_t>(d)] = static_cast<std::uint16_t>(s);
  }
  segment_built_ = std::make_unique<OnceFlag[]>(segments_.size());
}

// A segment's nodes, made on first use: inside a frame's shading, each
// thread makes the segments its samples reach (so no thread of its own, and
// a frame that sees few latitudes makes few), about 0.1 ms each.
void DiurnalLatitudeTable::build_segment(std::size_t s) const {
  const Segment& g = segments_[s];
  for (std::int64_t i = 0; i <= g.intervals; ++i) {
    const double lat_deg =
        i == g.intervals ? segment_tops_deg_[s]
                         : std::min(90.0, g.low_deg + g.width_deg * static_cast<double>(i) / static_cast<double>(g.intervals));
    const double lat = lat_deg * rad_per_deg;
    const SunPathAngles here = at_latitude(sun_, std::sin(lat), std::cos(lat));
    Node& node = nodes_[static_cast<std::size_t>(g.first_node + i)];
    node.regular = false;
    if (here.cos_latitude < kMinCosLatitude) continue;  // (never interpolated)
    const universe::DailyExtremes x = day_.at(lat_deg);
    DiurnalCycle c(x.t_min_K, x.t_max_K, here, shape_);
    const HalfDay half = half_day(here);
    const double length_h = sunrise_sunset(half).length_h();
    const double cos_h0 = half.kind == HalfDay::arc ? std::cos(half.h0_rad) : 1.0;
    bool regular = half.kind == HalfDay::arc && std::fabs(cos_h0) <= kMaxCosHalfDay &&
                   length_h > shape_.min_day_length_h && length_h < kHoursPerDay && x.t_max_K > x.t_min_K &&
                   c.sunset_slope_K_h_ > 0.0 && c.sunset_K_ > x.t_min_K;
    if (regular) {
      const double night_h = kHoursPerDay - length_h;
      const double ratio = (c.sunset_K_ - x.t_min_K) / c.sunset_slope_K_h_ / night_h;
      regular = ratio > 0.0 && ratio <= kMaxNightDecayRatio;
    }
    if (regular) c.solve_night();
    node = {x.t_min_K,       x.t_max_K,         c.sunrise_h_, c.sunset_h_,
            c.time_of_max_h_, c.half_period_h_, c.sunset_K_,  c.asymptote_K_,
            c.decay_h_,       regular && !c.linear_night_ && c.decay_h_ > 0.0};
  }
}

DiurnalLatitudeTable::Stencil DiurnalLatitudeTable::stencil(double latitude_deg) const {
  require_range(latitude_deg, -90.0, 90.0, "latitude_deg");
  std::size_t s = segment_of_degree_[static_cast<std::size_t>(latitude_deg + 90.0)];
  while (s + 1 < segments_.size() && latitude_deg > segment_tops_deg_[s]) ++s;
  segment_built_[s].call([&] { build_segment(s); });
  const Segment& g = segments_[s];
  const double t = std::clamp((latitude_deg - g.low_deg) * g.intervals_per_deg, 0.0, static_cast<double>(g.intervals));
  const std::int64_t k0 = std::clamp<std::int64_t>(static_cast<std::int64_t>(t) - 1, 0, g.intervals - 3);
  const Node* n = &nodes_[static_cast<std::size_t>(g.first_node + k0)];
  return {n, t - static_cast<double>(k0), n[0].regular && n[1].regular && n[2].regular && n[3].regular};
}

TemperatureTerm DiurnalLatitudeTable::temperature_term(double latitude_deg, double sin_latitude,
                                                      double cos_latitude, double longitude_deg) const {
  // (local_solar_time_from_eot_h with the equation of time in hours made once)
  require_finite(longitude_deg, "longitude_deg");
  const double local_h = wrap(utc_hours_ + longitude_deg / 15.0 + equation_of_time_h_, kHoursPerDay);
  const Stencil st = stencil(latitude_deg);
  if (!st.regular) {
    const universe::DailyExtremes x = day_.at(latitude_deg);
    return TemperatureTerm::constant(DiurnalCycle::temperature_K(
        x.t_min_K, x.t_max_K, at_latitude(sun_, sin_latitude, cos_latitude), shape_, local_h));
  }
  const Node* n = st.nodes;
  // Lagrange weights of the nodes at 0, 1, 2, 3 for x in [0, 3].
  const double x = st.x;
  const double a = x - 1.0, b = x - 2.0, c = x - 3.0;
  constexpr double kSixth = 1.0 / 6.0;
  const double w0 = -a * b * c * kSixth, w1 = x * b * c * 0.5, w2 = -x * a * c * 0.5, w3 = x * a * b * kSixth;
  const auto at = [&](double Node::*field) {
    return w0 * n[0].*field + w1 * n[1].*field + w2 * n[2].*field + w3 * n[3].*field;
  };
  // Sunrise and sunset first: then only the branch's own parameters.
  DiurnalCycle cycle;
  cycle.sunrise_h_ = at(&Node::sunrise_h);
  cycle.sunset_h_ = at(&Node::sunset_h);
  cycle.t_min_K_ = at(&Node::t_min_K);
  cycle.t_max_K_ = at(&Node::t_max_K);
  const double u = cycle.from_sunrise_h(local_h);
  if (u <= cycle.sunset_h_) {
    cycle.time_of_max_h_ = at(&Node::time_of_max_h);
    cycle.half_period_h_ = at(&Node::half_period_h);
  } else {
    cycle.sunset_K_ = at(&Node::sunset_K);
    cycle.asymptote_K_ = at(&Node::asymptote_K);
    cycle.decay_h_ = at(&Node::decay_h);
  }
  return cycle.temperature_term_at(u);
}

// ---- 2. Airless central bodies ----------------------------------------------

double subsolar_temperature_K(double subsolar_K, double cos_phi) {
  require_non_negative(subsolar_K, "subsolar_temperature_K");
  require_finite(cos_phi, "cos_phi");
  return cos_phi > 0.0 ? subsolar_K * std::pow(std::min(cos_phi, 1.0), 0.25) : 0.0;  // eq. 12
}

double dusk_temperature_K(const AirlessThermal& body) {
  check_body(body);
  return std::max(subsolar_temperature_K(body.subsolar_K, std::sin(body.dusk_elevation_deg * rad_per_deg)),
                  body.night_min_K);
}

double night_surface_temperature_K(double time_since_dusk_s, double night_length_s, double dusk_K, double dawn_K) {
  require_finite(time_since_dusk_s, "time_since_dusk_s");
  require_positive(night_length_s, "night_length_s");
  require_positive(dawn_K, "dawn_temperature_K");
  require_finite(dusk_K, "dusk_temperature_K");
  if (dusk_K < dawn_K)
    throw Error(Status::out_of_range,
                "dusk_temperature_K: " + std::to_string(dusk_K) + " below the dawn minimum " + std::to_string(dawn_K));
  const double x = std::clamp(time_since_dusk_s / night_length_s, 0.0, 1.0);  // t / t_night
  const double r = std::pow(dusk_K / dawn_K, 4) - 1.0;                        // t_night / tau
  return dusk_K * std::pow(1.0 + r * x, -0.25);
}

AirlessPoint airless_surface_point(const AirlessThermal& body, double latitude_deg, double hour_angle_deg,
                                   double subsolar_latitude_deg) {
  check_body(body);
  require_range(latitude_deg, -90.0, 90.0, "latitude_deg");
  require_range(subsolar_latitude_deg, -90.0, 90.0, "subsolar_latitude_deg");
  require_finite(hour_angle_deg, "hour_angle_deg");
  const double h = wrap_hour_angle_deg(hour_angle_deg);
  const double lat = latitude_deg * rad_per_deg, dec = subsolar_latitude_deg * rad_per_deg;
  const double a = std::sin(lat) * std::sin(dec), b = std::cos(lat) * std::cos(dec);
  auto sin_elevation = [&](double h_deg) { return std::clamp(a + b * std::cos(h_deg * rad_per_deg), -1.0, 1.0); };
  // Eq. 12 by day, not below the reported minimum (cos phi = sin e).
  auto day_K = [&](double sin_e) { return std::max(subsolar_temperature_K(body.subsolar_K, sin_e), body.night_min_K); };

  AirlessPoint p;
  const double sin_e = sin_elevation(h);
  p.sun_elevation_deg = std::asin(sin_e) * deg_per_rad;
  p.temperature_K = day_K(sin_e);
  if (b <= 1e-12) return p;  // a pole, or the Sun over a pole: no diurnal motion
  const double cos_dusk = (std::sin(body.dusk_elevation_deg * rad_per_deg) - a) / b;
  if (cos_dusk <= -1.0 || cos_dusk >= 1.0) return p;        // the Sun never crosses the dusk elevation
  const double dusk_h = std::acos(cos_dusk) * deg_per_rad;  // (0, 180)
  const double cos_rise = -a / b;
  double rise_h = -180.0, dawn_K = day_K(sin_elevation(180.0));  // the Sun never sets: ends at midnight
  if (cos_rise > -1.0) {
    rise_h = -std::acos(std::min(cos_rise, 1.0)) * deg_per_rad;
    dawn_K = body.night_min_K;
  }
  if (h < dusk_h && h > rise_h) return p;

  p.night = true;
  p.time_since_dusk_s = wrap(h - dusk_h, 360.0) / 360.0 * body.solar_day_s;
  p.night_length_s = wrap(rise_h - dusk_h, 360.0) / 360.0 * body.solar_day_s;
  p.temperature_K =
      night_surface_temperature_K(p.time_since_dusk_s, p.night_length_s, dusk_temperature_K(body), dawn_K);
  return p;
}

double airless_surface_temperature_K(const AirlessThermal& body, const Eigen::Vector3d& normal_body,
                                     const Eigen::Vector3d& sun_body, const Eigen::Vector3d& spin_axis_body) {
  if (!normal_body.allFinite() || !sun_body.allFinite() || !spin_axis_body.allFinite())
    throw Error(Status::out_of_range, "airless_surface_temperature_K: vectors must be finite");
  if (normal_body.norm() == 0.0 || sun_body.norm() == 0.0 || spin_axis_body.norm() == 0.0)
    throw Error(Status::out_of_range, "airless_surface_temperature_K: vectors must be non-zero");
  const Eigen::Vector3d w = spin_axis_body.normalized(), n = normal_body.normalized(), s = sun_body.normalized();
  const double lat_deg = std::asin(std::clamp(n.dot(w), -1.0, 1.0)) * deg_per_rad;
  const double dec_deg = std::asin(std::clamp(s.dot(w), -1.0, 1.0)) * deg_per_rad;
  // Hour angle: from the Sun's meridian to the point's, in the sense of rotation.
  const Eigen::Vector3d n_eq = n - n.dot(w) * w, s_eq = s - s.dot(w) * w;
  const double hour_deg = std::atan2(s_eq.cross(n_eq).dot(w), s_eq.dot(n_eq)) * deg_per_rad;
  return airless_surface_point(body, lat_deg, hour_deg, dec_deg).temperature_K;
}

// ---- 3. Satellites in eclipse -----------------------------------------------

double eclipse_temperature_K(double sunlit_K, double eclipse_K, double sun_fraction) {
  require_non_negative(sunlit_K, "sunlit_temperature_K");
  require_non_negative(eclipse_K, "eclipse_temperature_K");
  require_finite(sun_fraction, "sun_fraction");
  const double f = std::clamp(sun_fraction, 0.0, 1.0);
  const double e4 = std::pow(eclipse_K, 4);
  return std::pow(e4 + f * (std::pow(sunlit_K, 4) - e4), 0.25);
}

}  // namespace eoir::scene
