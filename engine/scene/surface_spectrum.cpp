#include "scene/surface_spectrum.hpp"

#include <algorithm>

#include "radiometry/planck.hpp"

namespace eoir::scene {
namespace {
radiometry::Brdf brdf_of(const universe::Material& m) {
  // Gray bodies are Lambertian, but for the Moon's (lunar_gray_body).
  if (m.gray_body && m.brdf.model != universe::BrdfModel::lunar_lommel_seeliger)
    return radiometry::Brdf(universe::BrdfParameters{});
  return radiometry::Brdf(m.brdf);
}
}  // namespace

SurfaceSpectrum::SurfaceSpectrum(const universe::Material& material, double gray_reflectance,
                                 const radiometry::SpectralView& view)
    : view_(&view), gray_(material.gray_body), gray_reflectance_(gray_reflectance), brdf_(brdf_of(material)) {
  const radiometry::SpectralBand& b = view.band;
  srf_ = gray_ ? std::vector<double>(static_cast<std::size_t>(b.intervals), gray_reflectance)
               : material.reflectance.interval_means(b.low_um, b.interval_um(), b.intervals);
  reflects_ = std::any_of(srf_.begin(), srf_.end(), [](double r) { return r > 0.0; });
  if (!srf_.empty()) max_srf_ = *std::max_element(srf_.begin(), srf_.end());
  if (!gray_ && view.integration == BandIntegration::grid) {
    std::vector<double> emissivity(srf_.size());
    for (std::size_t i = 0; i < srf_.size(); ++i)
      emissivity[i] = (1.0 - srf_[i]) * (view.transmittance.empty() ? 1.0 : view.transmittance[i]);
    emission_table_ = std::make_shared<const radiometry::BandPlanckTable>(view.band, view.sample_wavelengths_um,
                                                                          std::move(emissivity));
  }
}

void SurfaceSpectrum::add_emission(double temperature_K, std::vector<double>& out) const {
  if (gray_) {
    view_->add_gray_body_spectrum(temperature_K, gray_reflectance_, out);
    return;
  }
  const radiometry::SpectralBand& b = view_->band;
  const bool exact = view_->integration == BandIntegration::exact;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double B = exact ? radiometry::planck_band_radiance(temperature_K, b.grid_wavelength_um(static_cast<std::int64_t>(i)),
                                                              b.grid_wavelength_um(static_cast<std::int64_t>(i)) + b.interval_um()) /
                                 b.interval_um()
                           : radiometry::planck_radiance(view_->sample_wavelengths_um[i], temperature_K);
    out[i] += (1.0 - srf_[i]) * B;
  }
}

bool SurfaceSpectrum::emissivity(std::vector<double>& weights, double& scale) const {
  if (view_->integration != BandIntegration::grid) return false;
  weights.assign(srf_.size(), 1.0);
  scale = 1.0;
  if (gray_)
    scale = radiometry::emissivity_from_reflectance(gray_reflectance_);
  else
    for (std::size_t i = 0; i < srf_.size(); ++i) weights[i] = 1.0 - srf_[i];
  return true;
}

double SurfaceSpectrum::scaled_emission_radiance(double scale, double temperature_K) const {
  if (emission_table_ && view_->black_body && view_->integration != BandIntegration::exact)
    return radiometry::BandPlanckTable::blend(1.0 - scale, *view_->black_body, scale, *emission_table_,
                                              temperature_K);
  return (1.0 - scale) * view_->gray_body_radiance(temperature_K, 0.0) + scale * emission_radiance(temperature_K);
}

double SurfaceSpectrum::emission_radiance(double temperature_K) const {
  if (gray_) return view_->gray_body_radiance(temperature_K, gray_reflectance_);
  if (emission_table_) return emission_table_->radiance(temperature_K);
  thread_local std::vector<double> e;  // per-sample scratch: no allocation per call
  e.assign(srf_.size(), 0.0);
  add_emission(temperature_K, e);
  return view_->integrate(e);
}

}  // namespace eoir::scene
