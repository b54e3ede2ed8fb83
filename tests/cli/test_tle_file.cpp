// A file of two-line element sets as a scenario's objects (issue 23 item 3;
// plugin_host/cli/tle_file.hpp): one satellite per set, named by its title
// line; a corrupt set is refused naming its line in the file.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "tle_file.hpp"
#include "tle_lines.hpp"

using eoir::cli::parse_tle_file;
using eoir::cli::Sgp4;

namespace {

// The ISS set (tle_lines.hpp), and its lines with the satellite number and
// mean anomaly changed, checksum redone.
const std::string& kLine1 = eoir::test::kIssLine1;
const std::string& kLine2 = eoir::test::kIssLine2;
using eoir::test::with_checksum;
std::string line1(const std::string& satnum) { return with_checksum(kLine1.substr(0, 68).replace(2, 5, satnum)); }
std::string line2(const std::string& satnum, const std::string& field = "", std::size_t at = 0) {
  std::string l = kLine2.substr(0, 68).replace(2, 5, satnum);
  if (!field.empty()) l.replace(at, field.size(), field);
  return with_checksum(l);
}

std::string refusal(const std::string& text) {
  try {
    parse_tle_file(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(TleFile, NamesFromTitleLines) {
  // Three-line form with "0 " titles, a plain title, CRLF line ends, blank
  // lines between sets and trailing blanks on a title.
  const std::string text = "ISS (ZARYA)   \r\n" + kLine1 + "\r\n" + kLine2 + "\r\n\r\n" + "0 GEO-SAT 2\n" +
                           line1("11111") + "\n" + line2("11111") + "\n" + "DEB 3\n" + line1("22222") + "\n" +
                           line2("22222") + "\n\n";
  const auto sets = parse_tle_file(text);
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_EQ(sets[0].name, "ISS (ZARYA)");
  EXPECT_EQ(sets[1].name, "GEO-SAT 2");
  EXPECT_EQ(sets[2].name, "DEB 3");
  EXPECT_EQ(sets[0].title_line, 1u);
  EXPECT_EQ(sets[1].title_line, 5u);
  EXPECT_EQ(sets[2].title_line, 8u);
  EXPECT_EQ(sets[1].sgp4.satellite_number(), 11111);
  // Each set is its own lines' SGP4: the same state as the lines alone.
  const auto alone = Sgp4::from_tle(line1("22222"), line2("22222")).at_minutes(90.0);
  const auto from_file = sets[2].sgp4.at_minutes(90.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(from_file.r_km[i], alone.r_km[i]);
    EXPECT_EQ(from_file.v_km_s[i], alone.v_km_s[i]);
  }
}

TEST(TleFile, CorruptSetRefusedNamingTheLine) {
  const std::string good = "SAT A\n" + kLine1 + "\n" + kLine2 + "\n";
  // Line 6 (the second set's line 2): inclination 181.
  const std::string bad_inclination = good + "SAT B\n" + line1("11111") + "\n" + line2("11111", "181.0000", 8) + "\n";
  std::string why = refusal(bad_inclination);
  EXPECT_EQ(why.rfind("line 6: ", 0), 0u) << why;
  EXPECT_NE(why.find("SAT B"), std::string::npos) << why;
  EXPECT_NE(why.find("inclination"), std::string::npos) << why;
  // Line 5 (the second set's line 1): a wrong checksum digit.
  std::string l1 = line1("11111");
  l1.back() = l1.back() == '0' ? '1' : '0';
  why = refusal(good + "SAT B\n" + l1 + "\n" + line2("11111") + "\n");
  EXPECT_EQ(why.rfind("line 5: ", 0), 0u) << why;
  EXPECT_NE(why.find("checksum"), std::string::npos) << why;
  // A set cut short: its title's line.
  why = refusal(good + "SAT B\n" + line1("11111") + "\n");
  EXPECT_EQ(why.rfind("line 4: ", 0), 0u) << why;
  EXPECT_NE(why.find("cut short"), std::string::npos) << why;
  // No title before line 1.
  why = refusal(kLine1 + "\n" + kLine2 + "\n");
  EXPECT_EQ(why.rfind("line 1: ", 0), 0u) << why;
  EXPECT_NE(why.find("title"), std::string::npos) << why;
  // A name used twice.
  why = refusal(good + "SAT A\n" + line1("11111") + "\n" + line2("11111") + "\n");
  EXPECT_EQ(why.rfind("line 4: ", 0), 0u) << why;
  EXPECT_NE(why.find("twice"), std::string::npos) << why;
  // A title longer than a name may be (63 bytes).
  why = refusal(std::string(64, 'X') + "\n" + kLine1 + "\n" + kLine2 + "\n");
  EXPECT_EQ(why.rfind("line 1: ", 0), 0u) << why;
  // An empty file.
  why = refusal("\n\n");
  EXPECT_NE(why.find("no two-line element sets"), std::string::npos) << why;
}

}  // namespace
