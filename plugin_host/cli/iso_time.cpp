#include "iso_time.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace eoir::cli {
namespace {

// Days from 1970-01-01 to a civil date (H. Hinnant's algorithm).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

void civil_from_days(long long z, long long& y, unsigned& m, unsigned& d) {
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  y = static_cast<long long>(yoe) + era * 400;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = doy - (153 * mp + 2) / 5 + 1;
  m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2;
}

// 2000-01-01T12:00:00 in seconds since 1970-01-01T00:00:00.
constexpr double kJ2000Unix = 946728000.0;

bool leap(long long y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

}  // namespace

double parse_iso(const std::string& iso) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, consumed = 0;
  double s = 0.0;
  const auto bad = [&](const char* why) {
    return std::invalid_argument("'" + iso + "' is not an ISO-8601 UTC time (" + why + ")");
  };
  const char* c = iso.c_str();
  if (std::sscanf(c, "%5d-%2d-%2d%n", &y, &mo, &d, &consumed) != 3 || consumed != 10)
    throw bad("expected YYYY-MM-DD");
  std::size_t pos = static_cast<std::size_t>(consumed);
  if (pos < iso.size() && (iso[pos] == 'T' || iso[pos] == ' ')) {
    int n = 0;
    if (std::sscanf(c + pos + 1, "%2d:%2d:%lf%n", &h, &mi, &s, &n) != 3 || n < 8)
      throw bad("expected hh:mm:ss after the date");
    pos += 1 + static_cast<std::size_t>(n);
  }
  if (pos < iso.size() && (iso[pos] == 'Z' || iso[pos] == 'z')) ++pos;
  if (pos != iso.size()) throw bad("unexpected trailing characters; only UTC ('Z') is accepted");
  static const int mdays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (mo < 1 || mo > 12) throw bad("month out of range");
  if (d < 1 || d > mdays[mo - 1] + (mo == 2 && leap(y) ? 1 : 0)) throw bad("day out of range");
  if (h > 23 || mi > 59 || !(s >= 0.0 && s < 61.0)) throw bad("time of day out of range");
  const long long days = days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d));
  return static_cast<double>(days) * 86400.0 + h * 3600.0 + mi * 60.0 + s - kJ2000Unix;
}

std::string format_iso(double seconds) {
  // Round to whole milliseconds first so that 59.9996 s carries into minutes.
  const long long ms = std::llround((seconds + kJ2000Unix) * 1000.0);
  long long days = ms / 86400000, rem = ms % 86400000;
  if (rem < 0) {
    rem += 86400000;
    --days;
  }
  long long y;
  unsigned m, d;
  civil_from_days(days, y, m, d);
  const long long h = rem / 3600000, mi = rem / 60000 % 60, s = rem / 1000 % 60, f = rem % 1000;
  char buf[64];
  if (f != 0)
    std::snprintf(buf, sizeof buf, "%04lld-%02u-%02uT%02lld:%02lld:%02lld.%03lldZ", y, m, d, h, mi, s, f);
  else
    std::snprintf(buf, sizeof buf, "%04lld-%02u-%02uT%02lld:%02lld:%02lldZ", y, m, d, h, mi, s);
  return buf;
}

}  // namespace eoir::cli
