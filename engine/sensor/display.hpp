// Display images (spec 4.1.2; issue 21 item 6): values mapped to 0-255
// through a range [lo, hi] and a stretch. The range is the least and
// greatest value by automatic gain control, or, without it, [0, full_scale *
// 30^-step] (a gain selected in steps of a factor 30); the zscale stretch
// takes IRAF's automatic limits instead. With u = (v - lo) / (hi - lo)
// clipped to [0, 1], a byte is round(255 s(u)) with s:
//   linear  u
//   log     log(1 + a u) / log(1 + a), a = 1000
//   asinh   asinh(u / b) / asinh(1 / b), b = 0.1
//   zscale  u between zscale's limits (IRAF display.zscale: a line fitted to
//           1000 sorted samples with 2.5-sigma rejection, slope / 0.25 about
//           the median; astropy.visualization.ZScaleInterval's defaults)
// (a and b are the defaults of astropy.visualization's LogStretch and
// AsinhStretch). A value at or above `saturation` shows white (255), whatever
// the stretch. An image with lo = hi (and nothing saturated) is mid-grey, or
// black if it is zero.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "radiometry/radiance_image.hpp"
#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

using universe::DisplayStretch;

struct DisplayOptions {
  bool agc = true;
  std::int64_t gain_step = 0;
  double full_scale = 1.0;  // without AGC, the value step 0 maps to 255
  DisplayStretch stretch = DisplayStretch::linear;
  double saturation = HUGE_VAL;  // values at or above it show white
};

// The zscale limits of `values` (non-finite values skipped): lo, hi.
void zscale_limits(const std::vector<double>& values, double& lo, double& hi);

// threads: 0 = all cores (the result does not depend on it). `storage`: a
// buffer to reuse for the result (its contents are overwritten).
std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, const DisplayOptions& options,
                                               unsigned threads = 0, std::vector<std::uint8_t> storage = {});

// The scene generator's view: the irradiance of each sample of the field of
// view at the aperture (L dOmega), point sources added to their nearest
// sample; one byte per sample, full scale 1e-6 W/cm^2, nothing saturated
// (options.full_scale and options.saturation are not used).
std::vector<std::uint8_t> scene_display(const radiometry::RadianceImage& scene, const DisplayOptions& options,
                                        unsigned threads = 0, std::vector<std::uint8_t> storage = {});

}  // namespace eoir::sensor
