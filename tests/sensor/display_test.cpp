// Display images (spec 4.1.2): automatic gain control maps the least value to
// 0 and the greatest to 255 (linear between, rounded); without it the gain
// maps full_scale * 30^-step to 255 and clips; a constant image is mid-grey.
// The result is the same for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensor/display.hpp"

namespace s = eoir::sensor;

namespace {
s::DisplayOptions agc(s::DisplayStretch stretch = s::DisplayStretch::linear) {
  s::DisplayOptions o;
  o.stretch = stretch;
  return o;
}
s::DisplayOptions fixed_gain(std::int64_t step, double full_scale) {
  s::DisplayOptions o;
  o.agc = false;
  o.gain_step = step;
  o.full_scale = full_scale;
  return o;
}
}  // namespace

TEST(Display, AgcMapsTheRangeTo0Through255) {
  std::vector<double> v(100000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 3.0 + std::sin(0.001 * static_cast<double>(i)) * 2.0;
  v[77777] = 10.0;  // the greatest
  v[12] = -4.0;     // the least
  const auto one = s::compress_for_display(v, agc(), 1);
  const auto two = s::compress_for_display(v, agc(), 2);
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
    const auto b = s::compress_for_display(v, agc(), threads);
    EXPECT_EQ(b[10], 255) << threads;
    EXPECT_EQ(b[v.size() - 1], 0) << threads;
    EXPECT_EQ(b[1], 191) << threads;
  }
}

TEST(Display, FixedGainStepsOfThirtyAndClipping) {
  const std::vector<double> v{0.0, 0.5e-6, 1e-6, 2e-6, 1e-6 / 30.0};
  const auto step0 = s::compress_for_display(v, fixed_gain(0, 1e-6), 2);
  EXPECT_EQ(step0, (std::vector<std::uint8_t>{0, 128, 255, 255, 9}));
  const auto step1 = s::compress_for_display(v, fixed_gain(1, 1e-6), 2);
  EXPECT_EQ(step1[4], 255);  // full scale / 30 maps to 255 one step up
}

