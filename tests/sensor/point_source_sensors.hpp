// The sensors on which the point-source model is tested and benchmarked
// (spec 5.11.2): spec 7.6 Table 3 (11.45 lambda F# pixels, under-sampled),
// the same with jitter and defocus, and diffraction-limited ones sampled at
// a given fraction of lambda F#.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sensor/point_source_model.hpp"
#include "sensor/point_source_render.hpp"
#include "sensor/sensor_model.hpp"
#include "sensor/system_psf.hpp"

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

// A 64 x 64 wide-field sensor of Table 3's optics over fov_deg, noise off
// (137 to 9,100 lambda F# pixels at 3 to 120 deg).
inline SensorParameters wide(double fov_deg) {
  SensorParameters p;
  p.horizontal_pixels = p.vertical_pixels = 64;
  p.horizontal_fov_deg = p.vertical_fov_deg = fov_deg;
  p.noise_enabled = false;
  return p;
}

// The same field on an LWIR fence camera: f = 2 cm, F/2, 8-12 um, 10 um
// diffraction wavelength (lambda F# = 20 um): 0.82, 2.8, 18, 54 and 3,581
// lambda F# pixels at 3, 10, 60, 120, 179 deg.
inline SensorParameters fence(double fov_deg) {
  SensorParameters p = wide(fov_deg);
  p.focal_length_cm = 2.0;
  p.f_number = 2.0;
  p.band_low_um = 8.0;
  p.band_high_um = 12.0;
  p.diffraction_wavelength_um = 10.0;
  return p;
}

// Renders one unit source at pixel (W + H, W + H) + phi into a 3W x 3W image
// (W = 2H + 1, H the model's window_half): the exact path's window about
// its nearest pixel, with a margin of W where the multilevel tail's coarse
// grids may spill.
inline std::vector<double> render_one(const PointSourceModel& m, double phi_x, double phi_y) {
  const std::int64_t h = m.window_half, w = 2 * h + 1, side = 3 * w;
  std::vector<double> image(static_cast<std::size_t>(side * side), 0.0);
  PointSourceSignal s;
  s.x_px = static_cast<double>(w + h) + phi_x;
  s.y_px = static_cast<double>(w + h) + phi_y;
  s.electrons = 1.0;
  render_point_sources(m, {s}, side, side, image);
  return image;
}

// render_one's image against the exact path's window at the same offset
// (exact.at(-dx, -dy): as the image chain, columns grow toward -x', rows
// toward -y'; 0 outside the window): the largest |image - exact| of any
// pixel, and the image's total.
struct AgainstExact {
  double worst_pixel = 0, total = 0;
};
inline AgainstExact against_exact(const std::vector<double>& image, const FocalPlaneSamples& exact, std::int64_t h) {
  const std::int64_t w = 2 * h + 1, side = 3 * w;
  AgainstExact out;
  for (std::int64_t y = 0; y < side; ++y)
    for (std::int64_t x = 0; x < side; ++x) {
      const std::int64_t dx = x - w - h, dy = y - w - h;
      const double v = image[static_cast<std::size_t>(y * side + x)];
      const double e = std::abs(dx) <= h && std::abs(dy) <= h ? exact.at(-dx, -dy) : 0.0;
      out.total += v;
      out.worst_pixel = std::max(out.worst_pixel, std::abs(v - e));
    }
  return out;
}

// The sensor's model with the tail forced to `tail`.
inline PointSourceModel model_with(const SensorParameters& p, eoir::PointTail tail) {
  const auto sensor = resolve_sensor(p);
  eoir::Fidelity f = p.fidelity;
  f.point_tail = tail;
  return build_point_source_model(sensor->optics, sensor->grid, f);
}

}  // namespace eoir::sensor::testing
