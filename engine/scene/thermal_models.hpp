// Surface temperature laws of spec 4.3.1.3 (thermal models), as pure
// functions of geometry and time: the Earth's land/water diurnal cycle built
// on the climatology tables, the day and night sides of airless central
// bodies, and a satellite's temperature through an eclipse.
//
// Conventions: local (apparent) solar time in hours, 12 h when the Sun
// crosses the meridian; hour angle in degrees, 0 at local noon, positive in
// the afternoon; day of year 1.0 at 00:00 on 1 January (fractional).
//
// 1. Earth (spec 4.3.1.3, after Ignatov and Gutman 1999, J. Climate 12,
//    1900-1910: a monthly-mean diurnal cycle set by the daily maximum and
//    minimum only, a cosine by day and a decay by night). The equations are
//    those of Goettsche and Olesen (2001), Remote Sens. Environ. 76, 337-348
//    ("GOT01"), with its free parameters fixed so that the curve's daily
//    minimum and maximum are the table's t_min and t_max:
//      day,   t_sr <= t <= t_ss:  T = t_min + (t_max - t_min) cos(pi (t - t_m) / w)
//      night, t_ss <= t <= t_sr + 24 h:
//                                 T = T_inf + (T(t_ss) - T_inf) exp(-(t - t_ss) / k)
//    t_sr, t_ss: sunrise and sunset (local solar time) from latitude and
//    solar declination, the Sun's centre at kSunriseElevation_deg (sunrise_sunset());
//    the day length D used by the shape is held within [min_day_length_h, 24 h].
//    t_m = 12 h + max_lag_h sin(pi D / 24 h): the time of the maximum,
//    13.5 h for a 12-hour day (Holmes et al. 2013, HESS 17, 3695: thermal-IR
//    peak at 13:13 local solar time over Africa and Europe), the lag vanishing
//    as the day or the night vanishes so that t_m stays between noon and sunset.
//    w = 2 (t_m - t_sr): the cosine's half-period, so that T(t_sr) = t_min
//    (GOT01 fits w; here it is fixed by the minimum at sunrise).
//    k and T_inf (GOT01's attenuation constant and T0 + dT) solve
//    dT/dt continuous at t_ss and T(t_sr + 24 h) = t_min (the cycle closes);
//    k(1 - exp(-n/k)) = (T(t_ss) - t_min) / |dT/dt(t_ss)|, n = 24 h - D. When
//    no k exists (the sunset slope too shallow to reach t_min, which needs
//    nights much shorter than the defaults give) the night is linear.
//    The daily minimum is t_min at sunrise, the maximum t_max at t_m, exactly.
//    Polar day: D = 24 h, t_m = 12 h, w = 24 h: T = t_min at midnight, no
//    night branch. Polar night and days shorter than min_day_length_h: the
//    shape of a min_day_length_h day (max near noon, min at its "sunrise"),
//    which keeps the table's extremes where the Sun does not drive them.
//    Water uses the same shape with its own (small-amplitude) table.
//
// 2. Airless central bodies (spec 4.3.1.3). Day (eq. 12, Lawson and Jakosky):
//      T = T_ss cos^(1/4)(phi), phi the angle from the subsolar point
//        = T_ss sin^(1/4)(e), e the Sun's elevation,
//    not below the reported night minimum T_min. Night: "a T^(1/4)
//    temperature decay based on time in total shadow, tied to reported
//    minima", implemented as
//      T(t) = T_dusk (1 + t / tau)^(-1/4),  tau = t_night / ((T_dusk / T_dawn)^4 - 1)
//    (equivalently T^-4 grows linearly with the time t since dusk), where
//    tau ties the curve to the reported minimum: T(t_night) = T_dawn = T_min
//    at sunrise. Eq. 12 falls to 0 K at the terminator, so the night starts
//    at dusk, when the Sun's elevation falls to dusk_elevation_deg (0.7 deg):
//    T_dusk = max(eq. 12 there, T_min) = 0.333 T_ss (130 K for the Moon's
//    T_ss = 390 K, the equatorial terminator temperature of the Diviner fit of
//    Hurley et al. 2015, Icarus 255, 159-163). In the morning eq. 12 rises
//    from T_min at sunrise (the Sun's centre on the horizon). Both joins are
//    continuous. The time since dusk is geometric: (hour angle - dusk hour
//    angle) / 360 deg x the solar day.
//    Where the Sun never sets but dips below the dusk elevation, the night
//    ends at local midnight at the eq. 12 value there. Over the Moon's
//    equatorial night the law stays within 7 K of the Hurley et al. (2015)
//    Diviner fit (tests).
//
// 3. Satellites through an eclipse (memoryless radiative equilibrium):
//      T^4 = T_eclipse^4 + f (T_sunlit^4 - T_eclipse^4)
//    f the visible fraction of the solar disc (0 umbra, 1 full sunlight).
//    Balance per unit area: eps sigma T^4 = alpha f E_sun cos(i) + (terms
//    the eclipse is taken not to change: Earth IR and albedo, internal
//    power), so T^4 is affine in f; T_sunlit and T_eclipse are the user's two
//    equilibrium temperatures.
//    Memoryless: each instant is rendered on its own (a frame must not
//    depend on which frames were drawn before it), so no heat capacity is
//    integrated and the equilibrium is assumed at every instant. Real
//    surfaces lag by their thermal time constant (minutes for thin
//    blankets, hours for massive structure), so through the penumbra and
//    after it this overstates how fast the temperature changes.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/once.hpp"
#include "core/time.hpp"
#include "universe/surface_climatology.hpp"

