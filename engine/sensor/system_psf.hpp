// The system PSF (spec 5.7, eq. 40) and the energy it puts on detectors
// (eqs. 41-42, 51), by FFT of the system OTF (eq. 39) with FFTW.
//
// Method: the quantity wanted, the PSF integrated over a rectangular cell
// (a pixel for eq. 51, a sample cell for the scene grid), is the inverse
// Fourier transform of OTF(xi) * A sinc(xi_x a) sinc(xi_y b). The OTF is
// band-limited at 1/(lambda F#), so sampling it on an N x N frequency grid
// that covers the cutoff (focal-plane spacing dx <= lambda F# / 2) makes the
// inverse FFT exact up to aliasing of the PSF tails from the spatial period
// N dx. The spacing is an integer fraction of the output step (the pixel pitch
// or the sample spacing), so pixel values are FFT outputs, not interpolations.
// When Nyquist-fine spacing would leave a period shorter than the window plus
// one step (pixels of hundreds of lambda F#), dx is coarser and the spectrum
// is folded (each bin sums its aliases xi + m / dx inside the cutoff), which
// is still exact sampling; only the period, not the accuracy of the OTF
// sampling, is then limited by the grid size. The fold and its FFT run on
// every core (a sensor's one-off tables; the same numbers for any count).
#pragma once
#include <cstdint>
#include <vector>

#include "core/fidelity.hpp"
#include "sensor/otf.hpp"

namespace eoir::sensor {

// The numerical knobs of the PSF computation (core/fidelity.hpp): FFT size
// (psf_grid_size), radial OTF table size, alias margin and fold budget.
struct PsfNumerics {
  std::int64_t fft_size;
  std::int64_t otf_table_size;
  std::int64_t alias_margin_steps;
  double fold_budget;
  // The optics' radial OTF table at otf_table_size (radial_otf_table), made
  // once by a caller that folds many times for the same optics (only its
  // size is checked); null: each fold makes its own.
  const std::vector<double>* otf_table = nullptr;
  // fft_size may be any even size in [64, 4096] (the point-source tables fit
  // it to their period), and the inverse transform computes the window's
  // rows only; otherwise a power of two (psf_grid_size), the whole 2-D c2r.
  bool fitted_fft_size = false;
  explicit PsfNumerics(const Fidelity& f)
      : fft_size(f.psf_grid_size),
        otf_table_size(f.otf_table_size),
        alias_margin_steps(f.psf_alias_margin_steps),
        fold_budget(f.psf_fold_budget) {}
  // The fidelity defaults with another FFT size.
  PsfNumerics(std::int64_t fft) : PsfNumerics(Fidelity{}) { fft_size = fft; }  // NOLINT: implicit on purpose
};

// Values on a square focal-plane grid centred on the origin: element
// (ix, iy), -half <= ix, iy <= half, is at (ix step_x, iy step_y).
struct FocalPlaneSamples {
  std::int64_t size = 0;  // odd, samples per side
  double step_x_cm = 0, step_y_cm = 0;
  std::vector<double> values;  // row-major: [(iy + half) * size + (ix + half)]

  std::int64_t half() const { return size / 2; }
  double at(std::int64_t ix, std::int64_t iy) const {
    return values[static_cast<std::size_t>((iy + half()) * size + (ix + half()))];
  }
  double sum() const;
};

// FFT focal-plane spacing for an output step: step / k with the smallest
// integer k >= min_subdivisions such that step / k <= lambda F# / 2 (capped
// at fft_size / (window + 1), where folding takes over).
std::int64_t fft_subdivisions(const OpticsModel& optics, double step_cm, std::int64_t min_subdivisions);

// (a) The system PSF on a grid of the given spacing and odd size, normalised
// to unit sum. cell_integrated: each value is the PSF integrated over its
// spacing_x x spacing_y cell (what a convolution on that grid needs);
// otherwise the PSF is point-sampled. Throws out_of_range naming
// psf_grid_size when size + 1 > fft_size (the FFT period must hold the window
// plus one step; the same holds below).
FocalPlaneSamples sampled_psf(const OpticsModel& optics, double spacing_x_cm, double spacing_y_cm,
                              std::int64_t size, const PsfNumerics& numerics, bool cell_integrated = true);

// (b) Energy on detector, eq. 51, for a point source at (offset_x, offset_y)
// from the centre of pixel (0, 0): element (m, n) is the fraction of the
// source's energy on the pixel centred at (m p_x, n p_y). window is odd.
FocalPlaneSamples energy_on_detector(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm,
                                     std::int64_t window, double offset_x_cm, double offset_y_cm,
                                     const PsfNumerics& numerics);

// (b') The same quantity as a function of the source's position, on a finer
// grid: element (ix, iy) is the fraction of a source's energy falling on a
// pixel whose centre lies at (centre_x + ix step_x, centre_y + iy step_y)
// from the source (the PSF integrated over a p_x x p_y cell there). With
// step = pitch and centre 0 this is energy_on_detector at offset 0; finer
// steps tabulate eq. 51 against sub-pixel offsets with one FFT.
FocalPlaneSamples pixel_integrated_psf(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm,
                                       double step_x_cm, double step_y_cm, std::int64_t size, double centre_x_cm,
                                       double centre_y_cm, const PsfNumerics& numerics);

// (b'') The separable counterpart for pixels far wider than lambda F#: the
// line-spread function (the PSF integrated across y; its transform is the
// radial OTF on the xi axis, OTF(xi, 0)) integrated over a pixel of width
// pitch, sampled at centre + j step, j = -half..half, by one 1-D FFT (a
// Nyquist-fine spacing step / k <= lambda F# / 2, period at least
// period_cm and twice the samples' span). Its samples at whole pixels sum
// to one. otf_table_size as for integrated PSFs.
std::vector<double> pixel_integrated_lsf(const OpticsModel& optics, double pitch_cm, double step_cm, std::int64_t half,
                                         double centre_cm, double period_cm, std::int64_t otf_table_size);
// The same with the radial OTF table given (radial_otf_table), for callers
// that make several.
std::vector<double> pixel_integrated_lsf(const OpticsModel& optics, double pitch_cm, double step_cm, std::int64_t half,
                                         double centre_cm, double period_cm, const std::vector<double>& otf_table);

// The radial OTF at cutoff k / otf_table_size, k = 0..otf_table_size (and a
// zero past the end), the table the PSF folds interpolate linearly.
std::vector<double> radial_otf_table(const OpticsModel& optics, std::int64_t otf_table_size);

// (c) Ensquared energy, eq. 42: EOD of the centre pixel for a point source at
// its centre.
double ensquared_energy(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm, const PsfNumerics& numerics);

// True for powers of two in [64, 4096], the allowed psf_grid_size values.
bool valid_psf_grid_size(std::int64_t n);

}  // namespace eoir::sensor
