#include "scene/surface_model.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "scene/thermal_models.hpp"

namespace eoir::scene {

void Geography::latitude_longitude_deg(const Vec3& p, double& latitude_deg, double& longitude_deg) const {
  if (geodetic) {
    double h = 0;
    const double a = equatorial_radius_m, f = (a - polar_radius_m) / a;
    GeographicLib::Geocentric(a, f).Reverse(p.x(), p.y(), p.z(), latitude_deg, longitude_deg, h);
    return;
  }
  latitude_deg = std::atan2(p.z(), std::hypot(p.x(), p.y())) * constants::deg_per_rad;
  longitude_deg = std::atan2(p.y(), p.x()) * constants::deg_per_rad;
}

SurfaceModel::SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal, std::vector<double> self_radiance,
                           Geography geography, const radiometry::SpectralView& view,
                           std::int64_t temperature_table_size)
    : parts_(std::move(parts)),
      thermal_(thermal),
      self_radiance_(std::move(self_radiance)),
      geography_(std::move(geography)),
      view_(&view) {
  if (!self_radiance_.empty()) {  // a tabulated radiance has no temperature and reflects nothing
    thermal_.subsolar = false;
    geography_ = Geography{};
  }
  if (self_radiance_.empty()) {
    for (const PartSurface& s : parts_) reflects_ = reflects_ || s.spectrum->reflects();
    for (const auto* s : geography_.class_spectra) reflects_ = reflects_ || (s && s->reflects());
    for (const auto* s : geography_.albedo_spectra) reflects_ = reflects_ || (s && s->reflects());
  }
  for (const PartSurface& s : parts_)
    part_radiance_.push_back(self_radiance_.empty() ? s.spectrum->emission_radiance(s.temperature_K)
                                                    : view.integrate(self_radiance_));
  if (!thermal_.subsolar || temperature_table_size <= 0) return;
  const auto n = temperature_table_size;
  table_T0_ = std::min(thermal_.night_K, thermal_.subsolar_K);
  table_dT_ = std::max(std::fabs(thermal_.subsolar_K - thermal_.night_K), 1e-9) / static_cast<double>(n - 1);
  for (const PartSurface& s : parts_) {
    std::vector<double> row(static_cast<std::size_t>(n + 1));
    for (std::int64_t k = 0; k <= n; ++k)
      row[static_cast<std::size_t>(k)] = s.spectrum->emission_radiance(table_T0_ + static_cast<double>(k) * table_dT_);
    table_.push_back(std::move(row));
  }
}

const SurfaceSpectrum& SurfaceModel::spectrum(const SurfaceSite& site) const {
  const Geography& g = geography_;
  if (g.bitmap()) {
    double lat = 0, lon = 0;
    g.latitude_longitude_deg(site.point_body_m, lat, lon);
    if (g.land_cover) {
      const std::uint8_t c = g.land_cover->at(lat, lon);
      if (c < g.class_spectra.size() && g.class_spectra[c]) return *g.class_spectra[c];
    } else {
      const SurfaceSpectrum* s = g.albedo_spectra[g.albedo->at(lat, lon)];
      if (s) return *s;
    }
  }
  return *parts_[index(site.part)].spectrum;
}

double SurfaceModel::temperature_K(const SurfaceSite& site) const {
  const Geography& g = geography_;
  if (g.climatology && g.land_mask) {
    double lat = 0, lon = 0;
    g.latitude_longitude_deg(site.point_body_m, lat, lon);
    const auto kind = g.land_mask->at(lat, lon) ? universe::SurfaceKind::land : universe::SurfaceKind::water;
    return surface_temperature_K(*g.climatology, kind, lat, lon, g.calendar);
  }
  return thermal_.at(site.normal_body, parts_[index(site.part)].temperature_K);
}

void SurfaceModel::add_emission(const SurfaceSite& site, std::vector<double>& out) const {
  if (!self_radiance_.empty()) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += self_radiance_[i];
    return;
  }
  spectrum(site).add_emission(temperature_K(site), out);
}

double SurfaceModel::emission_radiance(const SurfaceSite& site) const {
  if (!varying()) return part_radiance(site.part);
  return spectrum(site).emission_radiance(temperature_K(site));
}

double SurfaceModel::emission_radiance_interpolated(const SurfaceSite& site) const {
  if (!thermal_.subsolar || table_.empty() || geography_.bitmap() || geography_.climatology)
    return emission_radiance(site);
  const auto& row = table_[index(site.part)];
  const double last = static_cast<double>(row.size() - 1);
  const double u = std::clamp((temperature_K(site) - table_T0_) / table_dT_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(u), row.size() - 2);
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

}  // namespace eoir::scene
