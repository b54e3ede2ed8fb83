// Bad input to compute_static_metrics: Status::out_of_range (unknown_name for
// an unknown preset) with the offending field named in the message.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/error.hpp"
#include "sensor/static_metrics.hpp"

using namespace eoir::sensor;

namespace {
void expect_rejected(const std::function<void(SensorParameters&)>& change, const std::string& field,
                     eoir::Status status = eoir::Status::out_of_range) {
  SensorParameters p;
  change(p);
  try {
    compute_static_metrics(p);
    ADD_FAILURE() << "accepted bad " << field;
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), status) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << "message '" << e.what() << "' does not name " << field;
  }
}
const double not_a_number = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TEST(StaticMetricsInput, PixelCounts) {
  expect_rejected([](auto& p) { p.horizontal_pixels = 0; }, "horizontal_pixels");
  expect_rejected([](auto& p) { p.vertical_pixels = -3; }, "vertical_pixels");
  SensorParameters zero;
  zero.horizontal_pixels = 0;
  try {
    compute_static_metrics(zero);
  } catch (const eoir::Error& e) {
    EXPECT_STREQ(e.what(), "horizontal_pixels: must be > 0, got 0");
  }
}

TEST(StaticMetricsInput, ReversedBandEdges) {
  SensorParameters reversed;
  reversed.band_low_um = 4.0;
  reversed.band_high_um = 1.0;
  try {
    compute_static_metrics(reversed);
    FAIL();
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::out_of_range);
    EXPECT_STREQ(e.what(), "band_high_um: must be greater than band_low_um (1 <= 4)");
  }
  expect_rejected([](auto& p) { p.band_high_um = p.band_low_um; }, "band_high_um");
  expect_rejected([](auto& p) { p.band_low_um = 0.0; }, "band_low_um");
}

TEST(StaticMetricsInput, NanAnywhere) {
  expect_rejected([](auto& p) { p.horizontal_fov_deg = not_a_number; }, "horizontal_fov_deg");
  expect_rejected([](auto& p) { p.vertical_fov_deg = not_a_number; }, "vertical_fov_deg");
  expect_rejected([](auto& p) { p.band_low_um = not_a_number; }, "band_low_um");
  expect_rejected([](auto& p) { p.band_high_um = not_a_number; }, "band_high_um");
  expect_rejected([](auto& p) { p.f_number = not_a_number; }, "f_number");
  expect_rejected([](auto& p) { p.focal_length_cm = not_a_number; }, "focal_length_cm");
  expect_rejected([](auto& p) { p.diffraction_wavelength_um = not_a_number; }, "diffraction_wavelength_um");
  expect_rejected([](auto& p) { p.defocus_mm = not_a_number; }, "defocus_mm");
  expect_rejected([](auto& p) { p.wavefront_error_rms_waves = not_a_number; }, "wavefront_error_rms_waves");
  expect_rejected([](auto& p) { p.jitter_mrad = not_a_number; }, "jitter_mrad");
  expect_rejected([](auto& p) { p.integration_time_ms = not_a_number; }, "integration_time_ms");
  expect_rejected([](auto& p) { p.sensitivity_pairs[0].value = not_a_number; }, "sensitivity_pairs[0].value");
  expect_rejected([](auto& p) { p.saturation_pairs[0].integration_time_ms = not_a_number; },
                  "saturation_pairs[0].integration_time_ms");
  expect_rejected([](auto& p) { p.horizontal_fov_deg = std::numeric_limits<double>::infinity(); },
                  "horizontal_fov_deg");
}

