#include "sensor/spectral_grid.hpp"

namespace eoir::sensor {

std::vector<double> SpectralGrid::wavelengths_um() const {
  std::vector<double> out(static_cast<std::size_t>(intervals));
  for (std::int64_t i = 0; i < intervals; ++i) out[static_cast<std::size_t>(i)] = wavelength_um(i);
  return out;
}

std::vector<double> SpectralGrid::centres_um() const {
  std::vector<double> out(static_cast<std::size_t>(intervals));
  for (std::int64_t i = 0; i < intervals; ++i) out[static_cast<std::size_t>(i)] = centre_um(i);
  return out;
}

}  // namespace eoir::sensor
