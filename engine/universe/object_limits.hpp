// The object limits of one engine, set at run time (README "Object limits"):
// the spec's counts (spec 3.1, core/limits.hpp) are the default profile;
// each may be raised up to its ceiling, or lowered to what the universe holds.
#pragma once
#include <cstddef>

#include "core/limits.hpp"

namespace eoir::universe {

struct ObjectLimits {
  std::size_t satellites = limits::max_satellites;
  std::size_t vehicles = limits::max_vehicles;  // aircraft plus ground vehicles
  std::size_t sites = limits::max_sites;
  std::size_t missiles = limits::max_missiles;
  std::size_t sensors = limits::max_sensors;

  bool is_default() const;
};

// The highest value each limit takes (eoir.h EOIR_CEILING_*).
namespace ceilings {
constexpr std::size_t satellites = 100000;
constexpr std::size_t vehicles = 10000;
constexpr std::size_t sites = 10000;
constexpr std::size_t missiles = 10000;
constexpr std::size_t sensors = 256;
}  // namespace ceilings

// Throws Error(out_of_range) naming the field ("max_satellites: 0 outside
// [1, 100000]") unless every limit is in [1, its ceiling].
void check_limits(const ObjectLimits& limits);

}  // namespace eoir::universe
