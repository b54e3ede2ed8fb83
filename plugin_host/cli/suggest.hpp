// "Did you mean" for unknown names (commands, options, providers, sensors,
// objects, properties): the closest known name by edit distance.
#pragma once
#include <string>
#include <vector>

namespace eoir::cli {

// Levenshtein distance, case-insensitive (a case difference costs 0).
std::size_t edit_distance(const std::string& a, const std::string& b);
// The candidate closest to `name` if it is close enough (at most 2 edits, or
// a third of the name's length for long names), else "".
std::string closest_name(const std::string& name, const std::vector<std::string>& candidates);
// " (did you mean 'X'?)" or "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace eoir::cli
