// Frames made in strips (issue 23 item 2; spec eq. 49): the scene's sample
// rows made strip by strip equal the whole grid's bit for bit, and the pixel
// means convolved through the temporary file equal the whole frame's to
// 1e-9 relative, for sensors whose PSF is diffraction alone, with jitter,
// defocus and wavefront error; the scene radiance and picks of a frame made
// in strips are the whole frame's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <string>

#include "../bench/bench_scene.hpp"
#include "core/error.hpp"
#include "scene/scene_generator.hpp"

namespace {

using eoir::Value;

// The largest |a - b| over pixels, relative to max(|a|, floor), with floor
// 1e-6 of the frame's peak (pixels of dark sky hold rounding alone).
double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double peak = 0;
  for (double v : a) peak = std::max(peak, std::abs(v));
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(std::abs(a[i]), 1e-6 * peak));
  return worst;
}

// The GEO full-disc scene of the benchmarks, noise off, on two threads.
std::unique_ptr<eoir::Engine> geo_scene(std::int64_t pixels, const char* scene_mode = "coarse") {
  eoir::bench::SensorSetup s;
  s.pixels = pixels;
  s.fov_deg = 18.0;
  s.noise = false;
  s.scene_mode = scene_mode;
  return eoir::bench::make_geo_scene(s, 1, 2);
}

struct Optics {
  const char* name;
  double jitter_mrad, defocus_mm, wavefront_waves;
};

class FrameStrips : public ::testing::TestWithParam<Optics> {};

TEST_P(FrameStrips, EqualTheWholeFrameTo1e9) {
  auto e = geo_scene(96, "smooth");
  const Optics o = GetParam();
  e->set_property("Sensor", "jitter_mrad", Value(o.jitter_mrad));
  e->set_property("Sensor", "defocus_mm", Value(o.defocus_mm));
  if (o.wavefront_waves > 0) {
    e->set_property("Sensor", "image_quality", Value(std::string("custom")));
    e->set_property("Sensor", "wavefront_error_rms_waves", Value(o.wavefront_waves));
  }
  const eoir::Frame& whole = e->render("Sensor");
  ASSERT_FALSE(whole.scene_in_strips);
  const std::vector<double> whole_mean = whole.sensor.mean_electrons;
  const std::size_t whole_rays = whole.scene.rays;
  e->set_property("Sensor", "scene_memory_max_mib", Value(0.0));
  const eoir::Frame& strips = e->render("Sensor");
  ASSERT_TRUE(strips.scene_in_strips);
  EXPECT_TRUE(strips.scene.image.radiance_W_cm2_sr.empty());
  EXPECT_TRUE(strips.scene_display().empty());
  EXPECT_EQ(strips.scene.rays, whole_rays);  // every sample and edge sub-sample cast once
  const double difference = max_relative_difference(whole_mean, strips.sensor.mean_electrons);
  RecordProperty("max_relative_difference", std::to_string(difference));
  std::printf("%s: largest relative difference %.3g\n", o.name, difference);
  EXPECT_LT(difference, 1e-9) << o.name;
  // (not a uniform frame: the Earth's disc fills most of it)
  EXPECT_GT(*std::max_element(whole_mean.begin(), whole_mean.end()),
            2.0 * *std::min_element(whole_mean.begin(), whole_mean.end()));
}

INSTANTIATE_TEST_SUITE_P(Optics, FrameStrips,
                         ::testing::Values(Optics{"diffraction", 0, 0, 0}, Optics{"jitter", 0.05, 0, 0},
                                           Optics{"defocus", 0, 0.05, 0}, Optics{"wavefront", 0.02, 0, 0.07}),
                         [](const auto& optics) { return std::string(optics.param.name); });

// Frames of a few pixels and oblong ones, in strips as whole.
TEST(FrameStrips, TinyAndOblongFramesEqualTheWholeFrame) {
  for (const auto& size : {std::pair<std::int64_t, std::int64_t>{1, 1}, {3, 2}, {40, 7}}) {
    auto e = geo_scene(8);
    e->set_property("Sensor", "horizontal_pixels", Value(size.first));
    e->set_property("Sensor", "vertical_pixels", Value(size.second));
    const std::vector<double> whole = e->render("Sensor").sensor.mean_electrons;
    e->set_property("Sensor", "scene_memory_max_mib", Value(0.0));
    const eoir::Frame& strips = e->render("Sensor");
    ASSERT_TRUE(strips.scene_in_strips);
    EXPECT_LT(max_relative_difference(whole, strips.sensor.mean_electrons), 1e-9) << size.first << " x " << size.second;
  }
}

// Rows made in strips of any height equal the whole grid's, bit for bit
// (silhouette edges, small objects and the sky's coarse grid read rows
// beyond a strip).
TEST(SceneRows, StripsOfAnyHeightEqualTheWholeGrid) {
  auto e = geo_scene(64);
  const eoir::Frame& f = e->render("Sensor");
  const auto& radiance = f.scene.image.radiance_W_cm2_sr;
  const std::int64_t w = f.grid().width(), h = f.grid().height();
  for (std::int64_t strip : {1, 7, 64, 113}) {
    eoir::scene::SceneRows rows;
    for (std::int64_t first = 0; first < h; first += strip) {
      const std::int64_t last = std::min(h, first + strip);
      rows = eoir::scene::generate_scene_rows(*f.world, first, last, 2, std::move(rows));
      ASSERT_EQ(rows.radiance_W_cm2_sr.size(), static_cast<std::size_t>((last - first) * w));
      for (std::int64_t i = 0; i < (last - first) * w; ++i) {
        const auto k = static_cast<std::size_t>(first * w + i);
        ASSERT_EQ(rows.radiance_W_cm2_sr[static_cast<std::size_t>(i)], radiance[k])
            << "strip " << strip << " sample " << k % w << ", " << k / w;
        ASSERT_EQ(rows.hits[static_cast<std::size_t>(i)].object_id, f.scene.hits[k].object_id);
        ASSERT_EQ(rows.hits[static_cast<std::size_t>(i)].part, f.scene.hits[k].part);
      }
    }
  }
  EXPECT_THROW(eoir::scene::generate_scene_rows(*f.world, h - 1, h + 1, 1), eoir::Error);
}

// A frame made in strips gives the whole frame's scene radiance and picks.
TEST(FrameStrips, SceneRadianceAndPicksAreMadeAgain) {
  auto e = geo_scene(48);
  const eoir::Frame& whole = e->render("Sensor");
  const std::int64_t fw = whole.grid().field_width(), fh = whole.grid().field_height();
  std::vector<double> a(static_cast<std::size_t>(fw * fh)), b(a.size());
  e->scene_field_radiance("Sensor", a.data());
  const eoir::scene::Pick pa = e->pick("Sensor", 1, 24, 24);
  e->set_property("Sensor", "scene_memory_max_mib", Value(0.0));
  e->render("Sensor");
  e->scene_field_radiance("Sensor", b.data());
  EXPECT_EQ(a, b);
  const eoir::scene::Pick pb = e->pick("Sensor", 1, 24, 24);
  EXPECT_EQ(pa.effective_radiance_W_cm2_sr, pb.effective_radiance_W_cm2_sr);
  EXPECT_EQ(pa.object, pb.object);
  EXPECT_EQ(pa.range_m, pb.range_m);
}

}  // namespace
