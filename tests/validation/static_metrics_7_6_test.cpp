// Spec 7.6 (Valid_Sens_StaticMetrics) Table 3, spec 7.5.5 and the OTF report
// curves against eqs. 34-38 and 56-57, evaluated independently here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "metrics/static_providers.hpp"
#include "sensor/static_metrics.hpp"

using namespace eoir::sensor;

namespace {

// Tolerance for a value the spec quotes to a few significant figures: 0.1 %
// of the value or half a unit of the last quoted digit, whichever is larger.
void expect_quoted(double actual, double quoted, double last_digit_unit, const char* what) {
  const double tolerance = std::max(1e-3 * std::abs(quoted), 0.5 * last_digit_unit);
  EXPECT_NEAR(actual, quoted, tolerance) << "spec 7.6 Table 3: " << what;
}

// Spec 7.6 step 2: the Table 3 sensor (also SensorParameters' defaults).
SensorParameters table3_sensor() {
  SensorParameters p;
  p.horizontal_pixels = p.vertical_pixels = 128;
  p.horizontal_fov_deg = p.vertical_fov_deg = 0.5;
  p.band_low_um = 1.0;
  p.band_high_um = 4.0;
  p.f_number = 3.5;
  p.focal_length_cm = 147.0;
  p.defocus_mm = 0.0;
  p.image_quality = eoir::universe::ImageQuality::diffraction_limited;
  p.diffraction_wavelength_um = 2.5;
  p.integration_time_ms = 10.0;
  p.sensitivity_quantity = ApertureQuantity::irradiance;
  p.sensitivity_pairs = {{10.0, 1.0e-18}};
  p.saturation_quantity = ApertureQuantity::irradiance;
  p.saturation_pairs = {{10.0, 1.0e-15}};
  p.jitter_mrad = 0.0;
  return p;
}

}  // namespace

TEST(Spec7_6_Table3, EnsquaredEnergy) {
  // Spec 7.6 step 4: 0.9683 for 100.22 um pixels, F/3.5, 2.5 um.
  const StaticMetrics m = compute_static_metrics(table3_sensor());
  EXPECT_NEAR(m.ensquared_energy, 0.9683, 0.0005);
  EXPECT_NEAR(m.pixel_pitch_x_cm * 1e4, 100.22, 0.005);
}

TEST(Spec7_6_Table3, EveryStaticMetric) {
  const StaticMetrics m = compute_static_metrics(table3_sensor());
  EXPECT_EQ(m.horizontal_pixels, 128);
  EXPECT_EQ(m.vertical_pixels, 128);
  expect_quoted(m.fov_solid_angle_sr, 7.6154e-5, 0.0001e-5, "FOV solid angle");
  expect_quoted(m.horizontal_fov_deg, 0.5, 0.1, "horizontal FOV");
  expect_quoted(m.vertical_fov_deg, 0.5, 0.1, "vertical FOV");
  expect_quoted(m.ifov_solid_angle_sr, 4.648e-9, 0.001e-9, "IFOV solid angle");
  expect_quoted(m.horizontal_ifov_mrad, 6.818e-2, 0.001e-2, "horizontal IFOV");
  expect_quoted(m.vertical_ifov_mrad, 6.818e-2, 0.001e-2, "vertical IFOV");
  expect_quoted(m.effective_fov_solid_angle_sr, 7.865e-5, 0.001e-5, "effective FOV solid angle");
  expect_quoted(m.effective_horizontal_fov_deg, 0.5081, 0.0001, "effective horizontal FOV");
  expect_quoted(m.effective_vertical_fov_deg, 0.5081, 0.0001, "effective vertical FOV");
  expect_quoted(m.effective_ifov_solid_angle_sr, 4.80e-9, 0.01e-9, "effective IFOV solid angle");
  expect_quoted(m.effective_horizontal_ifov_mrad, 6.928e-2, 0.001e-2, "effective horizontal IFOV");
  expect_quoted(m.effective_vertical_ifov_mrad, 6.928e-2, 0.001e-2, "effective vertical IFOV");
  expect_quoted(m.band_low_um, 1.0, 0.1, "low band edge");
  expect_quoted(m.band_high_um, 4.0, 0.1, "high band edge");
  expect_quoted(m.peak_irradiance_responsivity, 5.295e19, 0.001e19, "peak irradiance responsivity");
  expect_quoted(m.dark_nei_W_cm2, 1.0e-18, 0.1e-18, "NEI");
  expect_quoted(m.sei_W_cm2, 1.0e-15, 0.1e-15, "SEI");
  expect_quoted(m.peak_radiance_responsivity, 2.542e11, 0.001e11, "peak radiance responsivity");
  expect_quoted(m.dark_ner_W_cm2_sr, 2.083e-10, 0.001e-10, "NER");
  expect_quoted(m.ser_W_cm2_sr, 2.083e-7, 0.001e-7, "SER");
  expect_quoted(m.focal_length_cm, 147.0, 0.1, "effective focal length");
  expect_quoted(m.f_number, 3.5, 0.1, "F-number");
  expect_quoted(m.diffraction_wavelength_um, 2.5, 0.1, "diffraction wavelength");
  expect_quoted(m.airy_disk_diameter_mrad, 1.452e-2, 0.001e-2, "Airy disk diameter");
  expect_quoted(m.rayleigh_resolution_mrad, 7.262e-3, 0.001e-3, "Rayleigh resolution");
  expect_quoted(m.sparrow_resolution_mrad, 5.952e-3, 0.001e-3, "Sparrow resolution");
  // Derived, not in Table 3: D = f / F# and the electrons of spec 5.11.4-5.
  EXPECT_DOUBLE_EQ(m.entrance_pupil_diameter_cm, 42.0);
  EXPECT_NEAR(m.dark_noise_electrons, 1e-18 * m.peak_irradiance_responsivity, 1e-6);
  EXPECT_NEAR(m.saturation_electrons, 1e-15 * m.peak_irradiance_responsivity, 1e-3);
}

