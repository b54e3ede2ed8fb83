#include "sensor/sensor_parameters.hpp"

namespace eoir::sensor {

// Hufnagel OQF levels of spec 5.6.1.2 (Wrms in waves of lambda_diff). Data,
// not code: later product documentation lists 0.21 for "moderate" (ERRATA).
const std::vector<ImageQualityPreset>& image_quality_presets() {
  static const std::vector<ImageQualityPreset> presets{
      {"diffraction_limited", 0.0},
      {"negligible", 0.07},
      {"mild", 0.14},
      {"moderate", 0.28},
  };
  return presets;
}

}  // namespace eoir::sensor
