#include "geometry/sample_grid.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::geometry {

double SampleGrid::tan_x(double c) const {
  const double x_cm = (0.5 * static_cast<double>(width()) - c - 0.5) * pitch_x_cm /
                      static_cast<double>(per_pixel);
  return x_cm / focal_length_cm;
}

double SampleGrid::tan_y(double r) const {
  const double y_cm = (0.5 * static_cast<double>(height()) - r - 0.5) * pitch_y_cm /
                      static_cast<double>(per_pixel);
  return y_cm / focal_length_cm;
}

Eigen::Vector3d SampleGrid::direction_body(double c, double r) const {
  return direction_of_tangents(tan_x(c), tan_y(r));
}

double SampleGrid::sample_solid_angle_sr(std::int64_t c, std::int64_t r) const {
  // Pinhole projection: dOmega = dA' cos^3(theta) / f^2.
  const double tx = tan_x(c), ty = tan_y(r);
  const double cos_theta = 1.0 / std::sqrt(1.0 + tx * tx + ty * ty);
  const double k = static_cast<double>(per_pixel);
  const double d_area = (pitch_x_cm / k) * (pitch_y_cm / k);
  return d_area * cos_theta * cos_theta * cos_theta / (focal_length_cm * focal_length_cm);
}

double SampleGrid::sample_angle_rad() const {
  return std::min(pitch_x_cm, pitch_y_cm) / static_cast<double>(per_pixel) / focal_length_cm;
}

bool SampleGrid::sample_of(const Eigen::Vector3d& d, double& c, double& r) const {
  if (!(d.z() > 0)) return false;
  const double k = static_cast<double>(per_pixel);
  const double x_cm = d.x() / d.z() * focal_length_cm, y_cm = d.y() / d.z() * focal_length_cm;
  c = 0.5 * static_cast<double>(width()) - 0.5 - x_cm / (pitch_x_cm / k);
  r = 0.5 * static_cast<double>(height()) - 0.5 - y_cm / (pitch_y_cm / k);
  return true;
}

double SampleGrid::pixel_x_of(double c) const {
  return (c - static_cast<double>(guard_samples()) + 0.5) / static_cast<double>(per_pixel) - 0.5;
}

double SampleGrid::pixel_y_of(double r) const {
  return (r - static_cast<double>(guard_samples()) + 0.5) / static_cast<double>(per_pixel) - 0.5;
}

bool SampleGrid::in_field(double c, double r, double tolerance) const {
  const double g = static_cast<double>(guard_samples());
  return c >= g - 0.5 - tolerance && c <= g + static_cast<double>(field_width()) - 0.5 + tolerance &&
         r >= g - 0.5 - tolerance && r <= g + static_cast<double>(field_height()) - 0.5 + tolerance;
}

}  // namespace eoir::geometry