TEST(Spec7_6_Table3, ReportedThroughDataProviders) {
  // Spec 7.6 step 5: the four report styles carry the same numbers.
  using eoir::metrics::static_element;
  const StaticMetrics m = compute_static_metrics(table3_sensor());
  expect_quoted(static_element(m, "EOIR Sensor Spatial Performance", "Effective IFOV Solid Angle").number, 4.80e-9,
                0.01e-9, "Effective IFOV Solid Angle");
  expect_quoted(static_element(m, "EOIR Radiometric Performance", "Dark NER").number, 2.083e-10, 0.001e-10,
                "Dark NER");
  expect_quoted(static_element(m, "EOIR Sensor Optics", "Airy Disk Diameter").number, 1.452e-2, 0.001e-2,
                "Airy Disk Diameter");
  EXPECT_NEAR(static_element(m, "EOIR Sensor Optics", "Ensquared Energy").number, 0.9683, 0.0005);
  EXPECT_EQ(static_element(m, "EOIR Sensor Spectral Performance", "Number of Spectral Intervals").number, 10.0);
}

TEST(Spec7_5_5, PitchEqualToAiryDiameterGivesEnsquaredEnergy0p8445) {
  // Spec 7.5.5: 8-12 um band, pixel pitch = Airy diameter 2.44 lambda F#;
  // ERRATA: the definitions give 0.8445 ("~0.84" in the text).
  SensorParameters p = table3_sensor();
  p.band_low_um = 8.0;
  p.band_high_um = 12.0;
  p.diffraction_wavelength_um = 10.0;
  p.horizontal_pixels = p.vertical_pixels = 127;  // odd, as in the scenario
  const double pitch_cm = 2.44 * 10.0e-4 * p.f_number;
  const double fov_deg = 2.0 * std::atan(127 * pitch_cm / (2.0 * p.focal_length_cm)) * 180.0 / M_PI;
  p.horizontal_fov_deg = p.vertical_fov_deg = fov_deg;
  const StaticMetrics m = compute_static_metrics(p);
  EXPECT_NEAR(m.pixel_pitch_x_cm, pitch_cm, 1e-12);
  EXPECT_NEAR(m.ensquared_energy, 0.8445, 0.002);
  EXPECT_NEAR(m.ensquared_energy, 0.8445, 0.0001);  // in fact much closer
}

TEST(Spec7_7_1, EnsquaredEnergyOfTheUniformBackgroundSensor) {
  // Spec 7.7.1 items e-g: 100.2207 um pixels, f = 147 cm, ENSQ 0.86396. Item d
  // (R_peak,E = 3.779e20 with lambda_low = 8 um, 10 ms) fixes F/3.5; the
  // diffraction wavelength is the band centre, 10 um. We get 0.86390: the
  // spec's value is 6e-5 higher, within the accuracy of its own PSF grid.
  SensorParameters p = table3_sensor();
  p.band_low_um = 8.0;
  p.band_high_um = 12.0;
  p.diffraction_wavelength_um = 10.0;
  p.spectral_intervals = 50;
  const StaticMetrics m = compute_static_metrics(p);
  EXPECT_NEAR(m.pixel_pitch_x_cm * 1e4, 100.2207, 1e-4);
  EXPECT_NEAR(m.ensquared_energy, 0.86396, 1e-4);
  EXPECT_NEAR(m.peak_irradiance_responsivity, 3.779e20, 0.0005e20);
  EXPECT_NEAR(m.effective_ifov_solid_angle_sr, 5.38e-9, 0.005e-9);  // step 16
}