namespace eoir::scene {

// ---- The Sun seen from the Earth --------------------------------------------

// Apparent sunrise/sunset: the Sun's centre 0.833 deg below the horizon
// (refraction 34' plus the semi-diameter 16'; Astronomical Almanac).
constexpr double kSunriseElevation_deg = -0.833;

// Spencer (1971), Search 2(5), 172: Fourier series of the solar declination
// (max error ~0.035 deg) and the equation of time (apparent minus mean solar
// time, ~0.5 min), of gamma = 2 pi (day_of_year - 1) / 365.
double solar_declination_deg(double day_of_year);
double equation_of_time_min(double day_of_year);

// UTC day of year (1.0 at 00:00 on 1 January, Gregorian) and UTC hour of day
// of an engine time (UT1 - UTC < 0.9 s is neglected).
struct CalendarInstant {
  double day_of_year = 1.0;
  double utc_hours = 0.0;
};
CalendarInstant calendar_instant(const EngineTime& time);

// Local apparent solar time [0, 24) h at a longitude (deg east):
// UTC + longitude / 15 + equation of time.
double local_solar_time_h(double utc_hours, double longitude_deg, double day_of_year);
double local_solar_time_h(const EngineTime& time, double longitude_deg);

// Sunrise and sunset in local solar time for the Sun's centre at
// horizon_elevation_deg: cos h0 = (sin e0 - sin(lat) sin(decl)) / (cos(lat) cos(decl)),
// t = 12 h -+ h0 / 15 deg/h. Polar day: 0 h, 24 h; polar night: 12 h, 12 h.
struct SunriseSunset {
  double sunrise_h = 6.0, sunset_h = 18.0;
  double length_h() const { return sunset_h - sunrise_h; }
  bool polar_day() const { return length_h() >= 24.0; }
  bool polar_night() const { return length_h() <= 0.0; }
};
SunriseSunset sunrise_sunset(double latitude_deg, double declination_deg,
                             double horizon_elevation_deg = kSunriseElevation_deg);

// The Sun's daily path at a latitude as sines and cosines: the latitude's,
// the declination's, and the sine of the sunrise elevation.
struct SunPathAngles {
  double sin_latitude = 0.0, cos_latitude = 1.0;
  double sin_declination = 0.0, cos_declination = 1.0;
  double sin_horizon = 0.0;
  // From degrees (validated: latitude and declination in [-90, 90], the elevation too).
  static SunPathAngles from_deg(double latitude_deg, double declination_deg, double horizon_elevation_deg);
};

// ---- 1. Earth land and water ------------------------------------------------

struct DiurnalShape {
  double max_lag_h = 1.5;         // t_m - 12 h for a 12-hour day
  double min_day_length_h = 4.0;  // shorter days (and polar night) take this one's shape
  double horizon_elevation_deg = kSunriseElevation_deg;
};

// The positive root x of 1 - exp(-x) = r x for r in (0, 1): n/k of the
// night decay (DiurnalCycle), to rounding. Throws out_of_range outside (0, 1).
double night_decay_root(double r);

// A temperature as offset + scale f(argument), f a cosine, an exponential
// or nothing (the offset alone), so that the cosines and exponentials of many
// points are taken together (temperature_terms_K).
struct TemperatureTerm {
  enum class Function : std::uint8_t { none, cos, exp };
  double offset_K = 0.0, scale_K = 0.0, argument = 0.0;
  Function function = Function::none;
  static TemperatureTerm constant(double temperature_K) { return {temperature_K, 0.0, 0.0, Function::none}; }
  double value_K() const;  // (libm)
};
// out_K[i] = terms[i].value_K() to rounding: the batch's cosines and
// exponentials by vector maths (core/vector_math.hpp).
void temperature_terms_K(const TemperatureTerm* terms, std::size_t n, double* out_K);

class DiurnalCycle {
 public:
  // Throws out_of_range for non-finite arguments, t_min_K > t_max_K or a
  // shape outside max_lag_h in [0, 3] h, min_day_length_h in (0, 12] h.
  DiurnalCycle(double t_min_K, double t_max_K, double latitude_deg, double declination_deg,
               const DiurnalShape& shape = {});
  double temperature_K(double local_solar_time_h) const;
  // The same at one local solar time, the night decay solved only for a
  // point between sunset and sunrise (it is the costly part).
  static double temperature_K(double t_min_K, double t_max_K, double latitude_deg, double declination_deg,
                              double local_solar_time_h, const DiurnalShape& shape = {});
  // The same with the Sun's path at the latitude given as sines and cosines.
  static double temperature_K(double t_min_K, double t_max_K, const SunPathAngles& sun, const DiurnalShape& shape,
                              double local_solar_time_h);

