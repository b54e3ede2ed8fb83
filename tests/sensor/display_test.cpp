// Display images (spec 4.1.2): automatic gain control maps the least value to
// 0 and the greatest to 255 (linear between, rounded); without it the gain
// maps full_scale * 30^-step to 255 and clips; a constant image is mid-grey.
// The result is the same for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensor/display.hpp"

namespace s = eoir::sensor;

TEST(Display, AgcMapsTheRangeTo0Through255) {
  std::vector<double> v(100000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 3.0 + std::sin(0.001 * static_cast<double>(i)) * 2.0;
  v[77777] = 10.0;  // the greatest
  v[12] = -4.0;     // the least
  const auto one = s::compress_for_display(v, true, 0, 1.0, 1);
  const auto two = s::compress_for_display(v, true, 0, 1.0, 2);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one[77777], 255);
  EXPECT_EQ(one[12], 0);
  for (std::size_t i = 0; i < v.size(); i += 1009)
    EXPECT_EQ(one[i], static_cast<std::uint8_t>(std::lround((v[i] + 4.0) * 255.0 / 14.0))) << i;
}

// An odd count splits into unequal ranges: each range's least and greatest
// value must still reach the AGC (the greatest value in the first half, the
// least in the second: either alone would misplace 7.5, which maps to
// round(7.5 * 255 / 10) = 191).
TEST(Display, AgcSeesEveryRangeOfAnOddCount) {
  std::vector<double> v(8195);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = i < v.size() / 2 ? 5.0 + (i % 2) * 2.5 : 0.5 + 0.5 * (i % 2);
  v[10] = 10.0;
  v[v.size() - 1] = 0.0;
  for (unsigned threads : {1u, 2u, 3u}) {
    const auto b = s::compress_for_display(v, true, 0, 1.0, threads);
    EXPECT_EQ(b[10], 255) << threads;
    EXPECT_EQ(b[v.size() - 1], 0) << threads;
    EXPECT_EQ(b[1], 191) << threads;
  }
}

TEST(Display, FixedGainStepsOfThirtyAndClipping) {
  const std::vector<double> v{0.0, 0.5e-6, 1e-6, 2e-6, 1e-6 / 30.0};
  const auto step0 = s::compress_for_display(v, false, 0, 1e-6, 2);
  EXPECT_EQ(step0, (std::vector<std::uint8_t>{0, 128, 255, 255, 9}));
  const auto step1 = s::compress_for_display(v, false, 1, 1e-6, 2);
  EXPECT_EQ(step1[4], 255);  // full scale / 30 maps to 255 one step up
}

TEST(Display, ConstantImageIsMidGrey) {
  const std::vector<double> v(5000, 2.5);
  for (auto b : s::compress_for_display(v, true, 0, 1.0, 2)) ASSERT_EQ(b, 128);
  const std::vector<double> zero(5000, 0.0);
  for (auto b : s::compress_for_display(zero, true, 0, 1.0, 2)) ASSERT_EQ(b, 0);
}

// The scene view (spec 4.1.2): each field sample shows L dOmega
// (SampleGrid::sample_solid_angle_sr) plus the point sources nearest to it,
// compressed by AGC. Made in chunks on 1 and 2 threads, it equals the bytes
// of the whole irradiance image computed here; the field spans several
// chunks, two sources share a sample and one sits on a chunk's first sample.
TEST(Display, SceneViewIsSampleIrradiancePlusPointSources) {
  eoir::radiometry::RadianceImage scene;
  eoir::geometry::SampleGrid& g = scene.grid;
  g.pixels_x = 37;
  g.pixels_y = 29;
  g.per_pixel = 4;
  g.guard_pixels = 2;
  g.pitch_x_cm = g.pitch_y_cm = 1e-3;
  g.focal_length_cm = 2.0;
  const std::int64_t w = g.width(), h = g.height(), fw = g.field_width(), fh = g.field_height(), guard = g.guard_samples();
  ASSERT_GT(fw * fh, 3 * 4096);
  scene.radiance_W_cm2_sr.resize(static_cast<std::size_t>(w * h));
  for (std::size_t i = 0; i < scene.radiance_W_cm2_sr.size(); ++i)
    scene.radiance_W_cm2_sr[i] = 1e-3 * (1.0 + std::sin(0.37 * static_cast<double>(i)));
  const auto source = [&](std::int64_t c, std::int64_t r, double e) {
    eoir::radiometry::PointSource p;
    p.column = static_cast<double>(c + guard) + 0.2;
    p.row = static_cast<double>(r + guard) - 0.3;
    p.irradiance_W_cm2 = e;
    scene.point_sources.push_back(p);
  };
  source(5, 7, 2e-12);
  source(5, 7, 3e-12);                // the same sample
  source(4096 % fw, 4096 / fw, 1e-11);  // first sample of the second chunk
  source(fw - 1, fh - 1, 4e-12);       // the last sample
  std::vector<double> irradiance(static_cast<std::size_t>(fw * fh));
  for (std::int64_t r = 0; r < fh; ++r)
    for (std::int64_t c = 0; c < fw; ++c)
      irradiance[static_cast<std::size_t>(r * fw + c)] =
          scene.radiance_W_cm2_sr[static_cast<std::size_t>((r + guard) * w + c + guard)] *
          g.sample_solid_angle_sr(c + guard, r + guard);
  irradiance[static_cast<std::size_t>(7 * fw + 5)] += 5e-12;
  irradiance[4096] += 1e-11;
  irradiance.back() += 4e-12;
  const auto expected = s::compress_for_display(irradiance, true, 0, 1.0, 1);
  for (unsigned threads : {1u, 2u}) {
    const auto view = s::scene_display(scene, true, 0, threads);
    ASSERT_EQ(view.size(), expected.size());
    int off_by_one = 0;
    for (std::size_t i = 0; i < view.size(); ++i) {
      ASSERT_LE(std::abs(view[i] - expected[i]), 1) << i;  // dOmega's factors in another order may round a byte
      off_by_one += view[i] != expected[i];
    }
    EXPECT_LE(off_by_one, 2);
    EXPECT_EQ(view[4096], expected[4096]);
    EXPECT_EQ(view[static_cast<std::size_t>(7 * fw + 5)], expected[static_cast<std::size_t>(7 * fw + 5)]);
  }
}
