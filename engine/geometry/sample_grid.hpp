// The scene generator's angular sample grid (spec 4.1.3, 5.2): samples_per_pixel
// samples per pixel in each direction (the spec's 4) on a uniform focal-plane
// grid, mapped to directions by the arctangent of eqs. 15-16, plus a guard
// band of samples beyond the field of view so that the PSF convolution of an
// extended source has real scene on both sides of the field edge (no edge
// fall-off, unlike spec 7.2.2). The sensor model defines the grid; the scene
// generator fills it.
//
// Image orientation: images are stored as seen by an observer at the sensor
// looking along the line of sight (body +z) with body +y up, row 0 at the
// top. In the right-handed body frame body +x then points to the LEFT of the
// picture: column c grows toward body -x, row r toward body -y. The
// focal-plane inversion of eqs. 15-16 (alpha = -arctan(x'/f)) is undone:
// a sample's direction is normalise(tan_x, tan_y, 1) with tan_x falling with
// c and tan_y falling with r. (With north up, east is on the left, as on any
// picture of the sky.)
#pragma once
#include <Eigen/Core>
#include <cstdint>

namespace eoir::geometry {

struct SampleGrid {
  std::int64_t pixels_x = 0, pixels_y = 0;  // sensor pixels
  std::int64_t guard_pixels = 0;            // guard band on each side, in pixels
  std::int64_t per_pixel = 4;               // samples per pixel along each axis
  double pitch_x_cm = 0, pitch_y_cm = 0, focal_length_cm = 0;

  std::int64_t width() const { return (pixels_x + 2 * guard_pixels) * per_pixel; }   // samples
  std::int64_t height() const { return (pixels_y + 2 * guard_pixels) * per_pixel; }  // samples
  std::int64_t guard_samples() const { return guard_pixels * per_pixel; }
  std::int64_t field_width() const { return pixels_x * per_pixel; }   // samples inside the field
  std::int64_t field_height() const { return pixels_y * per_pixel; }
  // Tangents of the sample's direction (body x/z and y/z) for sample (c, r) of
  // the full grid including the guard band; fractional coordinates lie
  // within a sample's footprint (c +- 1/2, r +- 1/2).
  double tan_x(double c) const;
  double tan_y(double r) const;
  // Unit direction in the sensor body frame.
  Eigen::Vector3d direction_body(double c, double r) const;
  // The same from the tangents tan_x(c) and tan_y(r) (made once per column
  // and row where many samples are cast).
  static Eigen::Vector3d direction_of_tangents(double tan_x, double tan_y) {
    return Eigen::Vector3d(tan_x, tan_y, 1.0).normalized();
  }
  // Solid angle of one sample at (c, r) (sr), for display irradiance.
  double sample_solid_angle_sr(std::int64_t c, std::int64_t r) const;
  // The smallest angle between neighbouring samples (rad), on the axis.
  double sample_angle_rad() const;
  // Fractional sample coordinates (c, r) of a body direction; false if the
  // direction is behind the sensor.
  bool sample_of(const Eigen::Vector3d& direction_body, double& c, double& r) const;
  // Pixel coordinates (0 = centre of pixel 0) of fractional sample coordinates.
  double pixel_x_of(double c) const;
  double pixel_y_of(double r) const;
  // True if the sample coordinates lie inside the field of view (the ideal
  // field stop of spec 5.2, 7.2.1), within `tolerance` samples.
  bool in_field(double c, double r, double tolerance = 0.0) const;
};

}  // namespace eoir::geometry
