// Spec 5.7-5.8, 5.11.2: the PSF by FFT (eq. 40), ensquared energy (eq. 42)
// and energy on detector (eq. 51).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <thread>

#include "core/error.hpp"
#include "sensor/system_psf.hpp"

using namespace eoir::sensor;

namespace {
OpticsModel table3_optics() {
  OpticsModel o;
  o.focal_length_cm = 147.0;
  o.f_number = 3.5;
  o.diffraction_wavelength_cm = 2.5e-4;
  return o;
}
constexpr double pitch_cm = 100.2207e-4;
constexpr double lambda_f_cm = 2.5e-4 * 3.5;

// Independent ensquared energy: the Airy pattern
// PSF(r) = pi / (4 (lambda F)^2) [2 J1(v)/v]^2, v = pi r / (lambda F),
// integrated over the pixel by composite Gauss-Legendre quadrature.
double airy_ensquared_energy(double pitch, double lambda_f) {
  const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                        0.2369268850561891};
  const int panels = 200;
  const double h = 0.5 * pitch / panels;  // the quarter pixel [0, p/2]^2, by symmetry
  std::vector<double> nodes, weights;
  for (int k = 0; k < panels; ++k)
    for (int g = 0; g < 5; ++g) {
      nodes.push_back((k + 0.5) * h + 0.5 * h * gx[g]);
      weights.push_back(0.5 * h * gw[g]);
    }
  double sum = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      const double v = M_PI * std::hypot(nodes[i], nodes[j]) / lambda_f;
      const double a = v < 1e-8 ? 1.0 : 2.0 * std::cyl_bessel_j(1.0, v) / v;
      sum += weights[i] * weights[j] * a * a;
    }
  return 4.0 * sum * M_PI / (4.0 * lambda_f * lambda_f);
}
}  // namespace

TEST(SystemPsf, SampledPsfSumsToOne) {
  const OpticsModel o = table3_optics();
  for (bool cell : {true, false}) {
    const FocalPlaneSamples psf = sampled_psf(o, pitch_cm / 4, pitch_cm / 4, 41, 512, cell);
    EXPECT_NEAR(psf.sum(), 1.0, 1e-12);
    EXPECT_EQ(psf.values.size(), 41u * 41u);
    EXPECT_GT(psf.at(0, 0), psf.at(1, 0));
    EXPECT_NEAR(psf.at(3, -2), psf.at(-3, 2), 1e-15);  // point symmetric
    EXPECT_NEAR(psf.at(3, 2), psf.at(2, 3), 1e-12);     // radial OTF, square grid
  }
  // Unnormalised, the energy over the whole FFT period is exactly OTF(0) = 1.
  const FocalPlaneSamples full = energy_on_detector(o, pitch_cm, pitch_cm, 21, 0.0, 0.0, 512);
  EXPECT_NEAR(full.sum(), 1.0, 3e-3);  // the rest lies outside the 21 x 21 window
}

TEST(SystemPsf, AiryEncircledEnergyAtFirstDarkRing) {
  // 1 - J0(3.8317)^2 - J1(3.8317)^2 = 0.83779 inside r = 1.2197 lambda F#.
  const OpticsModel o = table3_optics();
  const double s = lambda_f_cm / 10.0;
  const std::int64_t n = 1024;
  const FocalPlaneSamples psf = sampled_psf(o, s, s, n - 1, n, false);
  const double r_dark = 3.8317059702075125 / M_PI * lambda_f_cm;
  double encircled = 0.0;
  for (std::int64_t iy = -psf.half(); iy <= psf.half(); ++iy)
    for (std::int64_t ix = -psf.half(); ix <= psf.half(); ++ix)
      if (std::hypot(ix * s, iy * s) <= r_dark) encircled += psf.at(ix, iy);
  const double v = 3.8317059702075125;
  const double exact = 1.0 - std::pow(std::cyl_bessel_j(0.0, v), 2) - std::pow(std::cyl_bessel_j(1.0, v), 2);
  EXPECT_NEAR(exact, 0.838, 0.0005);
  EXPECT_NEAR(encircled, exact, 2e-5);
}

TEST(SystemPsf, EnsquaredEnergyMatchesIndependentQuadrature) {
  const OpticsModel o = table3_optics();
  for (double pitch : {pitch_cm, 2.44 * lambda_f_cm, 1.0 * lambda_f_cm}) {
    const double reference = airy_ensquared_energy(pitch, lambda_f_cm);
    EXPECT_NEAR(ensquared_energy(o, pitch, pitch, 1024), reference, 2e-5) << "pitch " << pitch;
  }
}

