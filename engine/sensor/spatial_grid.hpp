// Field of view and spatial sampling grid of the focal plane (spec 5.2).
// Lengths in the focal plane are in cm, angles in radians unless a name says
// otherwise.
#pragma once
#include <cstdint>

namespace eoir::sensor {

// Pixel pitch from the full-angle FOV: eqs. 21-22 inverted,
// p = 2 f tan(FOV / 2) / N.
double pixel_pitch_from_fov_cm(double fov_rad, std::int64_t pixels, double focal_length_cm);

// Full-angle FOV from the pitch: eqs. 21-22, FOV = 2 arctan(N p / (2 f)).
double fov_from_pixel_pitch_rad(double pitch_cm, std::int64_t pixels, double focal_length_cm);

// On-axis IFOV: eqs. 23-24, IFOV = 2 arctan(p / (2 f)).
double ifov_rad(double pitch_cm, double focal_length_cm);

// Focal-plane sample interval: eqs. 13-14, four samples per pixel.
constexpr int samples_per_pixel = 4;
double sample_interval_cm(double pitch_cm);

// Focal plane -> object space: eqs. 15-16, alpha = -arctan(x' / f).
double focal_plane_to_angle_rad(double x_cm, double focal_length_cm);
// Object space -> focal plane, the inverse of eqs. 15-16: x' = -f tan(alpha).
double angle_to_focal_plane_cm(double angle_rad, double focal_length_cm);

// The uniform focal-plane sampling grid of one axis (eqs. 13-16): N pixels of
// pitch p centred on the optical axis, 4 samples per pixel at cell centres.
struct AxisGrid {
  std::int64_t pixels = 0;
  double pitch_cm = 0;
  double focal_length_cm = 0;

  std::int64_t samples() const { return pixels * samples_per_pixel; }
  double sample_interval_cm() const { return pitch_cm / samples_per_pixel; }
  // Focal-plane coordinate of the centre of sample i (0 <= i < samples()).
  double sample_position_cm(std::int64_t i) const;
  // Focal-plane coordinate of the centre of pixel m (0 <= m < pixels).
  double pixel_centre_cm(std::int64_t m) const;
  // Object-space angle of sample i through eq. 15 (or 16).
  double sample_angle_rad(std::int64_t i) const;
};

}  // namespace eoir::sensor
