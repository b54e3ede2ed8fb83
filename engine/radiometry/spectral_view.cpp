#include "radiometry/spectral_view.hpp"

#include "radiometry/planck.hpp"

namespace eoir::radiometry {

SpectralView SpectralView::make(double low_um, double high_um, std::int64_t intervals, BandIntegration integration,
                                SpectralQuadrature quadrature) {
  SpectralView v;
  v.band = SpectralBand{low_um, high_um, intervals};
  v.band.validate();
  v.integration = integration;
  v.quadrature = quadrature;
  v.sample_wavelengths_um = v.band.sample_wavelengths_um(quadrature);
  v.interval_um = v.band.interval_um();
  v.black_body = std::make_shared<const BandPlanckTable>(
      v.band, v.sample_wavelengths_um, std::vector<double>(v.sample_wavelengths_um.size(), 1.0));
  return v;
}

SpectralView SpectralView::through(const SpectralView& view, std::vector<double> transmittance) {
  SpectralView v = view;
  v.integration = BandIntegration::grid;
  v.transmittance = std::move(transmittance);
  v.black_body = std::make_shared<const BandPlanckTable>(v.band, v.sample_wavelengths_um, v.transmittance);
  return v;
}

double SpectralView::integrate(const std::vector<double>& spectral_values) const {
  // (a view not made by make, or a vector of another length: the checked
  // sum, which names what is wrong)
  if (!(interval_um > 0.0) || spectral_values.size() != static_cast<std::size_t>(band.intervals))
    return integrate_spectral_samples(band, spectral_values);
  if (transmittance.empty())
    return integrate_spectral_samples(interval_um, spectral_values.data(), spectral_values.size());
  thread_local std::vector<double> weighted;  // per-sample scratch: no allocation per call
  weighted.resize(spectral_values.size());
  for (std::size_t i = 0; i < weighted.size(); ++i) weighted[i] = spectral_values[i] * transmittance[i];
  return integrate_spectral_samples(interval_um, weighted.data(), weighted.size());
}

void SpectralView::add_gray_body_spectrum(double temperature_K, double reflectance, std::vector<double>& out) const {
  const double emissivity = emissivity_from_reflectance(reflectance);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] += emissivity * planck_radiance(sample_wavelengths_um[i], temperature_K);
}

double SpectralView::gray_body_radiance(double temperature_K, double reflectance) const {
  if (integration == BandIntegration::exact)
    return gray_body_band_radiance(emissivity_from_reflectance(reflectance), temperature_K, band.low_um,
                                   band.high_um);
  if (black_body) return emissivity_from_reflectance(reflectance) * black_body->radiance(temperature_K);
  thread_local std::vector<double> e;  // per-sample scratch: no allocation per call
  e.assign(sample_wavelengths_um.size(), 0.0);
  add_gray_body_spectrum(temperature_K, reflectance, e);
  return integrate(e);
}

}  // namespace eoir::radiometry
