// Spec 7.3 (numerical integration over wavelength) and 7.4 (response to a
// uniform extended source: dark offset, peak radiance responsivity, dark
// noise, scene photon noise, saturation), with Valid_Sens_UniformExtAreaSrc.
// Statistics use the whole 128 x 128 image: there is no edge artifact to
// avoid (7.2.2), and 16384 pixels estimate a standard deviation to 0.6 %.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenario_host.hpp"

using eoir::test::Image;
using eoir::test::ScenarioHost;

namespace {
const char* kScenario = "valid_sens_uniform_ext_area_src.json";
const char* kRadiometric = "EOIR Radiometric Performance";


Image render_at(ScenarioHost& host, double T) {
  host.set_number("Satellite2", "temperature_K", T);
  host.render();
  return host.image(EOIR_IMAGE_SENSOR_ELECTRONS);
}
}  // namespace

// 7.3: the band-integrated radiance reported for the blackbody converges to
// the true value as the number of spectral intervals grows (6 ... 100), at
// 150, 200 and 300 K; 150 K gives 3.40e-5 W/(cm^2 sr). The interval midpoint
// rule's error falls as 1/N^2 (below 0.12 % at N = 6, 0.0004 % at N = 100);
// the exact option is independent of N.
TEST(Spec_7_3, BandRadianceConvergesWithSpectralIntervals) {
  ScenarioHost host(kScenario);
  EXPECT_NEAR(eoir::test::reference_band_radiance_8_12(150), 3.40e-5, 0.005e-5);  // the spec's true value, to its 3 digits
  for (double T : {150.0, 200.0, 300.0}) {
    host.set_number("Satellite2", "temperature_K", T);
    const double truth = eoir::test::reference_band_radiance_8_12(T);
    double previous_error = 1.0;
    for (int n : {6, 12, 25, 50, 75, 100}) {
      host.set_number("Sensor1", "spectral_intervals", n);
      host.render();
      const double L = host.pick(256, 256).effective_radiance;
      const double error = std::fabs(L / truth - 1.0);
      EXPECT_LT(error, 0.0015) << T << " K, " << n << " intervals";
      EXPECT_LE(error, previous_error * 1.0001) << T << " K: error must not grow with N (" << n << ")";
      previous_error = error;
    }
    EXPECT_LT(previous_error, 5e-5) << T << " K at 100 intervals";
    host.set_string("Sensor1", "band_integration", "exact");
    for (int n : {6, 100}) {
      host.set_number("Sensor1", "spectral_intervals", n);
      host.render();
      EXPECT_NEAR(host.pick(256, 256).effective_radiance / truth, 1.0, 1e-9) << "exact, " << n << " intervals";
    }
    host.set_string("Sensor1", "band_integration", "grid");
  }
}

// 7.4.1: a 0 K source gives a mean response of zero (zero dark offset,
// 5.11.3): within 4 standard errors of the dark noise.
TEST(Spec_7_4_1, DarkOffsetIsZero) {
  ScenarioHost host(kScenario);
  const Image im = render_at(host, 0.0);
  const double sigma = im.stddev(0, 0, 128, 128);
  EXPECT_GT(sigma, 0);
  EXPECT_LT(std::fabs(im.mean(0, 0, 128, 128)), 4 * sigma / 128.0);
}

// 7.4.2: the slope of the mean response against the effective radiance at
// 150, 200, 250, 300, 325, 350 K equals the reported peak radiance
// responsivity within 0.5 %. 200 K gives 3.481e-4 W/(cm^2 sr).
TEST(Spec_7_4_2, PeakRadianceResponsivityFromSlope) {
  ScenarioHost host(kScenario);
  EXPECT_NEAR(eoir::test::reference_band_radiance_8_12(200), 3.481e-4, 0.0005e-4);
  std::vector<double> x, y;
  for (double T : {150.0, 200.0, 250.0, 300.0, 325.0, 350.0}) {
    x.push_back(eoir::test::reference_band_radiance_8_12(T));
    y.push_back(render_at(host, T).mean(0, 0, 128, 128));
  }
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double reported = host.metric(kRadiometric, "Peak Radiance Responsivity");
  EXPECT_NEAR(slope / reported, 1.0, 0.005);
}

// 7.4.3: with the dark NER set to 2e-8 W/(cm^2 sr), the standard deviation
// of the response to a 0 K source divided by the peak radiance responsivity
// recovers 2e-8 within 2 %.
TEST(Spec_7_4_3, DarkNoiseRecoversTheDarkNer) {
  ScenarioHost host(kScenario, [](nlohmann::json& doc) {
    doc["sensors"][0]["parameters"]["sensitivity_pairs"] = {1.0, 2e-8};
  });
  const Image im = render_at(host, 0.0);
  const double ner = im.stddev(0, 0, 128, 128) / host.metric(kRadiometric, "Peak Radiance Responsivity");
  EXPECT_NEAR(ner / 2e-8, 1.0, 0.02);
  EXPECT_NEAR(host.metric(kRadiometric, "Dark NER"), 2e-8, 1e-15);
}

// 7.4.4: the total noise equals sqrt(ne_dark^2 + L_eff R_peak,L) (eqs. 53-54)
// within 2 % at every temperature; photon noise dominates when hot.
TEST(Spec_7_4_4, ScenePhotonNoise) {
  ScenarioHost host(kScenario);
  const double R = host.metric(kRadiometric, "Peak Radiance Responsivity");
  const double ne_dark = 1e-9 * R;  // the scenario's dark NER (spec: 1e-9)
  for (double T : {150.0, 200.0, 250.0, 300.0, 325.0, 350.0}) {
    const double expected = std::sqrt(ne_dark * ne_dark + eoir::test::reference_band_radiance_8_12(T) * R);
    EXPECT_NEAR(render_at(host, T).stddev(0, 0, 128, 128) / expected, 1.0, 0.02) << T << " K";
  }
}

// 7.4.5: with saturation on at SER = 4e-3 W/(cm^2 sr), the response follows
// L_eff R_peak,L below the SER and is clipped at SER R_peak,L above it (200,
// 250, 302, 304, 325, 350 K: the band radiance crosses 4e-3 between 302 and
// 304 K).
TEST(Spec_7_4_5, SaturationAtTheSer) {
  ScenarioHost host(kScenario);
  host.set_bool("Sensor1", "saturation_enabled", true);
  const double R = host.metric(kRadiometric, "Peak Radiance Responsivity");
  EXPECT_NEAR(host.metric(kRadiometric, "SER"), 4e-3, 1e-12);
  const double full_well = 4e-3 * R;
  for (double T : {200.0, 250.0, 302.0, 304.0, 325.0, 350.0}) {
    const double L = eoir::test::reference_band_radiance_8_12(T);
    const Image im = render_at(host, T);
    const double mean = im.mean(0, 0, 128, 128);
    if (L < 4e-3) {
      EXPECT_NEAR(mean / (L * R), 1.0, 1e-3) << T << " K";
    } else {
      // Every pixel clipped (the source is ~400 sigma above the SER).
      EXPECT_NEAR(mean / full_well, 1.0, 1e-12) << T << " K";
      EXPECT_LT(im.stddev(0, 0, 128, 128), 1e-9 * full_well) << T << " K";
    }
  }
}
