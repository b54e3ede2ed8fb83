#include "sensor/detector_mtf.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace eoir::sensor {

double detector_footprint_mtf(double frequency_cycles_per_cm, double pitch_cm) {
  const double x = constants::pi * frequency_cycles_per_cm * pitch_cm;
  if (std::abs(x) < 1.0e-8) return 1.0;
  return std::abs(std::sin(x) / x);
}

double detector_footprint_mtf_object(double frequency_cycles_per_mrad, double pitch_cm, double focal_length_cm) {
  return detector_footprint_mtf(frequency_cycles_per_mrad * 1000.0 / focal_length_cm, pitch_cm);
}

}  // namespace eoir::sensor
