#include "universe/surface_climatology.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "core/read_file.hpp"

namespace eoir::universe {
namespace {

constexpr int kMonthDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
constexpr const char* kColumns[4] = {"lat_center_deg", "month", "t_min_K", "t_max_K"};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(s);
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!s.empty() && s.back() == ',') fields.emplace_back();
  return fields;
}

std::string format(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

// One band being read: its latitude, the line of its last row, its months.
struct Band {
  double latitude_deg = 0.0;
  long last_line = 0;
  std::array<DailyExtremes, 12> months{};
  std::array<bool, 12> seen{};
};

}  // namespace

double month_centre_day_of_year(int month) {
  if (month < 1 || month > 12)
    throw Error(Status::out_of_range, "month: " + std::to_string(month) + " outside [1, 12]");
  double start = 0.0;
  for (int m = 1; m < month; ++m) start += kMonthDays[m - 1];
  return 1.0 + start + 0.5 * kMonthDays[month - 1];
}

ClimatologyTable ClimatologyTable::parse(std::istream& in, const std::string& name) {
  ClimatologyTable table;
  table.source_ = name;
  bool have_header = false;
  bool have_band = false;
  Band band;
  std::string line;
  long line_number = 0;

  auto close_band = [&]() {
    int count = 0;
    std::string missing;
    for (int m = 0; m < 12; ++m) {
      if (band.seen[m]) {
        ++count;
      } else {
        missing += (missing.empty() ? "" : " ") + std::to_string(m + 1);
      }
    }
    if (count != 12)
      throw Error(Status::corrupt_file, name + ":" + std::to_string(band.last_line) + ": month: band " +
                                            format(band.latitude_deg) + " has " + std::to_string(count) +
                                            " of 12 months (missing " + missing + ")");
    table.latitudes_deg_.push_back(band.latitude_deg);
    table.months_.push_back(band.months);
  };

  while (std::getline(in, line)) {
    ++line_number;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::string where = name + ":" + std::to_string(line_number) + ": ";
    const auto fields = split_commas(content);
    if (!have_header) {
      for (std::size_t c = 0; c < 4; ++c)
        if (c >= fields.size() || fields[c] != kColumns[c])
          throw Error(Status::corrupt_file, where + kColumns[c] + ": expected as column " + std::to_string(c + 1) +
                                                " of the header lat_center_deg,month,t_min_K,t_max_K");
      if (fields.size() != 4)
        throw Error(Status::corrupt_file, where + "header: " + std::to_string(fields.size()) + " columns, expected 4");
      have_header = true;
      continue;
    }
    if (fields.size() != 4)
      throw Error(Status::corrupt_file, where + "line: " + std::to_string(fields.size()) + " fields, expected 4");
    auto number = [&](std::size_t c, double lo, double hi) {
      const std::string& text = fields[c];
      if (text.empty()) throw Error(Status::corrupt_file, where + kColumns[c] + ": empty");
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || errno == ERANGE)
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + text + "' is not a number");
      if (!std::isfinite(value))
        throw Error(Status::corrupt_file, where + kColumns[c] + ": '" + text + "' is not a finite number");
      if (value < lo || value > hi)
        throw Error(Status::corrupt_file,
                    where + kColumns[c] + ": " + text + " outside [" + format(lo) + ", " + format(hi) + "]");
      return value;
    };
    const double latitude_deg = number(0, -90.0, 90.0);
    const double month_value = number(1, 1.0, 12.0);
    if (month_value != std::floor(month_value))
      throw Error(Status::corrupt_file, where + "month: " + fields[1] + " is not a whole month 1-12");
    const int month = static_cast<int>(month_value);
    const double t_min_K = number(2, kMinPlausible_K, kMaxPlausible_K);
    const double t_max_K = number(3, kMinPlausible_K, kMaxPlausible_K);
    if (t_min_K > t_max_K)
      throw Error(Status::corrupt_file, where + "t_min_K: " + fields[2] + " above t_max_K " + fields[3]);

    if (!have_band || latitude_deg != band.latitude_deg) {
      if (have_band) {
        if (!(latitude_deg > band.latitude_deg))
          throw Error(Status::corrupt_file, where + "lat_center_deg: " + fields[0] + " after band " +
                                                format(band.latitude_deg) +
                                                " (bands must be contiguous, in strictly increasing latitude)");
        close_band();
      }
      band = Band{};
      band.latitude_deg = latitude_deg;
      have_band = true;
    }
    if (band.seen[month - 1])
      throw Error(Status::corrupt_file, where + "month: " + std::to_string(month) + " repeated in band " + fields[0]);
    band.seen[month - 1] = true;
    band.months[month - 1] = {t_min_K, t_max_K};
    band.last_line = line_number;
  }
  const std::string at_end = name + ":" + std::to_string(line_number) + ": ";
  if (!have_header)
    throw Error(Status::corrupt_file, at_end + "header: missing (no lat_center_deg,month,t_min_K,t_max_K line)");
  if (!have_band) throw Error(Status::corrupt_file, at_end + "lat_center_deg: no data rows");
  close_band();
  return table;
}

