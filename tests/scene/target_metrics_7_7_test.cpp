// Spec 7.7: dynamic metrics involving a target (Table 2, eqs. 58-78), with
// Valid_Sens_PtSrcTgtUniformBkg (7.7.1) and Valid_Sens_PointSrcTarget
// (7.7.2), and the per-frame truth of a rendered point source.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_host.hpp"

using eoir::test::Image;
using eoir::test::ScenarioHost;

namespace {
const char* kUniform = "valid_sens_pt_src_tgt_uniform_bkg.json";

// Half a unit of the last digit the spec quotes, or 0.1 %, whichever is larger.
double quoted(double value, double last_digit) { return std::max(0.5 * last_digit, 1e-3 * std::fabs(value)); }

}  // namespace

// 7.7.1 step 4, items a-j (and k, step 5 with ERRATA's 52.10 m^2): the
// stationary 1 m, 350 K target against the uniform 300 K background.
TEST(Spec_7_7_1, ItemsAToJ) {
  ScenarioHost host(kUniform);
  for (double t : {0.0, 300.0}) {  // constant over the report's time span
    host.at(t);
    EXPECT_NEAR(host.target_metric("Range to Target", "Aircraft2"), 98.4, quoted(98.4, 0.1));          // a
    EXPECT_NEAR(host.target_metric("Effective Target Irradiance", "Aircraft2"), 2.53e-12, quoted(2.53e-12, 0.01e-12));  // b
    EXPECT_NEAR(host.target_metric("Point Target Solid Angle", "Aircraft2"), 3.24e-10, quoted(3.24e-10, 0.01e-10));  // c
    EXPECT_NEAR(host.target_metric("Scene Photon NEI", "Aircraft2"), 2.34e-16, quoted(2.34e-16, 0.01e-16));          // d
    EXPECT_NEAR(host.target_metric("Total NEI", "Aircraft2"), 2.34e-16, quoted(2.34e-16, 0.01e-16));                 // e
    EXPECT_EQ(host.target_metric("Effective Target Radiance", "Aircraft2"), 0.0);                                    // f
    EXPECT_NEAR(host.target_metric("Effective Background Radiance", "Aircraft2"), 3.85e-3, quoted(3.85e-3, 0.01e-3));  // g
    EXPECT_NEAR(host.target_metric("Scene Photon NER", "Aircraft2"), 4.35e-8, quoted(4.35e-8, 0.01e-8));             // h
    EXPECT_NEAR(host.target_metric("Total NER", "Aircraft2"), 4.35e-8, quoted(4.35e-8, 0.01e-8));                    // i
    EXPECT_NEAR(host.target_metric("Signal to Noise Ratio", "Aircraft2") / 5479.0, 1.0, 0.005);                      // j
    EXPECT_NEAR(host.target_metric("Geometric IFOV Footprint", "Aircraft2"), 45.006, quoted(45.006, 0.001));         // k
    // Step 5 quotes 46.481 m^2; by Table 2 (Omega_EIFOV R^2) with this
    // sensor's ensquared energy 0.86396 it is 52.10 m^2 (ERRATA 7.7.1).
    EXPECT_NEAR(host.target_metric("Effective IFOV Footprint", "Aircraft2"), 52.10, quoted(52.10, 0.01));
    EXPECT_EQ(host.target_metric("Target Is Point Source", "Aircraft2"), 1.0);
  }
  EXPECT_NEAR(host.metric("EOIR Radiometric Performance", "Peak Irradiance Responsivity"), 3.779e20,
              quoted(3.779e20, 0.001e20));  // item d of step 2
  EXPECT_NEAR(host.metric("EOIR Sensor Optics", "Ensquared Energy"), 0.86396, 1e-4);  // item g (see tests/validation)
}

// Steps 6-8: equal temperatures give SNR 0 (exactly, with the consistent
// treatment of ERRATA footnote 3; to rounding here).
TEST(Spec_7_7_1, EqualTemperaturesGiveZeroSnr) {
  ScenarioHost host(kUniform);
  host.set_number("Aircraft2", "temperature_K", 300.0);
  EXPECT_LT(host.target_metric("Signal to Noise Ratio", "Aircraft2"), 1e-6);
}

