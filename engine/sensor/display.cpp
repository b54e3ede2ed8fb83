#include "sensor/display.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::sensor {

std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, bool agc, std::int64_t gain_step,
                                               double full_scale) {
  std::vector<std::uint8_t> out(values.size(), 0);
  if (values.empty()) return out;
  double lo = 0, scale = 0;
  if (agc) {
    const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
    lo = *mn;
    // A constant image shows mid-grey rather than dividing by zero (the
    // "strange effects" of AGC on low-contrast scenes, spec 4.1.2).
    scale = *mx > *mn ? 255.0 / (*mx - *mn) : 0.0;
    if (scale == 0.0) {
      std::fill(out.begin(), out.end(), static_cast<std::uint8_t>(*mx > 0 ? 128 : 0));
      return out;
    }
  } else {
    scale = 255.0 * std::pow(30.0, static_cast<double>(gain_step)) / full_scale;
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = std::round((values[i] - lo) * scale);
    out[i] = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
  }
  return out;
}

}  // namespace eoir::sensor
