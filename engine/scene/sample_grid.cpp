#include "scene/sample_grid.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::scene {

double SampleGrid::tan_x(std::int64_t c) const {
  const double x_cm = (0.5 * static_cast<double>(width()) - static_cast<double>(c) - 0.5) * pitch_x_cm / per_pixel;
  return x_cm / focal_length_cm;
}

double SampleGrid::tan_y(std::int64_t r) const {
  const double y_cm = (0.5 * static_cast<double>(height()) - static_cast<double>(r) - 0.5) * pitch_y_cm / per_pixel;
  return y_cm / focal_length_cm;
}

Eigen::Vector3d SampleGrid::direction_body(std::int64_t c, std::int64_t r) const {
  return Eigen::Vector3d(tan_x(c), tan_y(r), 1.0).normalized();
}

double SampleGrid::sample_solid_angle_sr(std::int64_t c, std::int64_t r) const {
  // Pinhole projection: dOmega = dA' cos^3(theta) / f^2.
  const double tx = tan_x(c), ty = tan_y(r);
  const double cos_theta = 1.0 / std::sqrt(1.0 + tx * tx + ty * ty);
  const double d_area = (pitch_x_cm / per_pixel) * (pitch_y_cm / per_pixel);
  return d_area * cos_theta * cos_theta * cos_theta / (focal_length_cm * focal_length_cm);
}

bool SampleGrid::sample_of(const Eigen::Vector3d& d, double& c, double& r) const {
  if (!(d.z() > 0)) return false;
  const double x_cm = d.x() / d.z() * focal_length_cm, y_cm = d.y() / d.z() * focal_length_cm;
  c = 0.5 * static_cast<double>(width()) - 0.5 - x_cm / (pitch_x_cm / per_pixel);
  r = 0.5 * static_cast<double>(height()) - 0.5 - y_cm / (pitch_y_cm / per_pixel);
  return true;
}

SampleGrid make_sample_grid(const sensor::SensorParameters& p, const sensor::StaticMetrics& m) {
  SampleGrid g;
  g.pixels_x = p.horizontal_pixels;
  g.pixels_y = p.vertical_pixels;
  g.pitch_x_cm = m.pixel_pitch_x_cm;
  g.pitch_y_cm = m.pixel_pitch_y_cm;
  g.focal_length_cm = p.focal_length_cm;
  // PSF reach in the focal plane: diffraction tail (20 lambda F# keeps the
  // energy beyond the guard below ~0.5 %), jitter (4 sigma) and the geometric
  // defocus blur diameter delta / F#.
  const double lambda_cm = p.diffraction_wavelength_um * 1e-4;
  const double reach_cm = 20.0 * lambda_cm * p.f_number + 4.0 * p.jitter_mrad * 1e-3 * p.focal_length_cm +
                          p.defocus_mm * 0.1 / p.f_number;
  const double pitch = std::min(g.pitch_x_cm, g.pitch_y_cm);
  const std::int64_t need = static_cast<std::int64_t>(std::ceil(reach_cm / pitch)) + 1;
  g.guard_pixels = std::clamp<std::int64_t>(need, 1, std::max<std::int64_t>(1, std::max(g.pixels_x, g.pixels_y)));
  return g;
}

}  // namespace eoir::scene