ClimatologyTable ClimatologyTable::load(const std::string& path) {
  std::istringstream in(read_file(path, std::size_t{1} << 20, "climatology tables"));
  return parse(in, path);
}

DailyExtremes ClimatologyTable::entry(std::size_t band, int month) const {
  if (band >= months_.size() || month < 1 || month > 12)
    throw Error(Status::out_of_range,
                source_ + ": no band " + std::to_string(band) + " month " + std::to_string(month));
  return months_[band][static_cast<std::size_t>(month - 1)];
}

ClimatologyDay ClimatologyTable::day(double day_of_year) const {
  require_finite(day_of_year, "day_of_year");
  // Days since 1 January 00:00 wrapped into one year, then the two
  // bracketing mid-months (December -> January across the year end).
  double x = std::fmod(day_of_year - 1.0, kYear_days);
  if (x < 0.0) x += kYear_days;
  int m0 = 12, m1 = 1;  // before January's centre: between last December and January
  double c0 = month_centre_day_of_year(12) - 1.0 - kYear_days, c1 = month_centre_day_of_year(1) - 1.0;
  for (int m = 1; m <= 12; ++m) {
    const double c = month_centre_day_of_year(m) - 1.0;
    if (x >= c) {
      m0 = m;
      c0 = c;
      m1 = m == 12 ? 1 : m + 1;
      c1 = m == 12 ? month_centre_day_of_year(1) - 1.0 + kYear_days : month_centre_day_of_year(m + 1) - 1.0;
    }
  }
  const double w_time = (x - c0) / (c1 - c0);
  ClimatologyDay day;
  day.latitudes_deg_ = latitudes_deg_;
  for (const auto& band : months_) {
    const DailyExtremes a = band[static_cast<std::size_t>(m0 - 1)], c = band[static_cast<std::size_t>(m1 - 1)];
    day.bands_.push_back(
        {a.t_min_K + w_time * (c.t_min_K - a.t_min_K), a.t_max_K + w_time * (c.t_max_K - a.t_max_K)});
  }
  return day;
}

DailyExtremes ClimatologyTable::at(double latitude_deg, double day_of_year) const {
  require_finite(latitude_deg, "latitude_deg");
  return day(day_of_year).at(latitude_deg);
}

double ClimatologyDay::hottest_K() const {
  double t = 0.0;
  for (const DailyExtremes& b : bands_) t = std::max(t, b.t_max_K);
  return t;
}

double ClimatologyDay::coldest_K() const {
  double t = std::numeric_limits<double>::infinity();
  for (const DailyExtremes& b : bands_) t = std::min(t, b.t_min_K);
  return t;
}

DailyExtremes ClimatologyDay::at(double latitude_deg) const {
  require_finite(latitude_deg, "latitude_deg");
  if (latitude_deg < -90.0 || latitude_deg > 90.0)
    throw Error(Status::out_of_range, "latitude_deg: " + format(latitude_deg) + " outside [-90, 90]");
  // The two bracketing bands and the weight of the upper one.
  const auto& lat = latitudes_deg_;
  if (latitude_deg <= lat.front()) return bands_.front();
  if (latitude_deg >= lat.back()) return bands_.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(lat.begin(), lat.end(), latitude_deg) - lat.begin());
  const std::size_t lo = hi - 1;
  const double w_lat = (latitude_deg - lat[lo]) / (lat[hi] - lat[lo]);
  const DailyExtremes a = bands_[lo], b = bands_[hi];
  return {a.t_min_K + w_lat * (b.t_min_K - a.t_min_K), a.t_max_K + w_lat * (b.t_max_K - a.t_max_K)};
}

SurfaceClimatology SurfaceClimatology::load(const std::string& data_dir) {
  const std::string folder = data_dir + "/earth/";
  return {ClimatologyTable::load(folder + "climatology_land.csv"),
          ClimatologyTable::load(folder + "climatology_water.csv")};
}

}  // namespace eoir::universe
