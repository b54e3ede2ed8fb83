// Issue 23 item 6: the per-sample shading of smooth and bitmap frames made
// cheaper must leave the frames as they were, to 1e-9 relative. The
// reference is the unmodified engine's output itself (main at commit
// b983174, before any of the speed changes), stored below: for the
// BM_FrameSunlight scene (tests/bench/bench_scene.hpp: the Earth from GEO,
// the Moon, three LEO satellites) at 64 x 64 pixels (4 x 4 samples per
// pixel), noise off, in each scene mode, by day and by night, in 0.45-0.75 um
// and 8-12 um: the scene radiance image's sum over each of 4 x 4 blocks of
// samples, the sum of its squares, and the noise-free electrons' sum.
// Radiances are >= 0, so a block sum moves by at most the largest relative
// change of its samples: every value must hold to 1e-9 relative (the sum of
// squares to 2e-9). A change of one sample in 1e6 of its value already moves
// its block's sum past that.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../bench/bench_scene.hpp"

namespace eoir::test {
namespace {

constexpr int kPixels = 64, kBlocks = 4;

struct Fingerprint {
  std::array<double, kBlocks * kBlocks> block_sums{};
  double sum_of_squares = 0, electrons = 0;
};

struct Case {
  int mode;  // 0 coarse, 1 smooth, 2 bitmap
  bool day, visible;
  Fingerprint expected;
};

Fingerprint render_fingerprint(const Case& c) {
  static const char* const modes[] = {"coarse", "smooth", "bitmap"};
  bench::SensorSetup s;
  s.pixels = kPixels;
  s.scene_mode = modes[c.mode];
  s.day_side = c.day;
  s.noise = false;
  if (c.visible) {
    s.band_low_um = 0.45;
    s.band_high_um = 0.75;
  }
  auto engine = bench::make_geo_scene(s);
  const Frame& f = engine->render("Sensor");
  const auto& L = f.scene.image.radiance_W_cm2_sr;
  const std::int64_t w = f.scene.image.grid.width(), h = f.scene.image.grid.height();
  EXPECT_EQ(static_cast<std::size_t>(w * h), L.size());
  Fingerprint out;
  for (std::int64_t r = 0; r < h; ++r)
    for (std::int64_t col = 0; col < w; ++col) {
      const double v = L[static_cast<std::size_t>(r * w + col)];
      out.block_sums[static_cast<std::size_t>((r * kBlocks / h) * kBlocks + col * kBlocks / w)] += v;
      out.sum_of_squares += v * v;
    }
  for (double e : f.sensor.mean_electrons) out.electrons += e;
  return out;
}

std::string print(const Fingerprint& f) {
  std::string s = "{{";
  char buf[40];
  for (std::size_t i = 0; i < f.block_sums.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.17g", i ? ", " : "", f.block_sums[i]);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "}, %.17g, ", f.sum_of_squares);
  s += buf;
  std::snprintf(buf, sizeof buf, "%.17g}", f.electrons);
  return s + buf;
}

bool near(double a, double b, double rel) { return std::fabs(a - b) <= rel * std::fabs(b); }

// Values printed by this file's render_fingerprint at commit b983174 (the
// engine before issue 23 item 6), mode/day/visible as in Case.
const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
#include "frame_shading_reference_values.inc"
  };
  return c;
}

TEST(FrameShadingReference, FramesEqualTheUnmodifiedEngineTo1e9) {
  ASSERT_EQ(cases().size(), 12u);
  for (const Case& c : cases()) {
    SCOPED_TRACE("mode " + std::to_string(c.mode) + (c.day ? " day" : " night") + (c.visible ? " visible" : " thermal"));
    const Fingerprint got = render_fingerprint(c);
    bool same = near(got.sum_of_squares, c.expected.sum_of_squares, 2e-9) &&
                near(got.electrons, c.expected.electrons, 1e-9);
    for (std::size_t i = 0; i < got.block_sums.size(); ++i) {
      EXPECT_TRUE(near(got.block_sums[i], c.expected.block_sums[i], 1e-9))
          << "block " << i << ": " << got.block_sums[i] << " vs " << c.expected.block_sums[i];
      same = same && near(got.block_sums[i], c.expected.block_sums[i], 1e-9);
    }
    EXPECT_TRUE(near(got.sum_of_squares, c.expected.sum_of_squares, 2e-9));
    EXPECT_TRUE(near(got.electrons, c.expected.electrons, 1e-9));
    if (!same) ADD_FAILURE() << "this frame now gives " << print(got);
  }
}

}  // namespace
}  // namespace eoir::test
