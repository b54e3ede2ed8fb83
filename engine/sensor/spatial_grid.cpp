#include "sensor/spatial_grid.hpp"

#include <cmath>

namespace eoir::sensor {

double pixel_pitch_from_fov_cm(double fov_rad, std::int64_t pixels, double focal_length_cm) {
  return 2.0 * focal_length_cm * std::tan(0.5 * fov_rad) / static_cast<double>(pixels);
}

double fov_from_pixel_pitch_rad(double pitch_cm, std::int64_t pixels, double focal_length_cm) {
  return 2.0 * std::atan(static_cast<double>(pixels) * pitch_cm / (2.0 * focal_length_cm));
}

double ifov_rad(double pitch_cm, double focal_length_cm) {
  return 2.0 * std::atan(pitch_cm / (2.0 * focal_length_cm));
}

double sample_interval_cm(double pitch_cm) { return pitch_cm / samples_per_pixel; }

double focal_plane_to_angle_rad(double x_cm, double focal_length_cm) {
  return -std::atan(x_cm / focal_length_cm);
}

double angle_to_focal_plane_cm(double angle_rad, double focal_length_cm) {
  return -focal_length_cm * std::tan(angle_rad);
}

double AxisGrid::sample_position_cm(std::int64_t i) const {
  return (static_cast<double>(i) + 0.5) * sample_interval_cm() - 0.5 * static_cast<double>(pixels) * pitch_cm;
}

double AxisGrid::pixel_centre_cm(std::int64_t m) const {
  return (static_cast<double>(m) + 0.5 - 0.5 * static_cast<double>(pixels)) * pitch_cm;
}

double AxisGrid::sample_angle_rad(std::int64_t i) const {
  return focal_plane_to_angle_rad(sample_position_cm(i), focal_length_cm);
}

}  // namespace eoir::sensor
