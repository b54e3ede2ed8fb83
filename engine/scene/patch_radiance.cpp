#include "scene/patch_radiance.hpp"

#include "radiometry/planck.hpp"

namespace eoir::scene {

SpectralView SpectralView::make(double low_um, double high_um, std::int64_t intervals, BandIntegration integration) {
  SpectralView v;
  v.band = radiometry::SpectralBand{low_um, high_um, intervals};
  v.band.validate();
  v.integration = integration;
  v.sample_wavelengths_um = v.band.sample_wavelengths_um();
  return v;
}

std::vector<double> spectral_radiance(const SurfacePoint& s, const SpectralView& view) {
  const double emissivity = radiometry::emissivity_from_reflectance(s.reflectance);
  std::vector<double> out(view.sample_wavelengths_um.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = emissivity * radiometry::planck_radiance(view.sample_wavelengths_um[i], s.temperature_K);
  return out;
}

double effective_radiance(const SurfacePoint& s, const SpectralView& view) {
  if (view.integration == BandIntegration::exact)
    return radiometry::gray_body_band_radiance(radiometry::emissivity_from_reflectance(s.reflectance),
                                               s.temperature_K, view.band.low_um, view.band.high_um);
  return radiometry::integrate_spectral_samples(view.band, spectral_radiance(s, view));
}

}  // namespace eoir::scene