  double sunrise_h() const { return sunrise_h_; }  // start of the cosine (T = t_min)
  double sunset_h() const { return sunset_h_; }    // start of the night decay
  double time_of_max_h() const { return time_of_max_h_; }
  double half_period_h() const { return half_period_h_; }  // w
  double decay_h() const { return decay_h_; }              // k (0: flat night, infinity: linear night)
  double asymptote_K() const { return asymptote_K_; }      // T_inf
  double sunset_K() const { return sunset_K_; }

 private:
  friend class ClimatologyInstant;
  friend class DiurnalLatitudeTable;
  DiurnalCycle() = default;
  // The day branch alone; solve_night() adds the night.
  DiurnalCycle(double t_min_K, double t_max_K, const SunPathAngles& sun, const DiurnalShape& shape);
  // temperature_K(local solar time) of a cycle with the day branch alone.
  double temperature_solving_night_K(double local_solar_time_h);
  void solve_night();
  double from_sunrise_h(double local_solar_time_h) const;  // the local time in [t_sr, t_sr + 24) h
  double temperature_at_K(double from_sunrise_h) const { return temperature_term_at(from_sunrise_h).value_K(); }
  TemperatureTerm temperature_term_at(double from_sunrise_h) const;

  double t_min_K_ = 0.0, t_max_K_ = 0.0;
  double sunrise_h_ = 6.0, sunset_h_ = 18.0, time_of_max_h_ = 13.5, half_period_h_ = 15.0;
  double sunset_K_ = 0.0, sunset_slope_K_h_ = 0.0, asymptote_K_ = 0.0, decay_h_ = 0.0;
  bool linear_night_ = false;
};

// The table's extremes at (latitude, day of year), the declination of that
// day (Spencer 1971) and the diurnal cycle at the local solar time.
double surface_temperature_K(const universe::SurfaceClimatology& climatology, universe::SurfaceKind kind,
                             double latitude_deg, double day_of_year, double local_solar_time_h,
                             const DiurnalShape& shape = {});
// The same at a geodetic latitude/longitude (deg) and an engine time.
double surface_temperature_K(const universe::SurfaceClimatology& climatology, universe::SurfaceKind kind,
                             double latitude_deg, double longitude_deg, const EngineTime& time,
                             const DiurnalShape& shape = {});
// ClimatologyInstant::temperature_K of one surface kind tabulated in
// latitude, for the many points of a frame: the diurnal cycle's parameters
// (t_min, t_max, sunrise, sunset, t_m, w, T(t_ss), T_inf, k) at nodes some
// 0.025 deg apart within each interval between the climatology's band centres
// (where t_min and t_max are linear in latitude), interpolated by the cubic
// through four nodes of the same interval; the cycle at the point's local
// solar time from them. Within 1e-11 of the exact temperature, relative
// (tests ThermalEarth.LatitudeTable*), so that a frame's radiance stays
// within 1e-9 of the exact one's (issue 23 item 6). Near a change of regime
// (polar day or night, a day length held at its bounds, a linear or flat
// night, a sunrise where acos is steep, latitudes past 72.5 deg, a night
// decay near linear) the stencil's nodes are marked and the exact cycle is
// computed instead.
class DiurnalLatitudeTable {
 public:
  DiurnalLatitudeTable(const universe::ClimatologyDay& day, const SunPathAngles& sun, const DiurnalShape& shape,
                       double utc_hours, double equation_of_time_min);
  double temperature_K(double latitude_deg, double sin_latitude, double cos_latitude, double longitude_deg) const {
    return temperature_term(latitude_deg, sin_latitude, cos_latitude, longitude_deg).value_K();
  }
  TemperatureTerm temperature_term(double latitude_deg, double sin_latitude, double cos_latitude,
                                   double longitude_deg) const;
  std::size_t nodes() const { return nodes_.size(); }
  std::size_t regular_nodes() const;  // nodes whose stencils may interpolate
  bool interpolates(double latitude_deg) const;  // false: the exact cycle there