namespace {
// Eqs. 34-38 written out again, independently of engine/sensor/otf.cpp.
double eq34(double nu) { return nu >= 1 ? 0.0 : 2 / M_PI * (std::acos(nu) - nu * std::sqrt(1 - nu * nu)); }
double eq35(double nu, double w) {
  return std::exp(-std::pow(2 * M_PI * w, 2) * (1 - std::exp(-2 * 3.0 * 3.0 * nu * nu)));
}
double two_j1_over_x(double x) { return x == 0 ? 1.0 : 2 * std::cyl_bessel_j(1.0, x) / x; }
double eq38(double xi_mrad, double sigma_mrad) { return std::exp(-2 * std::pow(M_PI * sigma_mrad * xi_mrad, 2)); }

void check_curves(const SensorParameters& p, bool expect_large_defocus) {
  const StaticMetrics m = compute_static_metrics(p);
  const double f = p.focal_length_cm, F = p.f_number, lambda = p.diffraction_wavelength_um * 1e-4;
  const double delta = p.defocus_mm * 0.1;
  const double w = p.image_quality == eoir::universe::ImageQuality::mild ? 0.14 : p.wavefront_error_rms_waves;
  const double cutoff_image = 1 / (lambda * F);                  // cycles/cm
  const double cutoff_object = (f / F) / lambda / 1000.0;        // D / lambda, cycles/mrad
  const double wpp = delta / (8 * F * F * lambda);
  EXPECT_EQ(wpp > 2.2, expect_large_defocus);
  const double ifov_mrad = 2 * std::atan(m.pixel_pitch_x_cm / (2 * f)) * 1000;
  ASSERT_EQ(m.optics_otf.value.size(), static_cast<std::size_t>(p.fidelity.otf_curve_points));
  EXPECT_NEAR(m.optics_otf.frequency_cycles_per_mrad.back(), std::max(cutoff_object, 2 / ifov_mrad), 1e-9);
  for (std::size_t i = 0; i < m.optics_otf.value.size(); ++i) {
    const double xi = m.optics_otf.frequency_cycles_per_mrad[i];
    EXPECT_EQ(xi, m.diffraction_otf.frequency_cycles_per_mrad[i]);
    const double xi_image = xi * 1000 / f;
    const double nu = xi / cutoff_object;
    double optics = 0.0;
    if (nu < 1) {
      const double product = expect_large_defocus
                                 ? two_j1_over_x(M_PI * delta * xi_image / F)  // eq. 37
                                 : eq34(nu) * two_j1_over_x(M_PI * delta * xi_image * (cutoff_image - xi_image) /
                                                            (F * cutoff_image));  // eqs. 34 x 36
      optics = product * eq35(nu, w);                                            // eq. 33
    }
    EXPECT_NEAR(m.diffraction_otf.value[i], eq34(nu), 1e-12) << "xi " << xi;
    EXPECT_NEAR(m.optics_otf.value[i], optics, 1e-12) << "xi " << xi;
    EXPECT_NEAR(m.jitter_otf.value[i], eq38(xi, p.jitter_mrad), 1e-12) << "xi " << xi;
    const double a = M_PI * xi_image * m.pixel_pitch_x_cm;
    EXPECT_NEAR(m.horizontal_detector_mtf.value[i], xi == 0 ? 1.0 : std::abs(std::sin(a) / a), 1e-12);  // eq. 56
    EXPECT_NEAR(m.vertical_detector_mtf.value[i], m.horizontal_detector_mtf.value[i], 1e-12);          // eq. 57
  }
}
}  // namespace

TEST(Spec5_6_OtfCurves, PointwiseEqualToEqs34To38SmallDefocus) {
  SensorParameters p = table3_sensor();
  p.focal_length_cm = 16.0;
  p.f_number = 2.0;
  p.diffraction_wavelength_um = 4.0;
  p.image_quality = eoir::universe::ImageQuality::mild;  // Wrms 0.14
  p.defocus_mm = 0.1;        // W_pp = 0.78 waves: eq. 36
  p.jitter_mrad = 0.02;
  p.fidelity.otf_curve_points = 257;
  check_curves(p, false);
}

TEST(Spec5_6_OtfCurves, PointwiseEqualToEqs34To38LargeDefocus) {
  SensorParameters p = table3_sensor();
  p.focal_length_cm = 16.0;
  p.f_number = 2.0;
  p.diffraction_wavelength_um = 4.0;
  p.image_quality = eoir::universe::ImageQuality::custom;
  p.wavefront_error_rms_waves = 0.05;
  p.defocus_mm = 1.0;  // W_pp = 7.8 waves: eq. 37
  p.jitter_mrad = 0.02;
  check_curves(p, true);
}
