// The TLE tests' shared set: the ISS example of the TLE format (both
// checksums right) and the checksum of column 69 for edited lines.
#pragma once
#include <string>

namespace eoir::test {

inline const std::string kIssLine1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
inline const std::string kIssLine2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

// The first 68 columns with column 69: their digits, and 1 for each '-', mod 10.
inline std::string with_checksum(const std::string& first_68) {
  int sum = 0;
  for (char c : first_68) sum += c >= '0' && c <= '9' ? c - '0' : c == '-';
  return first_68 + std::to_string(sum % 10);
}

}  // namespace eoir::test
