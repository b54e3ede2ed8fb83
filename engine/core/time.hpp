// Engine time (spec 3.2): TT kept as whole days since J2000.0 plus a fraction
// of a day, so that a step of one millisecond is exact over centuries.
// Conversions between scales go through ERFA.
#pragma once
#include <string>

namespace eoir {

enum class TimeScale : int { utc = 0, tai = 1, tt = 2, tdb = 3 };

// A two-part Julian date in a given scale (as ERFA's date1 + date2).
struct JulianDate {
  TimeScale scale = TimeScale::tt;
  double jd1 = 2451545.0;
  double jd2 = 0.0;
};

// The dates the engine accepts, TT: 1000-01-01 to 3000-01-01 (JD 2086302.5 to
// 2816787.5, J2000.0 -/+ 365,242.5 days), the span of ERFA's eraPlan94
// (the planets' places before issue 21; the VSOP87B series that replaced it
// hold to arcseconds over it); the Earth (eraEpv00) and the Moon (eraMoon98)
// degrade gracefully over it. UTC before 1960 is TAI (ERFA
// has no leap seconds before then).
constexpr double min_tt_days_since_j2000 = 2086302.5 - 2451545.0;
constexpr double max_tt_days_since_j2000 = 2816787.5 - 2451545.0;
// Each part of a two-part Julian date, in days.
constexpr double max_julian_date_part = 1.0e7;

class EngineTime {
 public:
  EngineTime() = default;
  // From any scale; throws eoir::Error(out_of_range) naming `field` (e.g.
  // "time.jd1", "times[3].jd2") for non-finite parts, parts beyond
  // max_julian_date_part, dates ERFA cannot convert and dates outside the
  // accepted range above.
  static EngineTime from(const JulianDate& date, const std::string& field = "time");
  static EngineTime from_tt_days(double days_since_j2000, double fraction_of_day);
  JulianDate to(TimeScale scale) const;
  // Whole TT days since J2000.0 and fraction of a day in [0, 1).
  double days() const { return days_; }
  double fraction() const { return fraction_; }
  // Seconds from `other` to this (exact to well below a microsecond).
  double seconds_since(const EngineTime& other) const;
  // Throws out_of_range for non-finite seconds or a result beyond
  // max_julian_date_part from J2000.0 (derived times may leave the accepted
  // range: light times, integration windows).
  EngineTime plus_seconds(double seconds) const;
  bool operator==(const EngineTime& o) const { return days_ == o.days_ && fraction_ == o.fraction_; }

 private:
  void normalise();
  // Throws out_of_range naming `field` outside the accepted range.
  void check_range(const std::string& field) const;
  double days_ = 0.0;
  double fraction_ = 0.0;
};

// ISO-8601 UTC "YYYY-MM-DDThh:mm:ss[.fff][Z]" <-> UTC two-part JD. Throws
// eoir::Error(out_of_range) naming the problem.
JulianDate utc_from_iso(const std::string& iso);
std::string iso_from_utc(const JulianDate& utc, int decimals = 3);

}  // namespace eoir
