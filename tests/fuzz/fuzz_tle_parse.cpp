// libFuzzer target: two-line elements (plugin_host/cli/sgp4.cpp,
// Sgp4::from_tle) on arbitrary bytes: line 1 up to the first newline, line 2
// after it. Parsed with and without the checksum comparison (so that the
// fields behind a wrong checksum are reached). Refusals are
// std::invalid_argument naming "line 1 " or "line 2 "; a parsed TLE
// propagates to finite states or Sgp4Error. Anything else is a finding
// (issue 25, item 7: undefined behaviour on a satellite number of 1e300).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "fuzz_heap_bound.hpp"
#include "sgp4.hpp"

namespace {
void parse(const std::string& line1, const std::string& line2, bool check_checksum) {
  using eoir::cli::Sgp4;
  try {
    const Sgp4 sat = Sgp4::from_tle(line1, line2, check_checksum);
    for (const double minutes : {0.0, 1.0, 1440.0, -1440.0, 525960.0}) {
      try {
        const eoir::cli::TemeState s = sat.at_minutes(minutes);
        for (int i = 0; i < 3; ++i)
          if (!std::isfinite(s.r_km[i]) || !std::isfinite(s.v_km_s[i])) {
            std::fprintf(stderr, "fuzz: a state that is not finite at %g min\n", minutes);
            std::abort();
          }
      } catch (const eoir::cli::Sgp4Error&) {
      }
    }
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.rfind("line 1 ", 0) != 0 && what.rfind("line 2 ", 0) != 0) {
      std::fprintf(stderr, "fuzz: a refusal that names no line: '%s'\n", e.what());
      std::abort();
    }
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = text.find('\n');
  const std::string line1 = text.substr(0, newline);
  const std::string line2 = newline == std::string::npos ? std::string() : text.substr(newline + 1);
  eoir_fuzz::within_heap_bound(size, 16.0, std::size_t{64} << 10, [&] {
    parse(line1, line2, false);
    parse(line1, line2, true);
  });
  return 0;
}
