// The Earth's land and water climatology tables (spec 4.3.1.3, 4.2.3):
// loading, validation with file:line:field messages, and interpolation in
// latitude and day of year.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "universe/surface_climatology.hpp"

using eoir::universe::ClimatologyTable;
using eoir::universe::DailyExtremes;
using eoir::universe::kYear_days;
using eoir::universe::month_centre_day_of_year;
using eoir::universe::SurfaceClimatology;
using eoir::universe::SurfaceKind;

namespace {

const SurfaceClimatology& climatology() {
  static const SurfaceClimatology c = SurfaceClimatology::load(EOIR_DATA_OUTPUT_DIR);
  return c;
}

// A well-formed two-band table, as text; rows can be replaced by the tests.
std::string good_table() {
  std::ostringstream s;
  s << "# comment\n\nlat_center_deg,month,t_min_K,t_max_K\n";
  for (int lat : {-5, 5})
    for (int m = 1; m <= 12; ++m) s << lat << "," << m << "," << 280 + m << "," << 290 + m << "\n";
  return s.str();
}

// The message of the corrupt_file error thrown when parsing `text`.
std::string parse_error(const std::string& text) {
  std::istringstream in(text);
  try {
    ClimatologyTable::parse(in, "t.csv");
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::corrupt_file) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

// good_table() with its line `line` (1-based) replaced.
std::string with_line(int line, const std::string& replacement) {
  std::istringstream in(good_table());
  std::ostringstream out;
  std::string l;
  for (int n = 1; std::getline(in, l); ++n) out << (n == line ? replacement : l) << "\n";
  return out.str();
}

// Parsing `text` fails with a message containing `expected` ("file:line: field: why").
void expect_refused(const std::string& text, const std::string& expected) {
  const std::string message = parse_error(text);
  EXPECT_NE(message.find(expected), std::string::npos) << message;
}

}  // namespace

TEST(ThermalClimatology, LoadsTheLandAndWaterTables) {
  const auto& c = climatology();
  for (SurfaceKind kind : {SurfaceKind::land, SurfaceKind::water}) {
    const auto& bands = c.table(kind).band_centres_deg();
    ASSERT_EQ(bands.size(), 18u);
    for (std::size_t i = 0; i < bands.size(); ++i) EXPECT_DOUBLE_EQ(bands[i], -85.0 + 10.0 * i);
  }
  // Spot values of the files (45 N July, land: Minneapolis normals).
  EXPECT_DOUBLE_EQ(c.land.entry(13, 7).t_min_K, 291.15);
  EXPECT_DOUBLE_EQ(c.land.entry(13, 7).t_max_K, 301.15);
  EXPECT_DOUBLE_EQ(c.water.entry(13, 7).t_min_K, 288.41);
  EXPECT_DOUBLE_EQ(c.water.entry(13, 7).t_max_K, 289.19);
}

TEST(ThermalClimatology, TableValuesAtBandCentresAndMidMonths) {
  const auto& t = climatology().land;
  for (std::size_t b = 0; b < t.band_centres_deg().size(); ++b)
    for (int m = 1; m <= 12; ++m) {
      const DailyExtremes x = t.at(t.band_centres_deg()[b], month_centre_day_of_year(m));
      EXPECT_NEAR(x.t_min_K, t.entry(b, m).t_min_K, 1e-9);
      EXPECT_NEAR(x.t_max_K, t.entry(b, m).t_max_K, 1e-9);
    }
  EXPECT_DOUBLE_EQ(month_centre_day_of_year(1), 16.5);
  EXPECT_DOUBLE_EQ(month_centre_day_of_year(2), 46.0);
  EXPECT_DOUBLE_EQ(month_centre_day_of_year(12), 350.5);
  EXPECT_THROW(month_centre_day_of_year(13), eoir::Error);
}

TEST(ThermalClimatology, LinearBetweenBandsAndBetweenMidMonths) {
  const auto& t = climatology().land;
  // 40 N, mid-July: halfway between the 35 N and 45 N bands.
  const double july = month_centre_day_of_year(7);
  EXPECT_NEAR(t.at(40.0, july).t_max_K, 0.5 * (t.entry(12, 7).t_max_K + t.entry(13, 7).t_max_K), 1e-9);
  EXPECT_NEAR(t.at(37.5, july).t_min_K, 0.75 * t.entry(12, 7).t_min_K + 0.25 * t.entry(13, 7).t_min_K, 1e-9);
  // 45 N, halfway between mid-July and mid-August.
  const double mid = 0.5 * (july + month_centre_day_of_year(8));
  EXPECT_NEAR(t.at(45.0, mid).t_min_K, 0.5 * (t.entry(13, 7).t_min_K + t.entry(13, 8).t_min_K), 1e-9);
  // Both at once: bilinear.
  const double expected =
      0.25 * (t.entry(12, 7).t_max_K + t.entry(13, 7).t_max_K + t.entry(12, 8).t_max_K + t.entry(13, 8).t_max_K);
  EXPECT_NEAR(t.at(40.0, mid).t_max_K, expected, 1e-9);
  // Beyond the end bands the end values hold.
  EXPECT_NEAR(t.at(90.0, july).t_min_K, t.entry(17, 7).t_min_K, 1e-9);
  EXPECT_NEAR(t.at(-89.0, july).t_max_K, t.entry(0, 7).t_max_K, 1e-9);
  EXPECT_THROW(t.at(90.5, july), eoir::Error);
  EXPECT_THROW(t.at(0.0, std::nan("")), eoir::Error);
}

TEST(ThermalClimatology, PeriodicAcrossTheYearEnd) {
  const auto& t = climatology().land;
  const double lat = 65.0;  // large seasonal swing: 237.78 K in January, 282.68 K in July
  // Mid-December to mid-January spans the year end: halfway is the mean.
  const double dec = month_centre_day_of_year(12), jan = month_centre_day_of_year(1) + kYear_days;
  const double halfway = 0.5 * (dec + jan);
  const double mean_K = 0.5 * (t.entry(15, 12).t_min_K + t.entry(15, 1).t_min_K);
  EXPECT_NEAR(t.at(lat, halfway).t_min_K, mean_K, 1e-9);               // late December
  EXPECT_NEAR(t.at(lat, halfway - kYear_days).t_min_K, mean_K, 1e-9);  // the same instant, before 1 January
  // 5 January (4 days after 1 January 00:00): between last December's centre and January's.
  const double w = (4.0 - (dec - 1.0 - kYear_days)) / (jan - dec);
  EXPECT_NEAR(t.at(lat, 5.0).t_max_K, t.entry(15, 12).t_max_K + w * (t.entry(15, 1).t_max_K - t.entry(15, 12).t_max_K),
              1e-9);
  // Continuous at the year boundary and one year apart equal.
  const double eps = 1e-6;
  EXPECT_NEAR(t.at(lat, 1.0 - eps).t_min_K, t.at(lat, 1.0 + eps).t_min_K, 1e-5);
  EXPECT_NEAR(t.at(lat, 1.0 + kYear_days - eps).t_max_K, t.at(lat, 1.0).t_max_K, 1e-5);
  for (double d : {3.0, 100.25, 200.0, 360.0})
    EXPECT_NEAR(t.at(lat, d).t_max_K, t.at(lat, d + kYear_days).t_max_K, 1e-9) << d;
}

TEST(ThermalClimatology, AcceptsTheWellFormedTable) {
  std::istringstream in(good_table());
  const auto t = ClimatologyTable::parse(in, "t.csv");
  EXPECT_EQ(t.band_centres_deg().size(), 2u);
  EXPECT_NEAR(t.at(0.0, month_centre_day_of_year(3)).t_min_K, 283.0, 1e-9);
}

// Lines of good_table(): 1 comment, 2 blank, 3 header, 4-15 band -5, 16-27 band 5.
TEST(ThermalClimatology, RefusesBadTablesNamingFileLineAndField) {
  expect_refused(with_line(3, "lat_center_deg,month,t_max_K,t_min_K"), "t.csv:3: t_min_K:");
  expect_refused(with_line(3, "lat_center_deg,month,t_min_K,t_max_K,x"), "t.csv:3: header:");
  expect_refused(with_line(6, "-5,3,283"), "t.csv:6: line:");
  expect_refused(with_line(6, "-5,3,abc,293"), "t.csv:6: t_min_K: 'abc' is not a number");
  expect_refused(with_line(6, "-5,3,nan,293"), "t.csv:6: t_min_K:");
  expect_refused(with_line(6, "-5,3,283,inf"), "t.csv:6: t_max_K:");
  expect_refused(with_line(6, "-5,3,283,"), "t.csv:6: t_max_K: empty");
  expect_refused(with_line(6, "-5,3,283,500"), "t.csv:6: t_max_K: 500 outside [150, 380]");
  expect_refused(with_line(6, "-5,3,100,293"), "t.csv:6: t_min_K: 100 outside");
  expect_refused(with_line(6, "-5,3,295,293"), "t.csv:6: t_min_K: 295 above t_max_K 293");
  expect_refused(with_line(6, "-5,13,283,293"), "t.csv:6: month: 13 outside [1, 12]");
  expect_refused(with_line(6, "-5,3.5,283,293"), "t.csv:6: month: 3.5 is not a whole month");
  expect_refused(with_line(6, "-5,2,283,293"), "t.csv:6: month: 2 repeated in band -5");
  expect_refused(with_line(6, "95,3,283,293"), "t.csv:6: lat_center_deg: 95 outside [-90, 90]");
  // A band left short: reported at its last row.
  expect_refused(with_line(15, "# December removed"), "t.csv:14: month: band -5 has 11 of 12 months (missing 12)");
  // Latitudes must increase, bands be contiguous.
  expect_refused(with_line(16, "-15,1,281,291"), "t.csv:16: lat_center_deg: -15 after band -5");
  expect_refused(with_line(27, "-5,12,292,302"), "t.csv:27: lat_center_deg: -5 after band 5");
  // Empty or header-only.
  expect_refused("# nothing\n", "t.csv:1: header: missing");
  expect_refused("lat_center_deg,month,t_min_K,t_max_K\n", "t.csv:1: lat_center_deg: no data rows");
}

TEST(ThermalClimatology, MissingFilesAreIoErrors) {
  try {
    SurfaceClimatology::load("/nonexistent/data");
    FAIL() << "loaded";
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::io);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/data/earth/climatology_land.csv"), std::string::npos);
  }
}
