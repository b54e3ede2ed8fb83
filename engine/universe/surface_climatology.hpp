// The Earth's thermal climatology tables (spec 4.3.1.3: "EOIR has tables of
// max and min temperatures by latitude region and month ... separate tables
// for land and water"; spec 4.2.3: land and water have separate thermal
// model temperatures).
//
// Files: <data_dir>/earth/climatology_land.csv and climatology_water.csv
// (data/earth/README.md). '#' comments and blank lines are skipped; the
// first other line is the header `lat_center_deg,month,t_min_K,t_max_K`;
// each row gives one latitude band centre and month (1-12) with the monthly
// means of the daily minimum and maximum temperature. The rows of a band are
// contiguous, the bands in strictly increasing latitude, each with the 12
// months exactly once. Checked on load: latitudes in [-90, 90], finite
// temperatures in [kMinPlausible_K, kMaxPlausible_K], t_min_K <= t_max_K; a
// bad table throws eoir::Error(Status::corrupt_file, "file:line: field: why").
//
// Interpolation (ClimatologyTable::at): linear in latitude between band
// centres, the end bands held beyond the first and last centre; linear in
// time between mid-months, periodic over the year. Month m is centred at
// the middle of calendar month m of a 365-day year (day of year 16.5 for
// January, 46.0 for February, 75.5 for March, ...; see
// month_centre_day_of_year), and the year is taken as kYear_days = 365.2425
// days long, so that December's centre joins the next January's across the
// year end (31.24 days apart). Day of year: 1.0 at 00:00 on 1 January
// (fractional; 2.5 is noon on 2 January); values outside [1, 1 + kYear_days)
// wrap.
#pragma once
#include <array>
#include <istream>
#include <string>
#include <vector>

namespace eoir::universe {

constexpr double kMinPlausible_K = 150.0;  // below the coldest skin temperatures measured on Earth (~180 K)
constexpr double kMaxPlausible_K = 380.0;  // above the hottest desert skin temperatures (~350 K)
constexpr double kYear_days = 365.2425;    // mean Gregorian year

// Day of year (1.0 = 00:00 on 1 January) of the middle of calendar month 1-12
// of a 365-day year; throws out_of_range for other months.
double month_centre_day_of_year(int month);

enum class SurfaceKind : int { land = 0, water = 1 };

struct DailyExtremes {
  double t_min_K = 0.0;  // monthly mean of the daily minimum
  double t_max_K = 0.0;  // monthly mean of the daily maximum
};

// The table at one day of year: each band's extremes blended in time
// (ClimatologyTable::day), computed once for a frame.
class ClimatologyDay {
 public:
  // Linear in latitude between band centres, the end bands held beyond
  // them; throws out_of_range for a non-finite latitude or one outside [-90, 90].
  DailyExtremes at(double latitude_deg) const;
  // The greatest t_max_K and the least t_min_K of any band (at() stays within them).
  double hottest_K() const;
  double coldest_K() const;
  const std::vector<double>& band_centres_deg() const { return latitudes_deg_; }

 private:
  friend class ClimatologyTable;
  std::vector<double> latitudes_deg_;
  std::vector<DailyExtremes> bands_;
};

class ClimatologyTable {
 public:
  // Parses the CSV text of `in`; `name` (normally the path) starts every
  // error message.
  static ClimatologyTable parse(std::istream& in, const std::string& name);
  // Throws eoir::Error(io) if the file cannot be opened.
  static ClimatologyTable load(const std::string& path);

  // Interpolated extremes at a latitude [-90, 90] and day of year (see
  // above); throws out_of_range for a non-finite argument or a latitude
  // outside [-90, 90].
  DailyExtremes at(double latitude_deg, double day_of_year) const;  // day(day_of_year).at(latitude_deg)
  // All bands at a day of year (throws out_of_range for a non-finite day).
  ClimatologyDay day(double day_of_year) const;

  const std::string& source() const { return source_; }
  const std::vector<double>& band_centres_deg() const { return latitudes_deg_; }
  // The table entry of band `band` (index into band_centres_deg) and month 1-12.
  DailyExtremes entry(std::size_t band, int month) const;

 private:
  std::string source_;
  std::vector<double> latitudes_deg_;
  std::vector<std::array<DailyExtremes, 12>> months_;  // [band][month - 1]
};

struct SurfaceClimatology {
  ClimatologyTable land, water;
  // Loads <data_dir>/earth/climatology_land.csv and climatology_water.csv.
  static SurfaceClimatology load(const std::string& data_dir);
  const ClimatologyTable& table(SurfaceKind kind) const { return kind == SurfaceKind::land ? land : water; }
};

}  // namespace eoir::universe
