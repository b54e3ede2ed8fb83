// Sensitivity and saturation reference pairs (spec 5.9-5.10, eqs. 43-46).
#pragma once
#include <string>
#include <vector>

#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

using universe::ApertureQuantity;
using universe::ReferencePair;
using universe::SensorParameters;

using universe::validate_reference_pairs;

// How the aperture-referred value scales with integration time between and
// beyond the pairs: NEI ~ 1/sqrt(t) (eqs. 43-44), SEI ~ 1/t (eqs. 45-46).
enum class TimeScaling { inverse_sqrt, inverse };

// Operating value at `integration_time_ms`: pairs are sorted by time (any
// input order), linearly interpolated between pairs and extrapolated with
// `scaling` below the first and above the last pair; one pair is eq. 44 / 46.
double interpolate_reference_pairs(std::vector<ReferencePair> pairs, double integration_time_ms,
                                   TimeScaling scaling);

// NEI at t (eqs. 43-44) and SEI at t (eqs. 45-46).
double operating_sensitivity(const std::vector<ReferencePair>& pairs, double integration_time_ms);
double operating_saturation(const std::vector<ReferencePair>& pairs, double integration_time_ms);

// Aperture-referred irradiance <-> radiance at the same number of electrons
// (spec 5.11.4-5.11.5: ne = NEI R_peak,E = NER R_peak,L), so
// NER = NEI R_peak,E / R_peak,L and the same for SEI/SER.
double radiance_from_irradiance(double irradiance_W_cm2, double peak_radiance_responsivity,
                                double peak_irradiance_responsivity);
double irradiance_from_radiance(double radiance_W_cm2_sr, double peak_radiance_responsivity,
                                double peak_irradiance_responsivity);

}  // namespace eoir::sensor