// Steps 12-14: a 0 K background gives scene photon NEI 0 and total NEI equal
// to the dark NEI 1e-18 W/cm^2.
TEST(Spec_7_7_1, ZeroKelvinBackground) {
  ScenarioHost host(kUniform);
  host.set_number("Aircraft1", "temperature_K", 0.0);
  EXPECT_EQ(host.target_metric("Scene Photon NEI", "Aircraft2"), 0.0);
  EXPECT_NEAR(host.target_metric("Total NEI", "Aircraft2"), 1e-18, 1e-24);
}

// Steps 15-23: Omega_EIFOV = 5.38e-9 sr; radius 4.072 m is a point target
// (Omega_T = 5.3799e-9 sr), 4.073 m an extended one (5.383e-9 sr) with
// effective target radiance 7.80e-3. Across the transition our SNR is
// continuous within 0.1 % (the spec reports a ~1 % step from its approximate
// point-source solid angle; ours is the exact projected area of eq. 58).
TEST(Spec_7_7_1, PointToExtendedTransition) {
  ScenarioHost host(kUniform);
  EXPECT_NEAR(host.metric("EOIR Sensor Spatial Performance", "Effective IFOV Solid Angle"), 5.38e-9,
              quoted(5.38e-9, 0.01e-9));
  const double r_point = 4.072, r_extended = 4.073;
  double snr_point = 0, snr_extended = 0;
  {
    const double dims[1] = {r_point};
    ASSERT_EQ(host.api().set_array(host.handle(), "Aircraft2", "dimensions_m", dims, 1), EOIR_OK);
    EXPECT_EQ(host.target_metric("Target Is Point Source", "Aircraft2"), 1.0);
    EXPECT_NEAR(host.target_metric("Point Target Solid Angle", "Aircraft2"), 5.3799e-9, quoted(5.3799e-9, 0.0001e-9));
    EXPECT_GT(host.target_metric("Effective Target Irradiance", "Aircraft2"), 0.0);
    EXPECT_EQ(host.target_metric("Effective Target Radiance", "Aircraft2"), 0.0);
    snr_point = host.target_metric("Signal to Noise Ratio", "Aircraft2");
  }
  {
    const double dims[1] = {r_extended};
    ASSERT_EQ(host.api().set_array(host.handle(), "Aircraft2", "dimensions_m", dims, 1), EOIR_OK);
    EXPECT_EQ(host.target_metric("Target Is Point Source", "Aircraft2"), 0.0);
    EXPECT_EQ(host.target_metric("Effective Target Irradiance", "Aircraft2"), 0.0);
    EXPECT_EQ(host.target_metric("Point Target Solid Angle", "Aircraft2"), 0.0);
    EXPECT_NEAR(host.target_metric("Effective Target Radiance", "Aircraft2"), 7.80e-3, quoted(7.80e-3, 0.01e-3));
    EXPECT_NEAR(host.target_metric("Effective Background Radiance", "Aircraft2"), 3.85e-3, quoted(3.85e-3, 0.01e-3));
    snr_extended = host.target_metric("Signal to Noise Ratio", "Aircraft2");
  }
  EXPECT_NEAR(snr_extended / snr_point, 1.0, 1e-3);
}

// 7.7.2: the SNR of the 1 cm, 250 K sphere against space follows the analytic
// E / NEI = L(250 K) pi r^2 / R^2 / 1e-18 W/cm^2 within 1 % from 10 km outward,
// over the report's 20 minutes at 60 s.
TEST(Spec_7_7_2, SnrAgainstRangeMatchesAnalytic) {
  ScenarioHost host("valid_sens_point_src_target.json");
  const double L = eoir::test::reference_band_radiance_8_12(250.0), area_cm2 = M_PI * 1.0 * 1.0;  // r = 1 cm
  double first_range = 0, last_range = 0;
  for (int step = 0; step <= 20; ++step) {
    host.at(60.0 * step);
    const double range_km = host.target_metric("Range to Target", "Satellite2");
    const double expected = L * area_cm2 / std::pow(range_km * 1e5, 2) / 1e-18;
    EXPECT_NEAR(host.target_metric("Signal to Noise Ratio", "Satellite2") / expected, 1.0, 0.01) << step;
    EXPECT_EQ(host.target_metric("Effective Background Radiance", "Satellite2"), 0.0);  // space
    if (step == 0) first_range = range_km;
    last_range = range_km;
  }
  EXPECT_NEAR(first_range, 10.0, 0.01);  // 7310 - 7300 km at the start
  EXPECT_GT(last_range, first_range);
}

