#include "core/time.hpp"

#include <erfa.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "core/error.hpp"

namespace eoir {
namespace {
constexpr double j2000_jd = 2451545.0;

void check(int erfa_status, const char* what, const std::string& field = "time") {
  if (erfa_status < 0) throw Error(Status::out_of_range, field + ": " + what + " failed (date out of range)");
}

// TT two-part JD from any scale.
void to_tt(const JulianDate& d, double& tt1, double& tt2, const std::string& field) {
  double a1 = 0, a2 = 0;
  switch (d.scale) {
    case TimeScale::tt: tt1 = d.jd1; tt2 = d.jd2; return;
    case TimeScale::tai: check(eraTaitt(d.jd1, d.jd2, &tt1, &tt2), "TAI to TT", field); return;
    case TimeScale::utc:
      check(eraUtctai(d.jd1, d.jd2, &a1, &a2), "UTC to TAI", field);
      check(eraTaitt(a1, a2, &tt1, &tt2), "TAI to TT", field);
      return;
    case TimeScale::tdb:
      // TDB-TT is below 2 ms; one fixed-point pass with the geocentric model.
      tt1 = d.jd1;
      tt2 = d.jd2 - eraDtdb(d.jd1, d.jd2, 0.0, 0.0, 0.0, 0.0) / 86400.0;
      return;
  }
  throw Error(Status::out_of_range, field + ".scale: unknown time scale");
}
}  // namespace

EngineTime EngineTime::from(const JulianDate& date, const std::string& field) {
  // Each part at most 1e7 days: every split of a date in the accepted range
  // (JD + 0, 2400000.5 + MJD, 0 + JD) fits, and the two parts cannot cancel
  // each other's precision away (1e308 - 1e308).
  for (const auto& [part, name] : {std::pair{date.jd1, field + ".jd1"}, std::pair{date.jd2, field + ".jd2"}}) {
    require_finite(part, name);
    if (std::fabs(part) > max_julian_date_part) {
      char text[160];
      std::snprintf(text, sizeof text, ": %.10g days: each part of a two-part Julian date must be within +/-%.0e", part,
                    max_julian_date_part);
      throw Error(Status::out_of_range, name + text);
    }
  }
  double tt1 = 0, tt2 = 0;
  to_tt(date, tt1, tt2, field);
  EngineTime t;
  // Split into whole days since J2000.0 and a fraction, keeping precision.
  const double d1 = tt1 - j2000_jd;
  const double whole1 = std::floor(d1);
  const double whole2 = std::floor(tt2);
  t.days_ = whole1 + whole2;
  t.fraction_ = (d1 - whole1) + (tt2 - whole2);
  t.normalise();
  t.check_range(field + ".jd1 + " + field + ".jd2");
  return t;
}

EngineTime EngineTime::from_tt_days(double days_since_j2000, double fraction_of_day) {
  require_finite(days_since_j2000, "time.days");
  require_finite(fraction_of_day, "time.fraction");
  EngineTime t;
  t.days_ = days_since_j2000;
  t.fraction_ = fraction_of_day;
  t.normalise();
  t.check_range("time.days");
  return t;
}

void EngineTime::normalise() {
  const double whole = std::floor(days_);
  fraction_ += days_ - whole;
  days_ = whole;
  const double carry = std::floor(fraction_);
  days_ += carry;
  fraction_ -= carry;
}

void EngineTime::check_range(const std::string& field) const {
  const double days = days_ + fraction_;
  if (days >= min_tt_days_since_j2000 && days <= max_tt_days_since_j2000) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "%s: TT JD %.10g is outside the dates the engine accepts, 1000-01-01 to 3000-01-01 TT (JD %.1f to "
                "%.1f, where ERFA's planetary ephemerides are valid)",
                field.c_str(), j2000_jd + days, j2000_jd + min_tt_days_since_j2000, j2000_jd + max_tt_days_since_j2000);
  throw Error(Status::out_of_range, text);
}

JulianDate EngineTime::to(TimeScale scale) const {
  const double tt1 = j2000_jd + days_, tt2 = fraction_;
  JulianDate out{scale, tt1, tt2};
  double a1 = 0, a2 = 0;
  switch (scale) {
    case TimeScale::tt: return out;
    case TimeScale::tai: check(eraTttai(tt1, tt2, &out.jd1, &out.jd2), "TT to TAI"); return out;
    case TimeScale::utc:
      check(eraTttai(tt1, tt2, &a1, &a2), "TT to TAI");
      check(eraTaiutc(a1, a2, &out.jd1, &out.jd2), "TAI to UTC");
      return out;
    case TimeScale::tdb:
      check(eraTttdb(tt1, tt2, eraDtdb(tt1, tt2, 0.0, 0.0, 0.0, 0.0), &out.jd1, &out.jd2), "TT to TDB");
      return out;
  }
  throw Error(Status::out_of_range, "scale: unknown time scale");
}

double EngineTime::seconds_since(const EngineTime& other) const {
  return ((days_ - other.days_) + (fraction_ - other.fraction_)) * 86400.0;
}

EngineTime EngineTime::plus_seconds(double seconds) const {
  require_finite(seconds, "seconds");
  EngineTime t = *this;
  const double whole_days = std::floor(seconds / 86400.0);
  t.days_ += whole_days;
  t.fraction_ += (seconds - whole_days * 86400.0) / 86400.0;
  t.normalise();
  // Derived times (light time, the integration window) may leave the
  // accepted range; they only need to stay where the split is exact.
  if (!(std::fabs(t.days_) <= max_julian_date_part))
    throw Error(Status::out_of_range, "seconds: " + std::to_string(seconds) + " s leaves the span of two-part dates");
  return t;
}

JulianDate utc_from_iso(const std::string& iso) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, consumed = 0;
  double s = 0;
  if (std::sscanf(iso.c_str(), "%d-%d-%dT%d:%d:%lf%n", &y, &mo, &d, &h, &mi, &s, &consumed) != 6 &&
      std::sscanf(iso.c_str(), "%d-%d-%d %d:%d:%lf%n", &y, &mo, &d, &h, &mi, &s, &consumed) != 6)
    throw Error(Status::out_of_range, "time: '" + iso + "' is not ISO-8601 YYYY-MM-DDThh:mm:ss[.fff]Z");
  const std::string rest = iso.substr(static_cast<size_t>(consumed));
  if (!(rest.empty() || rest == "Z" || rest == "z" || rest == "+00:00"))
    throw Error(Status::out_of_range, "time: '" + iso + "' must be UTC (suffix Z)");
  JulianDate out{TimeScale::utc, 0, 0};
  const int st = eraDtf2d("UTC", y, mo, d, h, mi, s, &out.jd1, &out.jd2);
  if (st < 0) throw Error(Status::out_of_range, "time: '" + iso + "' is not a valid calendar date/time");
  return out;
}

std::string iso_from_utc(const JulianDate& utc, int decimals) {
  int ihmsf[4];
  int y = 0, mo = 0, d = 0;
  if (eraD2dtf("UTC", decimals, utc.jd1, utc.jd2, &y, &mo, &d, ihmsf) < 0)
    throw Error(Status::out_of_range, "time: cannot format date as ISO-8601");
  char buf[64];
  if (decimals > 0)
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%0*dZ", y, mo, d, ihmsf[0], ihmsf[1], ihmsf[2],
                  decimals, ihmsf[3]);
  else
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02dZ", y, mo, d, ihmsf[0], ihmsf[1], ihmsf[2]);
  return buf;
}
}  // namespace eoir
