#include "universe/sensor_parameters.hpp"

#include <cmath>
#include <sstream>
#include <tuple>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/value.hpp"
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

const std::vector<std::string>& display_stretch_names() {
  static const std::vector<std::string> names{"linear", "log", "asinh", "zscale"};
  return names;
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
    check_range(pairs[i].integration_time_ms,
                Range{sensor_bounds::min_integration_time_ms, sensor_bounds::max_integration_time_ms},
                item + ".integration_time_ms", "ms");
    check_range(pairs[i].value, Range{sensor_bounds::min_reference_value, sensor_bounds::max_reference_value},
                item + ".value", "W/cm^2 or W/(cm^2 sr)");
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
  if (!(p.band_high_um > p.band_low_um))
    throw Error(Status::out_of_range, "band_high_um: must be greater than band_low_um (" +
                                          number_text(p.band_high_um) + " <= " + number_text(p.band_low_um) + ")");
  // The pixel pitch (eqs. 21-22) against the diffraction width lambda_diff F#.
  const double width_cm = p.diffraction_wavelength_um * 1.0e-4 * p.f_number;
  for (const auto& [fov_deg, pixels, axis] :
       {std::tuple{p.horizontal_fov_deg, p.horizontal_pixels, "horizontal"},
        std::tuple{p.vertical_fov_deg, p.vertical_pixels, "vertical"}}) {
    const double pitch_cm = 2.0 * p.focal_length_cm * std::tan(0.5 * fov_deg * constants::rad_per_deg) /
                            static_cast<double>(pixels);
    const double widths = pitch_cm / width_cm;
    if (widths > sensor_bounds::max_pitch_diffraction_widths) {
      std::ostringstream s;
      s << axis << "_fov_deg, " << axis << "_pixels, focal_length_cm: the pixel pitch (" << pitch_cm << " cm) spans "
        << widths << " diffraction widths lambda_diff F# (" << width_cm << " cm), at most "
        << sensor_bounds::max_pitch_diffraction_widths
        << " (the energy on detector, eq. 40, would take too long): use more pixels, a narrower field, a shorter "
           "focal length or a larger f_number or diffraction_wavelength_um";
      throw Error(Status::out_of_range, s.str());
    }
  }
}

}  // namespace eoir::universe
