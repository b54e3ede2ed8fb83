// A file of two-line element sets, one satellite per set (a scenario's
// objects[i].tle_file): each set is a title line (the object's name; a
// leading "0 " of the three-line form is dropped, trailing blanks too)
// followed by its line 1 and line 2 (sgp4.hpp). Blank lines between sets are
// skipped.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "sgp4.hpp"

namespace eoir::cli {

struct TleSet {
  std::string name;  // from the title line
  std::size_t title_line = 0;  // 1-based line number of the title in the file
  Sgp4 sgp4;
};

// Parses the text of a TLE file. Throws std::invalid_argument naming the
// line ("line 8: line 2 inclination: 181.0000 outside [0, 180]"): a set cut
// short, a title that is empty or longer than 63 bytes, a name used twice, an
// element line SGP4 refuses (sgp4.hpp).
std::vector<TleSet> parse_tle_file(const std::string& text);

}  // namespace eoir::cli
