// Point sources added to a pixel image (spec 5.11.2, eqs. 50-51) through the
// point-source model (point_source_model.hpp), streaks included: a source
// moving during the integration spreads its energy uniformly along its
// segment, summed over sub-steps at the segment's midpoints (at least
// streak_steps_per_pixel per pixel and streak_steps_per_lambda_f per
// lambda F# of displacement: the pixel-integrated PSF is band-limited at
// 1 / lambda F#, so such a sum is its integral along the segment up to the
// segment's ends). Whatever falls outside the image is lost.
#pragma once
#include <cstdint>
#include <vector>

#include "sensor/point_source_model.hpp"

namespace eoir::sensor {

struct PointSourceSignal {
  double x_px = 0, y_px = 0;                // pixel coordinates (0 = centre of pixel 0) of the middle of the streak
  double streak_x_px = 0, streak_y_px = 0;  // displacement during the integration (end - start), pixels
  double electrons = 0;                     // R_peak,E E^ps / ENSQ (eq. 50), spread by EOD over the pixels
};

// Adds sum over sources of electrons * EOD(pixel) to `image` (width x height,
// row-major). Returns the tail method used: the model's, automatic resolved
// for this frame (direct unless it costs over 2^25 multiply-adds and the
// multilevel tail over 4 times fewer), direct when the model has no tail.
PointTail render_point_sources(const PointSourceModel& model, const std::vector<PointSourceSignal>& sources,
                               std::int64_t width, std::int64_t height, std::vector<double>& image);

// Sub-steps of one source's streak (1 at rest).
std::int64_t streak_steps(const PointSourceModel& model, const PointSourceSignal& source);

}  // namespace eoir::sensor