 private:
  struct Node {
    double t_min_K, t_max_K, sunrise_h, sunset_h, time_of_max_h, half_period_h, sunset_K, asymptote_K, decay_h;
    bool regular;
  };
  struct Stencil {
    const Node* nodes;  // four
    double x;           // the point among them, in [0, 3]
    bool regular;
  };
  Stencil stencil(double latitude_deg) const;
  struct Segment {
    double low_deg, width_deg;
    std::int64_t intervals, first_node;
    double intervals_per_deg;  // intervals / width_deg
  };
  universe::ClimatologyDay day_;
  SunPathAngles sun_;
  DiurnalShape shape_;
  double utc_hours_, equation_of_time_h_;  // (the equation of time in hours)
  std::vector<Segment> segments_;
  std::vector<double> segment_tops_deg_;
  std::uint16_t segment_of_degree_[181] = {};  // by latitude + 90 deg, whole degrees
  std::unique_ptr<OnceFlag[]> segment_built_;
  mutable std::vector<Node> nodes_;  // each segment's made on first use (build_segment)
  void build_segment(std::size_t segment) const;
};

// The climatology and the Sun at one instant, computed once for a frame:
// both tables at the day of year, the declination (its sine and cosine), the
// equation of time and the diurnal shape (its horizon's sine).
class ClimatologyInstant {
 public:
  ClimatologyInstant() = default;
  ClimatologyInstant(const universe::SurfaceClimatology& climatology, const CalendarInstant& calendar,
                     const DiurnalShape& shape = {});
  // surface_temperature_K at a geodetic latitude/longitude (deg).
  double temperature_K(universe::SurfaceKind kind, double latitude_deg, double longitude_deg) const;
  // The same with the latitude's sine and cosine given (a surface point has them).
  double temperature_K(universe::SurfaceKind kind, double latitude_deg, double sin_latitude, double cos_latitude,
                       double longitude_deg) const;
  // No temperature_K of this instant exceeds it: the day's greatest t_max
  // (the diurnal cycle stays within t_min..t_max).
  double hottest_K() const { return std::max(land_.hottest_K(), water_.hottest_K()); }
  // No temperature_K of this instant is below it: the day's least t_min (the
  // cycle's minimum, at sunrise).
  double coldest_K() const { return std::min(land_.coldest_K(), water_.coldest_K()); }
  // temperature_K from the kind's DiurnalLatitudeTable, made on first use
  // (its segments too) and shared by copies of this instant.
  double tabulated_temperature_K(universe::SurfaceKind kind, double latitude_deg, double sin_latitude,
                                 double cos_latitude, double longitude_deg) const {
    return latitude_table(kind).temperature_K(latitude_deg, sin_latitude, cos_latitude, longitude_deg);
  }
  const DiurnalLatitudeTable& latitude_table(universe::SurfaceKind kind) const;

