// Display images (spec 4.1.2): values compressed to 0-255 by automatic gain
// control (the least and greatest values to 0 and 255) or, without it, by a
// gain selected in steps of a factor 30 that maps `full_scale` * 30^-step to
// 255 and clips.
#pragma once
#include <cstdint>
#include <vector>

#include "radiometry/radiance_image.hpp"

namespace eoir::sensor {

// threads: 0 = all cores (the result does not depend on it). `storage`: a
// buffer to reuse for the result (its contents are overwritten).
std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, bool agc, std::int64_t gain_step,
                                               double full_scale, unsigned threads = 0,
                                               std::vector<std::uint8_t> storage = {});

// The scene generator's view: the irradiance of each sample of the field of
// view at the aperture (L dOmega), point sources added to their nearest
// sample; one byte per sample, full scale 1e-6 W/cm^2.
std::vector<std::uint8_t> scene_display(const radiometry::RadianceImage& scene, bool agc, std::int64_t gain_step,
                                        unsigned threads = 0, std::vector<std::uint8_t> storage = {});

}  // namespace eoir::sensor