TEST(SystemPsf, EnsquaredEnergyConvergesWithGridSize) {
  OpticsModel o = table3_optics();
  for (double w : {0.0, 0.14}) {
    for (double jitter : {0.0, 0.01}) {
      o.wavefront_error_rms_waves = w;
      o.jitter_mrad = jitter;
      const double coarse = ensquared_energy(o, pitch_cm, pitch_cm, 256);
      const double fine = ensquared_energy(o, pitch_cm, pitch_cm, 1024);
      EXPECT_NEAR(coarse, fine, 2e-4) << "Wrms " << w << " jitter " << jitter;
    }
  }
}

TEST(SystemPsf, EnergyOnDetectorSubPixelOffsets) {
  const OpticsModel o = table3_optics();
  const double ensq = ensquared_energy(o, pitch_cm, pitch_cm, 512);
  const FocalPlaneSamples centred = energy_on_detector(o, pitch_cm, pitch_cm, 5, 0.0, 0.0, 512);
  EXPECT_DOUBLE_EQ(centred.at(0, 0), ensq);
  EXPECT_NEAR(centred.at(1, 0), centred.at(0, 1), 1e-15);
  // Half a pixel to the right: two pixels share the light equally.
  const FocalPlaneSamples half = energy_on_detector(o, pitch_cm, pitch_cm, 5, 0.5 * pitch_cm, 0.0, 512);
  EXPECT_NEAR(half.at(0, 0), half.at(1, 0), 1e-12);
  EXPECT_NEAR(half.at(0, 0), 0.4874, 0.001);
  // A whole pixel: the centred pattern moves one pixel.
  const FocalPlaneSamples whole = energy_on_detector(o, pitch_cm, pitch_cm, 5, pitch_cm, -pitch_cm, 512);
  EXPECT_NEAR(whole.at(1, -1), ensq, 1e-12);
  EXPECT_NEAR(whole.at(2, -1), centred.at(1, 0), 1e-12);
  // A corner: four equal pixels.
  const FocalPlaneSamples corner =
      energy_on_detector(o, pitch_cm, pitch_cm, 5, 0.5 * pitch_cm, 0.5 * pitch_cm, 512);
  EXPECT_NEAR(corner.at(0, 0), corner.at(1, 1), 1e-12);
  EXPECT_NEAR(corner.at(0, 1), corner.at(1, 0), 1e-12);
}

TEST(SystemPsf, GridChoiceSamplesAboveCutoff) {
  const OpticsModel o = table3_optics();
  // dx = p / k <= lambda F# / 2 and <= p / 4.
  const std::int64_t k = fft_subdivisions(o, pitch_cm, 4);
  EXPECT_LE(pitch_cm / k, 0.5 * lambda_f_cm);
  EXPECT_GT(pitch_cm / (k - 1), 0.5 * lambda_f_cm);
  EXPECT_EQ(fft_subdivisions(o, 0.1 * lambda_f_cm, 4), 4);
  EXPECT_TRUE(valid_psf_grid_size(64));
  EXPECT_TRUE(valid_psf_grid_size(4096));
  EXPECT_FALSE(valid_psf_grid_size(32));
  EXPECT_FALSE(valid_psf_grid_size(8192));
  EXPECT_FALSE(valid_psf_grid_size(384));
  // A window wider than the FFT period is refused, naming the knob.
  try {
    energy_on_detector(o, pitch_cm, pitch_cm, 129, 0.0, 0.0, 128);
    FAIL();
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::out_of_range);
    EXPECT_NE(std::string(e.what()).find("psf_grid_size"), std::string::npos);
  }
}