TEST(Display, ConstantImageIsMidGrey) {
  const std::vector<double> v(5000, 2.5);
  for (auto b : s::compress_for_display(v, agc(), 2)) ASSERT_EQ(b, 128);
  const std::vector<double> zero(5000, 0.0);
  for (auto b : s::compress_for_display(zero, agc(), 2)) ASSERT_EQ(b, 0);
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
  const auto expected = s::compress_for_display(irradiance, agc(), 1);
  for (unsigned threads : {1u, 2u}) {
    const auto view = s::scene_display(scene, agc(), threads);
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

// Stretches (issue 21 item 6): with u = (v - lo) / (hi - lo) a byte is
// round(255 s(u)), s(u) = log(1 + 1000 u) / log(1001) or
// asinh(10 u) / asinh(10) (astropy.visualization's LogStretch and
// AsinhStretch with their defaults, written out here).
TEST(Display, LogAndAsinhStretches) {
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(2.0 + 3.0 * i / 100.0);  // lo = 2, hi = 5 under AGC
  const auto log = s::compress_for_display(v, agc(s::DisplayStretch::log), 2);
  const auto asinh = s::compress_for_display(v, agc(s::DisplayStretch::asinh), 2);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double u = (v[i] - 2.0) / 3.0;
    EXPECT_EQ(log[i], std::lround(255.0 * std::log(1.0 + 1000.0 * u) / std::log(1001.0))) << i;
    EXPECT_EQ(asinh[i], std::lround(255.0 * std::asinh(u / 0.1) / std::asinh(10.0))) << i;
  }
  // u = 0.01: linear 3, log 255 log(11) / log(1001) = 88.5, asinh 255 asinh(0.1) / asinh(10) = 8.49.
  EXPECT_EQ(log[1], 89);
  EXPECT_EQ(asinh[1], 8);
  // Without AGC the range is [0, full_scale 30^-step].
  const std::vector<double> w{0.0, 1e-9, 1e-6, 5e-6};
  const auto fixed = s::compress_for_display(w, [] {
    auto o = fixed_gain(0, 1e-6);
    o.stretch = s::DisplayStretch::log;
    return o;
  }(), 1);
  EXPECT_EQ(fixed, (std::vector<std::uint8_t>{0, static_cast<std::uint8_t>(std::lround(255.0 * std::log(2.0) / std::log(1001.0))), 255, 255}));
}

// A saturated pixel is white under every stretch; a frame saturated all over
// is white, not the mid-grey of a flat frame.
TEST(Display, SaturatedPixelsAreWhite) {
  std::vector<double> v(4000, 10.0);
  v[7] = 100.0;    // saturated
  v[8] = 1000.0;   // above: as the engine clips, but any value at or above counts
  v[9] = 99.999;   // just below
  for (auto stretch : {s::DisplayStretch::linear, s::DisplayStretch::log, s::DisplayStretch::asinh,
                       s::DisplayStretch::zscale}) {
    auto o = agc(stretch);
    o.saturation = 100.0;
    const auto b = s::compress_for_display(v, o, 2);
    EXPECT_EQ(b[7], 255) << static_cast<int>(stretch);
    EXPECT_EQ(b[8], 255) << static_cast<int>(stretch);
    o.agc = false;
    o.gain_step = -2;  // 100 maps to 255 / 900 without the rule
    o.full_scale = 100.0;
    EXPECT_EQ(s::compress_for_display(v, o, 2)[7], 255) << static_cast<int>(stretch);
  }
  std::vector<double> all(5000, 100.0);
  auto o = agc();
  o.saturation = 100.0;
  for (auto b : s::compress_for_display(all, o, 2)) ASSERT_EQ(b, 255);
  o.saturation = HUGE_VAL;  // the same frame without saturation: flat, mid-grey
  for (auto b : s::compress_for_display(all, o, 2)) ASSERT_EQ(b, 128);
}

// zscale's limits (IRAF display.zscale): n sorted samples (every
// n/1000-th value), a line fitted with 2.5-sigma rejection, slope k;
// lo = median - (c - 1) k / 0.25 and hi = median + (n - c) k / 0.25 with
// c = (n - 1) / 2, within the samples' extremes. Expected values from
// astropy 5.2.1's ZScaleInterval() (astropy.visualization, the same
// algorithm written independently) on the same arrays.
TEST(Display, ZscaleLimitsAsAstropy) {
  // A noisy ramp with 20 outliers at its top: the outliers are rejected.
  std::vector<double> v(1000);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = static_cast<double>(i);
    v[i] = i >= 980 ? 1e6 : 0.01 * x + 0.003 * std::sin(1.7 * x);
  }
  double lo = 0, hi = 0;
  s::zscale_limits(v, lo, hi);
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 25.03656801263402, 1e-9);
  // 3000 values (every third sampled) with an outlier every 97th.
  std::vector<double> w(3000);
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double x = static_cast<double>(i);
    w[i] = i % 97 == 0 ? 500.0 : std::sin(0.37 * x) * 5 + x * 0.001;
  }
  s::zscale_limits(w, lo, hi);
  EXPECT_NEAR(lo, -4.942762941019945, 1e-9);
  EXPECT_NEAR(hi, 27.138441856476618, 1e-9);
  // The bytes: linear between the limits, outliers clipped white.
  s::zscale_limits(v, lo, hi);
  const auto b = s::compress_for_display(v, agc(s::DisplayStretch::zscale), 1);
  EXPECT_EQ(b[500], std::lround((v[500] - lo) * 255.0 / (hi - lo)));
  EXPECT_EQ(b[999], 255);
  // Fewer than 5 samples: the extremes.
  s::zscale_limits({3.0, 1.0, 2.0}, lo, hi);
  EXPECT_EQ(lo, 1.0);
  EXPECT_EQ(hi, 3.0);
}
