#include "core/tabulated_function.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace eoir {

TabulatedFunction::TabulatedFunction(std::vector<double> wavelength_um, std::vector<double> value,
                                     const std::string& field)
    : wavelength_um_(std::move(wavelength_um)), value_(std::move(value)) {
  if (wavelength_um_.size() != value_.size() || wavelength_um_.size() < 2)
    throw Error(Status::out_of_range, field + ": need >= 2 points and as many values as wavelengths");
  for (std::size_t i = 0; i < wavelength_um_.size(); ++i) {
    require_finite(wavelength_um_[i], field + ".wavelength_um[" + std::to_string(i) + "]");
    require_finite(value_[i], field + ".value[" + std::to_string(i) + "]");
    if (i > 0 && !(wavelength_um_[i] > wavelength_um_[i - 1]))
      throw Error(Status::out_of_range, field + ".wavelength_um: not strictly increasing at index " +
                                            std::to_string(i));
  }
}

double TabulatedFunction::operator()(double wavelength_um) const {
  if (wavelength_um_.empty() || !(wavelength_um >= wavelength_um_.front()) || wavelength_um > wavelength_um_.back())
    return 0.0;
  const auto it = std::upper_bound(wavelength_um_.begin(), wavelength_um_.end(), wavelength_um);
  const std::size_t i =
      it == wavelength_um_.end() ? wavelength_um_.size() - 1 : static_cast<std::size_t>(it - wavelength_um_.begin());
  if (i == 0) return value_.front();
  const double f = (wavelength_um - wavelength_um_[i - 1]) / (wavelength_um_[i] - wavelength_um_[i - 1]);
  return value_[i - 1] + f * (value_[i] - value_[i - 1]);
}

double TabulatedFunction::integral(double low_um, double high_um) const {
  if (wavelength_um_.empty() || !(high_um > low_um)) return 0.0;
  const double a = std::max(low_um, wavelength_um_.front()), b = std::min(high_um, wavelength_um_.back());
  if (!(b > a)) return 0.0;
  // Trapezoids between a, the table points inside (a, b), and b: exact for
  // the piecewise-linear table.
  double sum = 0.0, x0 = a, y0 = (*this)(a);
  auto it = std::upper_bound(wavelength_um_.begin(), wavelength_um_.end(), a);
  for (; it != wavelength_um_.end() && *it < b; ++it) {
    const double x1 = *it, y1 = value_[static_cast<std::size_t>(it - wavelength_um_.begin())];
    sum += 0.5 * (y0 + y1) * (x1 - x0);
    x0 = x1;
    y0 = y1;
  }
  return sum + 0.5 * (y0 + (*this)(b)) * (b - x0);
}

std::vector<double> TabulatedFunction::interval_means(double low, double width, std::int64_t count) const {
  std::vector<double> out(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    const double a = low + static_cast<double>(i) * width;
    out[static_cast<std::size_t>(i)] = integral(a, a + width) / width;
  }
  return out;
}

}  // namespace eoir
