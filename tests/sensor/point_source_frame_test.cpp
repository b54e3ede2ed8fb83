// The image chain with point sources (spec 5.11, eqs. 49-51): a frame holding
// only point sources does no FFT once the sensor's point-source model is
// built (the scene FFT is skipped without extended radiance, DESIGN.md 4, and
// the energy on detector comes from the model's tables); the point-source
// list's positions and streaks (sample coordinates) reach the pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fftw_plans.hpp"
#include "sensor/image_chain.hpp"
#include "sensor/point_source_render.hpp"

using namespace eoir::sensor;

namespace {

std::shared_ptr<const SensorModel> noise_free_table3() {
  SensorParameters p;  // spec 7.6 Table 3
  p.noise_enabled = false;
  return resolve_sensor(p);
}

eoir::radiometry::RadianceImage empty_scene(const SensorModel& model) {
  eoir::radiometry::RadianceImage scene;
  scene.grid = model.grid;
  scene.radiance_W_cm2_sr.assign(static_cast<std::size_t>(model.grid.width() * model.grid.height()), 0.0);
  return scene;
}

}  // namespace

TEST(Spec_5_11_PointSourceFrame, NoFftForPointSourcesOnly) {
  const auto model = noise_free_table3();
  eoir::radiometry::RadianceImage scene = empty_scene(*model);
  for (int i = 0; i < 50; ++i) {
    eoir::radiometry::PointSource ps;
    ps.column = static_cast<double>(model->grid.guard_samples()) + 7.3 * i + 0.37;
    ps.row = static_cast<double>(model->grid.guard_samples()) + 5.1 * i + 2.9;
    ps.irradiance_W_cm2 = 1e-16;
    ps.streak_columns = i % 3 == 0 ? 9.0 : 0.0;
    scene.point_sources.push_back(ps);
  }
  std::mt19937_64 rng(1);
  model->point_sources();  // the one-off build (its FFTs)
  const std::uint64_t before = eoir::fftw::plan_requests();
  const SensorImage image = render_sensor_image(*model, scene, rng);
  EXPECT_EQ(eoir::fftw::plan_requests(), before);
  double sum = 0;
  for (double v : image.mean_electrons) sum += v;
  EXPECT_GT(sum, 0.0);
  // The counter does count: extended radiance brings the scene FFT (its row
  // and column plans, requested once per thread's share).
  scene.radiance_W_cm2_sr[scene.radiance_W_cm2_sr.size() / 2] = 1e-6;
  render_sensor_image(*model, scene, rng);
  EXPECT_GT(eoir::fftw::plan_requests(), before);
}

// A point source's sample coordinates and streak (samples, end - start) map
// to pixels as x = (column - guard + 1/2) / k - 1/2 (geometry/sample_grid.hpp)
// and streak / k, k samples per pixel; r_E = R_peak,E E^ps EOD / ENSQ (eq. 50).
TEST(Spec_5_11_PointSourceFrame, StreakInSamplesReachesThePixels) {
  const auto model = noise_free_table3();
  eoir::radiometry::RadianceImage scene = empty_scene(*model);
  const double k = static_cast<double>(model->grid.per_pixel), guard = static_cast<double>(model->grid.guard_samples());
  eoir::radiometry::PointSource ps;
  ps.column = guard + 200.6;
  ps.row = guard + 301.2;
  ps.irradiance_W_cm2 = 2e-16;
  ps.streak_columns = 48.0;  // 12 pixels
  ps.streak_rows = -18.0;    // -4.5 pixels
  scene.point_sources.push_back(ps);
  std::mt19937_64 rng(1);
  const SensorImage image = render_sensor_image(*model, scene, rng);
  PointSourceSignal s;
  s.x_px = (200.6 + 0.5) / k - 0.5;
  s.y_px = (301.2 + 0.5) / k - 0.5;
  s.streak_x_px = 12.0;
  s.streak_y_px = -4.5;
  s.electrons = model->metrics.peak_irradiance_responsivity * 2e-16 / model->metrics.ensquared_energy;
  std::vector<double> expected(image.mean_electrons.size(), 0.0);
  render_point_sources(model->point_sources(), {s}, model->grid.pixels_x, model->grid.pixels_y, expected);
  double peak = 0;
  for (double v : expected) peak = std::max(peak, v);
  ASSERT_GT(peak, 0.0);
  for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_NEAR(image.mean_electrons[i], expected[i], 1e-12 * peak) << i;
}
