// Reading JSON input files defensively (scenario files of the CLI and of the
// host library). Before the document is built, one streaming (SAX) pass over
// the text refuses, naming the JSON path of the problem:
//   - nesting deeper than kMaxJsonDepth arrays/objects (a 100,000-deep
//     document would otherwise exhaust the stack in recursive code);
//   - a key given twice in one object (JSON leaves it undefined; nlohmann
//     keeps the last silently);
//   - numbers outside the range of a double (1e999);
// and files larger than kMaxJsonFileBytes are not read at all (/dev/zero).
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace eoir::cli {

// Scenario files nest 6 levels deep; 64 leaves room for any real document.
constexpr int kMaxJsonDepth = 64;
// 64 MiB: far above any scenario (an ephemeris of 100,000 points is ~15 MB).
constexpr std::size_t kMaxJsonFileBytes = std::size_t{64} << 20;

// what() is "PATH: why" (PATH "" for the document itself, e.g.
// "objects[0].motion.lat_deg: number out of range (1e999)").
class JsonInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses `text` with the checks above. Throws JsonInputError.
nlohmann::json parse_json_checked(const std::string& text);

// Reads a whole file of at most kMaxJsonFileBytes (regular files are checked
// by size first; pipes and devices are read up to the cap). Throws
// JsonInputError ("cannot open ...", "larger than ...").
std::string read_file_capped(const std::string& path, std::size_t max_bytes = kMaxJsonFileBytes);

}  // namespace eoir::cli
