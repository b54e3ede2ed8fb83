// Access intervals of a sampled constraint (spec 7.8): the times in
// [start, stop] where a predicate holds (e.g. SNR >= min_snr), found by
// stepping and refining each change of the predicate by bisection.
//
// Times are handled as whole milliseconds (the engine receives times as ISO
// strings with millisecond resolution, iso_time.hpp), so a refined boundary
// is the pair of adjacent milliseconds where the predicate changes: the
// crossing is known to within 1 ms (the tolerance), and every reported
// interval start/stop is an instant where the predicate was evaluated true.
// Intervals shorter than a step that start and end between two samples are
// not seen (as with any sampled access computation).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

namespace eoir::cli {

struct AccessInterval {
  int64_t start_ms = 0;  // first millisecond inside (predicate true)
  int64_t stop_ms = 0;   // last millisecond inside
};

struct AccessResult {
  std::vector<AccessInterval> intervals;
  std::size_t evaluations = 0;  // calls of the predicate
};

// Progress callback: (phase "sample" or "refine", done, total).
using AccessProgress = std::function<void(const char* phase, std::size_t done, std::size_t total)>;

// samples_ms: the step grid (ascending, start and stop included). The
// predicate is called with times in milliseconds (same origin as samples_ms).
AccessResult find_access(const std::vector<int64_t>& samples_ms, const std::function<bool(int64_t)>& inside,
                         const AccessProgress& progress = {});

}  // namespace eoir::cli