TEST(StaticMetricsInput, RangesAndLimits) {
  expect_rejected([](auto& p) { p.horizontal_fov_deg = 180.0; }, "horizontal_fov_deg");
  expect_rejected([](auto& p) { p.vertical_fov_deg = -1.0; }, "vertical_fov_deg");
  expect_rejected([](auto& p) { p.spectral_intervals = 0; }, "spectral_intervals");
  expect_rejected([](auto& p) { p.f_number = 0.0; }, "f_number");
  expect_rejected([](auto& p) { p.jitter_mrad = -0.1; }, "jitter_mrad");
  expect_rejected([](auto& p) { p.integration_time_ms = 0.0; }, "integration_time_ms");
  expect_rejected([](auto& p) { p.integration_time_ms = -5.0; }, "integration_time_ms");
  expect_rejected([](auto& p) { p.sensitivity_pairs.clear(); }, "sensitivity_pairs");
  // A ninth pair exceeds EOIR_MAX_REFERENCE_PAIRS (the C ABI's status).
  expect_rejected([](auto& p) { p.sensitivity_pairs.assign(9, ReferencePair{1.0, 1e-18}); }, "sensitivity_pairs",
                  eoir::Status::limit_exceeded);
  expect_rejected([](auto& p) { p.saturation_pairs.assign(9, ReferencePair{1.0, 1e-15}); }, "saturation_pairs",
                  eoir::Status::limit_exceeded);
  expect_rejected([](auto& p) { p.sensitivity_pairs[0].integration_time_ms = 0.0; },
                  "sensitivity_pairs[0].integration_time_ms");
  for (std::int64_t n : {0, 32, 100, 1000, 8192})
    expect_rejected([n](auto& p) { p.fidelity.psf_grid_size = n; }, "psf_grid_size");
  expect_rejected([](auto& p) { p.fidelity.otf_curve_points = 1; }, "otf_curve_points");
  expect_rejected([](auto& p) { p.fidelity.samples_per_pixel = 0; }, "samples_per_pixel");
  expect_rejected([](auto& p) { p.image_quality = static_cast<eoir::universe::ImageQuality>(9); }, "image_quality",
                  eoir::Status::unknown_name);
}

TEST(StaticMetricsInput, SaturationDisabled) {
  SensorParameters p;
  p.saturation_enabled = false;
  p.saturation_pairs.clear();  // not needed when saturation is off
  const StaticMetrics m = compute_static_metrics(p);
  EXPECT_TRUE(std::isinf(m.saturation_electrons));
  EXPECT_TRUE(std::isinf(m.sei_W_cm2));
  p.saturation_pairs = {{10.0, 1e-15}};
  const StaticMetrics with_pairs = compute_static_metrics(p);
  EXPECT_TRUE(std::isinf(with_pairs.saturation_electrons));  // SEe- = inf (spec 5.11.5)
  EXPECT_DOUBLE_EQ(with_pairs.sei_W_cm2, 1e-15);             // still reported
}

TEST(StaticMetricsInput, RadianceReferencePairs) {
  // NER pairs give the same electrons as the equivalent NEI pairs.
  SensorParameters p;
  const StaticMetrics irradiance = compute_static_metrics(p);
  p.sensitivity_quantity = ApertureQuantity::radiance;
  p.sensitivity_pairs = {{10.0, irradiance.dark_ner_W_cm2_sr}};
  p.saturation_quantity = ApertureQuantity::radiance;
  p.saturation_pairs = {{10.0, irradiance.ser_W_cm2_sr}};
  const StaticMetrics radiance = compute_static_metrics(p);
  EXPECT_NEAR(radiance.dark_nei_W_cm2 / 1e-18, 1.0, 1e-12);
  EXPECT_NEAR(radiance.sei_W_cm2 / 1e-15, 1.0, 1e-12);
  EXPECT_NEAR(radiance.dark_noise_electrons / irradiance.dark_noise_electrons, 1.0, 1e-12);
  EXPECT_NEAR(radiance.dark_noise_electrons, radiance.dark_ner_W_cm2_sr * radiance.peak_radiance_responsivity,
              1e-9 * radiance.dark_noise_electrons);
  EXPECT_NEAR(radiance.saturation_electrons / irradiance.saturation_electrons, 1.0, 1e-12);
}
