#include "sensor/reference_pairs.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace eoir::sensor {

double interpolate_reference_pairs(std::vector<ReferencePair> pairs, double integration_time_ms,
                                   TimeScaling scaling) {
  std::sort(pairs.begin(), pairs.end(), [](const ReferencePair& a, const ReferencePair& b) {
    return a.integration_time_ms < b.integration_time_ms;
  });
  // Extrapolation from reference time t_ref to t: 1/sqrt(t) (eqs. 43-44) or 1/t (eqs. 45-46).
  auto scale = [&](const ReferencePair& ref) {
    const double ratio = ref.integration_time_ms / integration_time_ms;
    return ref.value * (scaling == TimeScaling::inverse_sqrt ? std::sqrt(ratio) : ratio);
  };
  if (integration_time_ms <= pairs.front().integration_time_ms) return scale(pairs.front());
  if (integration_time_ms >= pairs.back().integration_time_ms) return scale(pairs.back());
  // t_{k-1} < t <= t_k: linear interpolation (middle rows of eqs. 43 and 45).
  std::size_t k = 1;
  while (pairs[k].integration_time_ms < integration_time_ms) ++k;
  const ReferencePair& a = pairs[k - 1];
  const ReferencePair& b = pairs[k];
  return (b.value - a.value) * (integration_time_ms - a.integration_time_ms) /
             (b.integration_time_ms - a.integration_time_ms) +
         a.value;
}

double operating_sensitivity(const std::vector<ReferencePair>& pairs, double integration_time_ms) {
  return interpolate_reference_pairs(pairs, integration_time_ms, TimeScaling::inverse_sqrt);
}

double operating_saturation(const std::vector<ReferencePair>& pairs, double integration_time_ms) {
  return interpolate_reference_pairs(pairs, integration_time_ms, TimeScaling::inverse);
}

double radiance_from_irradiance(double irradiance_W_cm2, double peak_radiance_responsivity,
                                double peak_irradiance_responsivity) {
  return irradiance_W_cm2 * peak_irradiance_responsivity / peak_radiance_responsivity;
}

double irradiance_from_radiance(double radiance_W_cm2_sr, double peak_radiance_responsivity,
                                double peak_irradiance_responsivity) {
  return radiance_W_cm2_sr * peak_radiance_responsivity / peak_irradiance_responsivity;
}

}  // namespace eoir::sensor
