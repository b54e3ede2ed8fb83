// Spectral bandpass and sampling grid (spec 5.3).
#pragma once
#include <cstdint>
#include <vector>

namespace eoir::sensor {

struct SpectralGrid {
  double low_um = 0, high_um = 0;
  std::int64_t intervals = 0;

  // Delta lambda = (lambda_high - lambda_low) / N_intervals (spec 5.3).
  double interval_um() const { return (high_um - low_um) / static_cast<double>(intervals); }
  // lambda_i = lambda_low + i * Delta lambda, i = 0 .. N_intervals - 1 (spec 5.3).
  double wavelength_um(std::int64_t i) const { return low_um + static_cast<double>(i) * interval_um(); }
  // Centre of interval i, lambda_low + (i + 1/2) Delta lambda (midpoint rule).
  double centre_um(std::int64_t i) const { return low_um + (static_cast<double>(i) + 0.5) * interval_um(); }
  std::vector<double> wavelengths_um() const;
  std::vector<double> centres_um() const;
};

}  // namespace eoir::sensor
