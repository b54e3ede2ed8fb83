// Parsing the engine's JSON input files defensively (state, sensor, material
// and map files, composite parts). One streaming (SAX) pass before the
// document is built refuses, naming the JSON path of the value
// ("objects[2].properties.temperature_K"):
//   - nesting deeper than max_json_depth arrays/objects (recursive code over
//     a 100,000-deep document would exhaust the stack);
//   - a key given twice in one object (JSON leaves it undefined);
//   - numbers beyond the range of a double (1e999);
//   - where the text stops being JSON: truncation, a bare NaN or Infinity
//     (what Python's json.dump writes), garbage.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "core/error.hpp"

namespace eoir::universe {

// Every engine file nests at most 8 levels; composites at most 8 parts deep.
constexpr std::size_t max_json_depth = 64;

// The document of `text`; throws eoir::Error(status) "ORIGIN: PATH: why"
// (ORIGIN names the file, e.g. "file 'a.scd'").
nlohmann::json parse_json_document(const std::string& text, const std::string& origin,
                                   Status status = Status::corrupt_file);

}  // namespace eoir::universe
