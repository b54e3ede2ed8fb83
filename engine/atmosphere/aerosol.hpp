// The aerosol's extinction at 0.55 um against altitude (Shettle and Fenn
// 1979 as LOWTRAN 7 arranges it, data/atmosphere/aerosol_profile_lowtran7.csv):
// the boundary layer (0-2 km) set by the meteorological visibility V, its
// ground value 3.912 / V less the molecules' 0.0116 km^-1 (Koschmieder), the
// profiles between the tabulated visibilities interpolated in 1 / V; above
// it the tropospheric background (2-10 km), the stratospheric background
// (10-30 km) and the upper atmosphere (30-100 km), spring-summer.
#pragma once
#include <string>
#include <vector>

#include "universe/atmosphere_settings.hpp"

namespace eoir::atmosphere {

// Molecular (Rayleigh) extinction at 0.55 um at sea level that the
// visibility's Koschmieder extinction includes (LOWTRAN 7).
constexpr double kRayleighExtinction550_per_km = 0.0116;

class AerosolProfile {
 public:
  // Throws io or corrupt_file naming the file and line; aerosol none gives 0.
  static AerosolProfile make(const universe::AtmosphereSettings& settings, const std::string& data_dir);
  double extinction_550_per_m(double altitude_m) const;

 private:
  std::vector<double> altitude_m_, extinction_per_m_;  // piecewise linear
};

}  // namespace eoir::atmosphere