// Per-frame truth: for an isolated noise-free point source, the centroid of
// the rendered electrons equals the reported sub-pixel position within 0.01
// pixel. This holds for a PSF sampled at the Nyquist rate or finer (optics
// cutoff 1/(lambda F#) below 1/pitch): with coarser pixels the centroid of
// any pixelated spot is biased toward the pixel centre (the aliased terms
// OTF(k/p) sinc'(k) of the centroid sum do not vanish), which is physics,
// not a rendering error. Valid_Sens_PSF is sampled finely (lambda F# = 3.75
// pixels); its point source is moved to an arbitrary sub-pixel position.
TEST(Truth, CentroidOfRenderedPointSourceMatchesReportedPosition) {
  ScenarioHost host("valid_sens_psf.json", [](nlohmann::json& doc) {
    const double ifov = 0.04e-3, tx = 3.37 * ifov, ty = -2.21 * ifov, r = 100e3, n = std::sqrt(1 + tx * tx + ty * ty);
    for (auto& p : doc["objects"][1]["motion"]["points"]) p["position_m"] = {7000e3 + r * tx / n, r * ty / n, r / n};
  });
  host.render();
  size_t count = 0;
  ASSERT_EQ(host.api().truth_count(host.handle(), "Sensor1", &count), EOIR_OK) << host.api().last_error();
  ASSERT_EQ(count, 1u);
  eoir_truth truth{};
  truth.struct_size = sizeof truth;
  ASSERT_EQ(host.api().truth_get(host.handle(), "Sensor1", 0, &truth), EOIR_OK);
  EXPECT_STREQ(truth.object, "Aircraft2");
  EXPECT_NEAR(truth.pixel_x, 127 - 3.37, 0.01);  // body +x is on the left of the picture
  EXPECT_NEAR(truth.pixel_y, 127 + 2.21, 0.01);  // body -y is down
  EXPECT_GT(std::fabs(truth.pixel_x - std::round(truth.pixel_x)), 0.05);             // between pixel centres
  EXPECT_EQ(truth.point_source, 1);
  const Image im = host.image(EOIR_IMAGE_SENSOR_MEAN);
  // A window centred on the source's pixel, 2 x 100 + 1 pixels (27 lambda F#
  // each side): the Airy tails it cuts are cut symmetrically.
  double sum = 0, sx = 0, sy = 0;
  const int cx = static_cast<int>(std::lround(truth.pixel_x)), cy = static_cast<int>(std::lround(truth.pixel_y));
  for (int y = cy - 100; y <= cy + 100; ++y)
    for (int x = cx - 100; x <= cx + 100; ++x) {
      sum += im.at(x, y);
      sx += x * im.at(x, y);
      sy += y * im.at(x, y);
    }
  EXPECT_NEAR(sx / sum, truth.pixel_x, 0.01);
  EXPECT_NEAR(sy / sum, truth.pixel_y, 0.01);
  EXPECT_NEAR(truth.range_m, 100e3, 1.0);
  EXPECT_NEAR(truth.snr, host.target_metric("Signal to Noise Ratio", "Aircraft2"), 1e-9 * truth.snr);
}

// Bad input: unknown target or sensor, target equal to the sensor's parent,
// no target for the target group: a status and a message naming the field.
TEST(TargetMetrics, BadInput) {
  ScenarioHost host(kUniform);
  std::string message;
  EXPECT_EQ(host.try_target_metric("Signal to Noise Ratio", "Nobody", "Sensor1", message), EOIR_ERR_UNKNOWN_NAME);
  EXPECT_NE(message.find("Nobody"), std::string::npos) << message;
  EXPECT_EQ(host.try_target_metric("Signal to Noise Ratio", "Aircraft2", "Sensor9", message), EOIR_ERR_UNKNOWN_NAME);
  EXPECT_NE(message.find("Sensor9"), std::string::npos) << message;
  EXPECT_EQ(host.try_target_metric("Signal to Noise Ratio", "Aircraft3", "Sensor1", message), EOIR_ERR_NOT_ALLOWED);
  EXPECT_NE(message.find("target"), std::string::npos) << message;
  EXPECT_EQ(host.try_target_metric("Signal to Noise Ratio", "", "Sensor1", message), EOIR_ERR_NULL_ARGUMENT);
  EXPECT_NE(message.find("target"), std::string::npos) << message;
  EXPECT_EQ(host.try_target_metric("Signal to Noise", "Aircraft2", "Sensor1", message), EOIR_ERR_UNKNOWN_NAME);
  EXPECT_NE(message.find("Signal to Noise"), std::string::npos) << message;
}