// Pixels far larger than lambda F#: the Nyquist-fine grid would need more FFT
// points than psf_grid_size, so the spectrum is folded instead (still exact
// sampling, with a shorter period).
TEST(SystemPsf, FoldedSpectrumForLargePixels) {
  const OpticsModel o = table3_optics();
  const double big = 50.0 * lambda_f_cm;  // 100 FFT points per pixel at Nyquist
  const double reference = airy_ensquared_energy(big, lambda_f_cm);
  EXPECT_NEAR(ensquared_energy(o, big, big, 1024), reference, 2e-5);  // not folded
  EXPECT_NEAR(ensquared_energy(o, big, big, 128), reference, 2e-4);   // folded, period 2 pixels
  EXPECT_NEAR(ensquared_energy(o, big, big, 64), reference, 5e-4);    // folded, period 2 pixels
  // A window of pixels, folded (N = 128: 12 points per pixel instead of 23)
  // against the unfolded 1024 grid.
  const FocalPlaneSamples folded = energy_on_detector(o, pitch_cm, pitch_cm, 9, 0.3 * pitch_cm, 0.1 * pitch_cm, 128);
  const FocalPlaneSamples fine = energy_on_detector(o, pitch_cm, pitch_cm, 9, 0.3 * pitch_cm, 0.1 * pitch_cm, 1024);
  for (std::size_t i = 0; i < fine.values.size(); ++i) EXPECT_NEAR(folded.values[i], fine.values[i], 1e-4) << i;
  // The spec 7.8 kind of sensor: 24 deg over 128 pixels at f = 147 cm, 10 um,
  // F/3.5: 4.9 mm pixels, 140 lambda F#, fine with the default grid.
  const double huge = 2.0 * 147.0 * std::tan(12.0 * M_PI / 180.0) / 128.0;
  OpticsModel lwir = o;
  lwir.diffraction_wavelength_cm = 10e-4;
  const double e512 = ensquared_energy(lwir, huge, huge, 512);
  EXPECT_NEAR(e512, ensquared_energy(lwir, huge, huge, 4096), 1e-5);
  EXPECT_GT(e512, 0.995);
}

TEST(SystemPsf, RectangularPixels) {
  // Different pitches along x and y: each axis has its own FFT spacing, and
  // the radial OTF makes the result symmetric under exchanging them.
  const OpticsModel o = table3_optics();
  const double a = ensquared_energy(o, pitch_cm, 0.5 * pitch_cm, 512);
  const double b = ensquared_energy(o, 0.5 * pitch_cm, pitch_cm, 512);
  EXPECT_NEAR(a, b, 1e-6);
  EXPECT_LT(a, ensquared_energy(o, pitch_cm, pitch_cm, 512));
  EXPECT_GT(a, ensquared_energy(o, 0.5 * pitch_cm, 0.5 * pitch_cm, 512));
  const FocalPlaneSamples eod = energy_on_detector(o, pitch_cm, 0.5 * pitch_cm, 7, 0.0, 0.0, 512);
  EXPECT_GT(eod.at(0, 1), eod.at(1, 0));  // the short pixels lose more light along y
}

TEST(SystemPsf, ConcurrentCallsAgree) {
  const OpticsModel o = table3_optics();
  const double reference = ensquared_energy(o, pitch_cm, pitch_cm, 256);
  std::vector<double> results(4, 0.0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < results.size(); ++t)
    threads.emplace_back([&, t] { results[t] = ensquared_energy(o, pitch_cm, pitch_cm, t % 2 ? 256 : 128); });
  for (auto& th : threads) th.join();
  for (std::size_t t = 1; t < results.size(); t += 2) EXPECT_DOUBLE_EQ(results[t], reference);
}

// The fitted point tables' transform (PsfNumerics::fitted_fft_size: along y
// for every column, along x for the window's rows only) is the 2-D c2r's
// inverse DFT in another order: the same samples within rounding, here with
// an off-centre shift (a spectrum neither real nor even), at steps of one
// FFT point and of four (rows and columns read every fourth one).
TEST(SystemPsf, WindowRowsTransformIsTheWholeTransform) {
  const OpticsModel o = table3_optics();
  for (const double step_cm : {0.25 * pitch_cm, 2.0 * lambda_f_cm}) {
    PsfNumerics whole(256);
    PsfNumerics rows = whole;
    rows.fitted_fft_size = true;  // 256 is even: valid for both paths
    const FocalPlaneSamples a = pixel_integrated_psf(o, pitch_cm, pitch_cm, step_cm, step_cm, 61, 0.3 * step_cm,
                                                     -0.2 * step_cm, whole);
    const FocalPlaneSamples b = pixel_integrated_psf(o, pitch_cm, pitch_cm, step_cm, step_cm, 61, 0.3 * step_cm,
                                                     -0.2 * step_cm, rows);
    ASSERT_EQ(a.values.size(), b.values.size());
    double largest = 0, worst = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      largest = std::max(largest, std::abs(a.values[i]));
      worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
    }
    std::cout << "  step " << step_cm / pitch_cm << " px: largest difference " << worst / largest
              << " of the largest sample\n";
    EXPECT_GT(largest, 0.01);
    EXPECT_LT(worst, 1e-14 * largest);
    EXPECT_GT(worst, 0.0);  // (the other path ran: its rounding differs)
  }
}
