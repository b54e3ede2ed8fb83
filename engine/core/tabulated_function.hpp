// A tabulated function of wavelength: values at strictly increasing
// wavelengths (um), linear between them, 0 outside. The measured solar
// spectrum (spec 4.1.4, eq. 6), material reflectances (4.1.4.1) and
// user-supplied spectral radiances are all tables.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace eoir {

class TabulatedFunction {
 public:
  TabulatedFunction() = default;
  // Throws eoir::Error(out_of_range) naming `field` ("spectrum" by default)
  // unless there are >= 2 finite points with strictly increasing wavelengths.
  TabulatedFunction(std::vector<double> wavelength_um, std::vector<double> value,
                    const std::string& field = "spectrum");
  double operator()(double wavelength_um) const;
  // Exact integral of the piecewise-linear table over [low, high] (um times
  // the value's unit).
  double integral(double low_um, double high_um) const;
  // Means over `count` consecutive intervals of `width` starting at `low`:
  // the spectral vector whose rectangle sum on the spectral grid (spec 5.3)
  // equals the exact integral, whatever fine structure lies between points.
  std::vector<double> interval_means(double low_um, double width_um, std::int64_t count) const;
  const std::vector<double>& wavelengths_um() const { return wavelength_um_; }
  const std::vector<double>& values() const { return value_; }
  bool empty() const { return wavelength_um_.empty(); }

 private:
  std::vector<double> wavelength_um_;
  std::vector<double> value_;
};

}  // namespace eoir
