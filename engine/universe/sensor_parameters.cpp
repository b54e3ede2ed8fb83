#include "universe/sensor_parameters.hpp"

#include <sstream>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "universe/sensor_properties.hpp"

namespace eoir::universe {

// Hufnagel OQF levels of spec 5.6.1.2 (Wrms in waves of lambda_diff).
const std::vector<ImageQualityPreset>& image_quality_presets() {
  static const std::vector<ImageQualityPreset> presets{
      {"diffraction_limited", 0.0},
      {"negligible", 0.07},
      {"mild", 0.14},
      {"moderate", 0.28},
  };
  return presets;
}

const std::vector<std::string>& image_quality_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& p : image_quality_presets()) n.push_back(p.name);
    n.push_back("custom");
    return n;
  }();
  return names;
}

void validate_reference_pairs(const std::vector<ReferencePair>& pairs, const std::string& field) {
  if (pairs.empty()) throw Error(Status::out_of_range, field + ": at least one reference pair is required");
  if (pairs.size() > limits::max_reference_pairs)
    throw Error(Status::limit_exceeded, field + ": at most " + std::to_string(limits::max_reference_pairs) +
                                            " reference pairs, got " + std::to_string(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string item = field + "[" + std::to_string(i) + "]";
    require_positive(pairs[i].integration_time_ms, item + ".integration_time_ms");
    require_positive(pairs[i].value, item + ".value");
    for (std::size_t j = 0; j < i; ++j)
      if (pairs[j].integration_time_ms == pairs[i].integration_time_ms)
        throw Error(Status::out_of_range, item + ".integration_time_ms: repeats the time of " + field + "[" +
                                              std::to_string(j) + "]");
  }
}

void validate(const SensorParameters& p) {
  // Each property's own check (range, choices, pairs) on the current value;
  // the saturation pairs only matter with saturation on (spec 5.11.5).
  SensorParameters copy = p;
  for (const auto& spec : sensor_properties())
    if (p.saturation_enabled || std::string(spec.name) != "saturation_pairs") spec.set(copy, spec.get(p));
  if (!(p.band_high_um > p.band_low_um)) {
    std::ostringstream s;
    s << "band_high_um: must be greater than band_low_um (" << p.band_high_um << " <= " << p.band_low_um << ")";
    throw Error(Status::out_of_range, s.str());
  }
}

}  // namespace eoir::universe
