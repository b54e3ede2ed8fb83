// Strict parsing of two-line elements (plugin_host/cli/sgp4.cpp; issue 25,
// item 7): fixed columns of the TLE format, a checksum digit in column 69
// that matches, digits where the format has digits, fields in range and the
// epoch day within its year. Every refusal is std::invalid_argument naming
// the line and the field.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sgp4.hpp"
#include "tle_lines.hpp"

using eoir::cli::Sgp4;

namespace {

// The ISS set (the test scenario of check_sgp4.py; tle_lines.hpp).
const std::string& kLine1 = eoir::test::kIssLine1;
const std::string& kLine2 = eoir::test::kIssLine2;
using eoir::test::with_checksum;

// kLine1/kLine2 with `text` at 0-based column `at`, checksum recomputed.
std::string line1_with(std::size_t at, const std::string& text) {
  return with_checksum(kLine1.substr(0, 68).replace(at, text.size(), text));
}
std::string line2_with(std::size_t at, const std::string& text) {
  return with_checksum(kLine2.substr(0, 68).replace(at, text.size(), text));
}

// The message of the refusal of (l1, l2); "" (and a failure) if accepted.
std::string refusal(const std::string& l1, const std::string& l2) {
  try {
    Sgp4::from_tle(l1, l2);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << l1 << "\n" << l2;
  return {};
}

#define EXPECT_REFUSED(l1, l2, text)                      \
  do {                                                    \
    const std::string message = refusal(l1, l2);          \
    EXPECT_NE(message.find(text), std::string::npos) << message; \
  } while (0)

}  // namespace

TEST(Tle, ValidLinesParse) {
  const Sgp4 iss = Sgp4::from_tle(kLine1, kLine2);
  EXPECT_EQ(iss.satellite_number(), 25544);
  // Trailing line ends are not columns.
  EXPECT_EQ(Sgp4::from_tle(kLine1 + "\r\n", kLine2 + "\n").satellite_number(), 25544);
  // Alpha-5 numbers (A = 10: 100001).
  EXPECT_EQ(Sgp4::from_tle(line1_with(2, "A0001"), line2_with(2, "A0001")).satellite_number(), 100001);
  // The last day of a leap year.
  EXPECT_NO_THROW(Sgp4::from_tle(line1_with(18, "08366.50000000"), kLine2));
}

// Issue 25, item 7: each of these was accepted (1e300 with undefined
// behaviour: a double out of the range of long converted to long).
TEST(Tle, MalformedLinesAreRefusedNamingTheField) {
  EXPECT_REFUSED(line1_with(2, "1e300"), line2_with(2, "1e300"), "line 1 satellite number");
  EXPECT_REFUSED(line1_with(2, "0x1p9"), line2_with(2, "00512"), "line 1 satellite number");
  EXPECT_REFUSED(kLine1.substr(0, 68) + "X", kLine2, "line 1 checksum: column 69 is 'X', not a digit");
  EXPECT_REFUSED(kLine1, kLine2.substr(0, 68) + " ", "line 2 checksum");
  EXPECT_REFUSED(kLine1.substr(0, 67), kLine2, "line 1 format: 67 columns");
  EXPECT_REFUSED(kLine1 + " trailing", kLine2, "line 1 format: 78 columns");
  EXPECT_REFUSED(kLine1, kLine2 + "0", "line 2 format: 70 columns");
  EXPECT_REFUSED(kLine1, line2_with(8, "181.0000"), "line 2 inclination: 181.0000 outside [0, 180]");
  EXPECT_REFUSED(kLine1, line2_with(8, "-51.6416"), "line 2 inclination: '-51.6416' is not of the form NNN.NNNN");
  EXPECT_REFUSED(line1_with(18, "09366.50000000"), kLine2, "line 1 epoch day: 366.50000000 outside [1, 366) in 2009");
  EXPECT_REFUSED(line1_with(18, "08000.50000000"), kLine2, "line 1 epoch day: 000.50000000 outside [1, 367) in 2008");
  EXPECT_REFUSED(kLine1, line2_with(17, "360.5000"), "line 2 right ascension of the node: 360.5000 outside [0, 360)");
  EXPECT_REFUSED(kLine1, line2_with(34, "1e2.0000"), "line 2 argument of perigee");
  EXPECT_REFUSED(kLine1, line2_with(43, " inf    "), "line 2 mean anomaly");
  EXPECT_REFUSED(kLine1, line2_with(52, "00.00000000"), "line 2 mean motion: must be positive");
  EXPECT_REFUSED(kLine1, line2_with(26, "00-6703"), "line 2 eccentricity");
  EXPECT_REFUSED(line1_with(33, "-.0000x182"), kLine2, "line 1 ndot");
  EXPECT_REFUSED(line1_with(44, " 00000x0"), kLine2, "line 1 nddot");
  EXPECT_REFUSED(line1_with(53, "-11606-x"), kLine2, "line 1 bstar");
  EXPECT_REFUSED(line1_with(7, "X"), kLine2, "line 1 classification");
  EXPECT_REFUSED(line1_with(18, "x8"), kLine2, "line 1 epoch year");
  EXPECT_REFUSED(line1_with(64, "29x7"), kLine2, "line 1 element set number");
  EXPECT_REFUSED(kLine1, line2_with(63, "5x353"), "line 2 revolution number");
  EXPECT_REFUSED(line1_with(1, "x"), kLine2, "line 1 format");
  EXPECT_REFUSED(kLine1, line2_with(2, "25545"), "line 2 satellite number: differs from line 1's");
  // A wrong checksum digit, as before.
  EXPECT_REFUSED(kLine1.substr(0, 68) + "8", kLine2, "line 1 checksum: column 69 is 8 but the line sums to 7");
}
