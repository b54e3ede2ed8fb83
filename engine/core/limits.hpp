// Compile-time limits of the modeled universe (spec 3.1, 4.3.3-4.3.6); the C
// header repeats them as EOIR_MAX_*.
#pragma once
#include <cstddef>

namespace eoir::limits {
constexpr std::size_t max_satellites = 16;
constexpr std::size_t max_vehicles = 6;  // aircraft plus ground vehicles
constexpr std::size_t max_sites = 16;    // ground sites carrying sensors (not vehicles)
constexpr std::size_t max_missiles = 6;
constexpr std::size_t max_missile_stages = 18;
constexpr std::size_t max_sensors = 6;
constexpr std::size_t max_reference_pairs = 8;
constexpr std::size_t max_name_length = 63;
}  // namespace eoir::limits