 private:
  struct LatitudeTables {
    OnceFlag built[2];
    std::unique_ptr<DiurnalLatitudeTable> table[2];  // land, water
  };
  universe::ClimatologyDay land_, water_;
  CalendarInstant calendar_;
  DiurnalShape shape_;
  double equation_of_time_min_ = 0.0;
  SunPathAngles sun_;  // the declination's and the horizon's (the latitude's per point)
  std::shared_ptr<LatitudeTables> tables_ = std::make_shared<LatitudeTables>();
};

// ---- 2. Airless central bodies ----------------------------------------------

// Solar day lengths (Sun to Sun at a fixed point): NASA NSSDC planetary fact
// sheets (D. R. Williams): Mercury "length of day" 4222.6 h; the Moon's mean
// synodic month 29.530589 d; the Mars sol 88775.244 s (Allison 1997,
// Geophys. Res. Lett. 24, 1967).
constexpr double kMercurySolarDay_s = 4222.6 * 3600.0;
constexpr double kMoonSolarDay_s = 29.530589 * 86400.0;
constexpr double kMarsSolarDay_s = 88775.244;

struct AirlessThermal {
  double subsolar_K = 390.0;  // T_ss of eq. 12 (the Moon: Lawson and Jakosky)
  double night_min_K = 95.0;  // reported minimum before sunrise (the Moon: Diviner, Hurley et al. 2015)
  double solar_day_s = kMoonSolarDay_s;
  double dusk_elevation_deg = 0.7;  // the night decay starts when the Sun sinks to this elevation
};

// Eq. 12: T_ss cos^(1/4)(phi) for cos(phi) > 0, else 0.
double subsolar_temperature_K(double subsolar_K, double cos_phi);
// max(eq. 12 at dusk_elevation_deg, night_min_K).
double dusk_temperature_K(const AirlessThermal& body);
// The night law: T_dusk (1 + t/tau)^(-1/4), tau = night_length_s / ((dusk_K/dawn_K)^4 - 1),
// t clamped to [0, night_length_s]; throws out_of_range unless
// night_length_s > 0 and dusk_K >= dawn_K > 0.
double night_surface_temperature_K(double time_since_dusk_s, double night_length_s, double dusk_K, double dawn_K);

struct AirlessPoint {
  double temperature_K = 0.0;
  double sun_elevation_deg = 0.0;
  bool night = false;              // on the decay branch
  double time_since_dusk_s = 0.0;  // night only
  double night_length_s = 0.0;     // night only: dusk to sunrise
};
// A point at latitude `latitude_deg` and hour angle `hour_angle_deg` (any
// value, wrapped) on a body whose subsolar point is at `subsolar_latitude_deg`
// (the Sun's declination in the body's equator).
AirlessPoint airless_surface_point(const AirlessThermal& body, double latitude_deg, double hour_angle_deg,
                                   double subsolar_latitude_deg);
// The same from body-frame vectors: the outward normal, the direction to the
// Sun and the spin axis of the body's rotation relative to the Sun (the
// north pole for a prograde rotator); none need be unit length.
double airless_surface_temperature_K(const AirlessThermal& body, const Eigen::Vector3d& normal_body,
                                     const Eigen::Vector3d& sun_body, const Eigen::Vector3d& spin_axis_body);

// ---- 3. Satellites in eclipse -----------------------------------------------

// T = (T_e^4 + f (T_s^4 - T_e^4))^(1/4); f clamped to [0, 1]; throws
// out_of_range for negative or non-finite temperatures or a non-finite f.
double eclipse_temperature_K(double sunlit_K, double eclipse_K, double sun_fraction);

}  // namespace eoir::scene
