// Streaks (spec 5.11.2 with a source moving during the integration time): the
// energy of eq. 50 spread uniformly along the segment the source covers
// (sensor/point_source_render.hpp).
//
//  - Energy: a streak inside the array holds what the same source at rest
//    holds, within 0.1 %.
//  - Length: the image of a uniform segment convolved with the
//    pixel-integrated PSF has, about the segment's middle, the second moment
//    L^2 / 12 plus the rest image's moments averaged along the segment
//    (variances add under convolution; pixels coarser than lambda F# bias a
//    rest image's centroid toward its pixel's centre, which the first-moment
//    term carries). The length so measured along x and along y equals the
//    displacement within 0.05 pixel.
//  - Leaving the array: for a point-symmetric PSF the part of a long uniform
//    segment beyond a straight array edge takes exactly its share of the
//    energy out (what spills in and out across the edge cancels; with
//    sub-steps finer than lambda F# the sum over them does too, the
//    pixel-integrated PSF being band-limited): the image holds (length
//    inside / length) of the source's energy, within 1e-4.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "point_source_sensors.hpp"
#include "sensor/point_source_render.hpp"

using namespace eoir::sensor;
using namespace eoir::sensor::testing;

namespace {

constexpr std::int64_t kSide = 256;  // image pixels; the sources sit well inside unless a test says otherwise

std::vector<double> render(const PointSourceModel& m, const PointSourceSignal& s) {
  std::vector<double> image(static_cast<std::size_t>(kSide * kSide), 0.0);
  render_point_sources(m, {s}, kSide, kSide, image);
  return image;
}

double total(const std::vector<double>& image) {
  double t = 0;
  for (double v : image) t += v;
  return t;
}

// The image's moment of order k of the column (axis 0) or row (axis 1)
// coordinate about `about`, per unit energy.
double moment(const std::vector<double>& image, int axis, double about, int k) {
  double s0 = 0, sk = 0;
  for (std::int64_t y = 0; y < kSide; ++y)
    for (std::int64_t x = 0; x < kSide; ++x) {
      const double v = image[static_cast<std::size_t>(y * kSide + x)];
      const double c = static_cast<double>(axis == 0 ? x : y) - about;
      s0 += v;
      sk += v * (k == 1 ? c : c * c);
    }
  return sk / s0;
}

const std::vector<eoir::PointTail> both{eoir::PointTail::direct, eoir::PointTail::multilevel};

}  // namespace

TEST(Spec_5_11_2_Streak, EnergyEqualsSourceAtRest) {
  for (const SensorParameters& p : {table3(), jitter_defocus()})
    for (eoir::PointTail tail : both) {
      const PointSourceModel m = model_with(p, tail);
      PointSourceSignal rest;
      rest.x_px = 127.3;
      rest.y_px = 121.8;
      rest.electrons = 1000.0;
      PointSourceSignal streak = rest;
      streak.streak_x_px = 25.4;
      streak.streak_y_px = -13.7;
      ASSERT_GT(streak_steps(m, streak), 25 * 11);  // at least 1 per lambda F# (11.45 per pixel)
      EXPECT_NEAR(total(render(m, streak)) / total(render(m, rest)), 1.0, 1e-3);
    }
}

TEST(Spec_5_11_2_Streak, LengthEqualsDisplacement) {
  for (const SensorParameters& p : {table3(), jitter_defocus(), nyquist()})
    for (eoir::PointTail tail : both) {
      const PointSourceModel m = model_with(p, tail);
      const auto sensor = resolve_sensor(p);
      const double pixels_per_lambda_f =
          sensor->grid.pitch_x_cm / (sensor->optics.diffraction_wavelength_cm * sensor->optics.f_number);
      for (const auto& d : {std::pair<double, double>{18.6, -11.2}, {-12.0, 20.5}, {30.25, 0.0}}) {
        PointSourceSignal streak;
        streak.x_px = 128.3;
        streak.y_px = 128.6;
        streak.streak_x_px = d.first;
        streak.streak_y_px = d.second;
        streak.electrons = 1.0;
        const std::vector<double> image = render(m, streak);
        // The closed form by quadrature along the segment (4 points per
        // lambda F#, other points than the renderer's sub-steps): the rest
        // image at s has, about s, the second moment M2(s) and first moment
        // b(s) along each axis (b != 0 for pixels coarser than the optics
        // resolve). About the segment's middle x0 the streak then has
        //   V = <M2(s) + 2 (s - x0) b(s)> + <(s - x0)^2>, <(s - x0)^2> = L^2 / 12.
        const double length = std::hypot(d.first, d.second);
        const int points = static_cast<int>(std::ceil(length * std::max(8.0, 4.0 * pixels_per_lambda_f))) + 1;
        double expected_rest[2] = {0, 0};
        for (int q = 0; q < points; ++q) {
          const double t = (q + 0.5) / points - 0.5;
          PointSourceSignal rest = streak;
          rest.x_px += t * d.first;
          rest.y_px += t * d.second;
          rest.streak_x_px = rest.streak_y_px = 0;
          const std::vector<double> r = render(m, rest);
          for (int axis = 0; axis < 2; ++axis) {
            const double at = axis == 0 ? rest.x_px : rest.y_px, middle = axis == 0 ? streak.x_px : streak.y_px;
            expected_rest[axis] += (moment(r, axis, at, 2) + 2.0 * (at - middle) * moment(r, axis, at, 1)) / points;
          }
        }
        const double length_x = std::sqrt(12.0 * std::max(0.0, moment(image, 0, streak.x_px, 2) - expected_rest[0]));
        const double length_y = std::sqrt(12.0 * std::max(0.0, moment(image, 1, streak.y_px, 2) - expected_rest[1]));
        EXPECT_NEAR(length_x, std::abs(d.first), 0.05) << d.first << ", " << d.second;
        EXPECT_NEAR(length_y, std::abs(d.second), 0.05) << d.first << ", " << d.second;
      }
    }
}

TEST(Spec_5_11_2_Streak, LeavingTheArrayLosesThePartOutside) {
  for (const SensorParameters& p : {table3(), jitter_defocus()})
    for (eoir::PointTail tail : both) {
      const PointSourceModel m = model_with(p, tail);
      PointSourceSignal rest;
      rest.x_px = 128.0;
      rest.y_px = 128.0;
      rest.electrons = 1.0;
      const double whole = total(render(m, rest));
      // Across the left edge (x = -1/2): from x = -10.63 to 10.37, 10.87 of
      // 21 pixels inside.
      PointSourceSignal streak;
      streak.x_px = -0.13;
      streak.y_px = 128.2;
      streak.streak_x_px = 21.0;
      streak.electrons = 1.0;
      EXPECT_NEAR(total(render(m, streak)) / whole, 10.87 / 21.0, 1e-4);
      // Slanted across the bottom edge (y = 255.5), far from the corners:
      // from y = 235.4 to 275.4, (255.5 - 235.4) / 40 of it inside.
      streak.x_px = 100.7;
      streak.y_px = 255.4;
      streak.streak_x_px = -15.0;
      streak.streak_y_px = 40.0;
      EXPECT_NEAR(total(render(m, streak)) / whole, (255.5 - 235.4) / 40.0, 1e-4);
    }
}
