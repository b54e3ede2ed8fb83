// Display compression to 0-255 (spec 4.1.2): automatic gain control maps the
// least and greatest values to 0 and 255; without it a gain selected in steps
// of a factor 30 maps `full_scale` * 30^-step to 255 and clips.
#pragma once
#include <cstdint>
#include <vector>

namespace eoir::sensor {

std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, bool agc, std::int64_t gain_step,
                                               double full_scale);

}  // namespace eoir::sensor
