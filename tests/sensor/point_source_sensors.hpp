// The sensors on which the point-source model is tested and benchmarked
// (spec 5.11.2): spec 7.6 Table 3 (11.45 lambda F# pixels, under-sampled),
// the same with jitter and defocus, and diffraction-limited ones sampled at
// a given fraction of lambda F#.
#pragma once
#include <cmath>

#include "sensor/point_source_model.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::sensor::testing {

inline SensorParameters table3() { return SensorParameters{}; }  // the defaults

// Table 3 with line-of-sight jitter (sigma f = 0.15 pixel) and 0.6 mm of
// defocus: 2.4 waves peak to peak, past the 2.2-wave switch, so eq. 37's
// sharp-edged blur disk (0.17 mm = 1.7 pixels across).
inline SensorParameters jitter_defocus() {
  SensorParameters p;
  p.jitter_mrad = 0.01;
  p.defocus_mm = 0.6;
  return p;
}

// Diffraction limited (Table 3's optics), pixel = `pixel_in_lambda_f`
// lambda F#, `pixels` x `pixels`.
inline SensorParameters sampled(double pixel_in_lambda_f, int pixels) {
  SensorParameters p;
  p.horizontal_pixels = p.vertical_pixels = pixels;
  const double pitch_cm = pixel_in_lambda_f * p.diffraction_wavelength_um * 1e-4 * p.f_number;
  p.horizontal_fov_deg = p.vertical_fov_deg =
      2.0 * std::atan(0.5 * pixels * pitch_cm / p.focal_length_cm) * 180.0 / M_PI;
  return p;
}

// Nyquist sampling (pixel = lambda F# / 2), 256 x 256: the point window
// reaches the 255-pixel cap of psf_grid_size 512.
inline SensorParameters nyquist() { return sampled(0.5, 256); }

// Over-sampled (pixel = lambda F# / 4), 128 x 128: the window is the array.
inline SensorParameters oversampled() { return sampled(0.25, 128); }

// The sensor's model with the tail forced to `tail`.
inline PointSourceModel model_with(const SensorParameters& p, eoir::PointTail tail) {
  const auto sensor = resolve_sensor(p);
  eoir::Fidelity f = p.fidelity;
  f.point_tail = tail;
  return build_point_source_model(sensor->optics, sensor->grid, f);
}

}  // namespace eoir::sensor::testing
