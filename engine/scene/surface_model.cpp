#include "scene/surface_model.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "scene/thermal_models.hpp"

namespace eoir::scene {

void Geography::locate(const Vec3& p, SurfacePoint& point) const {
  const double rho = std::sqrt(p.x() * p.x() + p.y() * p.y());
  point.longitude_deg = std::atan2(p.y(), p.x()) * constants::deg_per_rad;
  // The latitude as atan2(u, v), its sine and cosine u / |(u, v)|, v / |(u, v)|.
  const auto set_latitude = [&point](double u, double v) {
    point.latitude_deg = std::atan2(u, v) * constants::deg_per_rad;
    const double r = std::sqrt(u * u + v * v);
    point.sin_latitude = r > 0 ? u / r : 0.0;
    point.cos_latitude = r > 0 ? v / r : 1.0;
  };
  if (!geodetic) return set_latitude(p.z(), rho);
  // On the spheroid (a ray's hit) the geodetic latitude is the normal's
  // elevation, tan(lat) = (a/c)^2 z / rho; off it (a patch centre) WGS84's
  // geodetic inverse (GeographicLib).
  const double a = equatorial_radius_m, c = polar_radius_m;
  const double on_surface = (rho / a) * (rho / a) + (p.z() / c) * (p.z() / c) - 1.0;
  if (std::fabs(on_surface) <= 1e-12) return set_latitude(a * a * p.z(), c * c * rho);
  double h = 0;
  GeographicLib::Geocentric(a, (a - c) / a).Reverse(p.x(), p.y(), p.z(), point.latitude_deg, point.longitude_deg, h);
  const double lat = point.latitude_deg * constants::rad_per_deg;
  point.sin_latitude = std::sin(lat);
  point.cos_latitude = std::cos(lat);
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
    for (const PartSurface& s : parts_) reflects_ = reflects_ || (!s.emits_only && s.spectrum->reflects());
    for (const auto* s : geography_.class_spectra) reflects_ = reflects_ || (s && s->reflects());
    for (const auto* s : geography_.albedo_spectra) reflects_ = reflects_ || (s && s->reflects());
    if (geography_.clouds) reflects_ = reflects_ || geography_.cloud_spectrum->reflects();
  }
  for (const PartSurface& s : parts_)
    part_radiance_.push_back(!self_radiance_.empty()   ? view.integrate(self_radiance_)
                             : !s.self_radiance.empty() ? view.integrate(s.self_radiance)
                                                        : s.spectrum->emission_radiance(s.temperature_K));
  if (thermal_.subsolar && temperature_table_size > 0) {
    const auto n = temperature_table_size;
    table_T0_ = std::min(thermal_.night_K, thermal_.subsolar_K);
    table_dT_ = std::max(std::fabs(thermal_.subsolar_K - thermal_.night_K), 1e-9) / static_cast<double>(n - 1);
    for (const PartSurface& s : parts_) {
      std::vector<double> row(static_cast<std::size_t>(n + 1));
      for (std::int64_t k = 0; k <= n; ++k)
        row[static_cast<std::size_t>(k)] =
            s.spectrum->emission_radiance(table_T0_ + static_cast<double>(k) * table_dT_);
      table_.push_back(std::move(row));
    }
  }
  // The hottest the surface can be: its parts, eq. 12's subsolar point, the
  // airless night (below both), the climatology's day; one table step above
  // it for the L(T) table's last node. Every term eps_i B(lambda_i, T) of a
  // band integral grows with T.
  if (!self_radiance_.empty()) {
    emission_bound_ = std::numeric_limits<double>::infinity();
    return;
  }
  for (const PartSurface& s : parts_)
    if (!s.self_radiance.empty()) emission_bound_ = std::numeric_limits<double>::infinity();
  double hottest_K = 0;
  for (const PartSurface& s : parts_) hottest_K = std::max(hottest_K, s.temperature_K);
  if (thermal_.subsolar) hottest_K = std::max({hottest_K, thermal_.subsolar_K, thermal_.night_K}) + table_dT_;
  if (geography_.climatology) hottest_K = std::max(hottest_K, geography_.climatology_now.hottest_K());
  // The coldest: the climatology's day (every point of a central body with
  // one), eq. 12 falls to 0 K at the terminator (the airless night stays at
  // or above its minimum), else the coldest part.
  double coldest_K = std::numeric_limits<double>::infinity();
  for (const PartSurface& s : parts_) coldest_K = std::min(coldest_K, s.temperature_K);
  if (thermal_.subsolar) coldest_K = thermal_.airless_night ? thermal_.night_K : 0.0;
  if (geography_.climatology) coldest_K = geography_.climatology_now.coldest_K();
  emission_floor_ = std::numeric_limits<double>::infinity();
  const auto bound = [&](const SurfaceSpectrum* s) {
    if (!s) return;
    emission_bound_ = std::max(emission_bound_, s->emission_radiance(hottest_K));
    emission_floor_ = std::min(emission_floor_, coldest_K > 0 ? s->emission_radiance(coldest_K) : 0.0);
    if (!s->reflects()) return;
    const double max_srf = *std::max_element(s->srf().begin(), s->srf().end());
    srf_bound_ = std::max(srf_bound_, max_srf);
    reflection_bound_per_sr_ = std::max(reflection_bound_per_sr_, max_srf * s->brdf().max_projected_value_per_sr());
  };
  for (const PartSurface& s : parts_) bound(s.spectrum);
  for (const auto* s : geography_.class_spectra) bound(s);
  for (const auto* s : geography_.albedo_spectra) bound(s);
  // The land's brightness scales an SRF by up to min(1 / max SRF, the map's
  // largest value): the emission (1 - s) B + s eps B lies between the black
  // body's and the one at the top scale, the reflection grows with s.
  if (geography_.land_brightness) {
    const universe::RasterLevel& b = *geography_.land_brightness;
    const double map_top = b.value_offset() + 255.0 * b.value_scale();
    const auto scaled = [&](const SurfaceSpectrum* s) {
      if (!s || !(s->max_srf() > 0)) return;
      const double top = std::min(map_top, 1.0 / s->max_srf());
      emission_bound_ = std::max(emission_bound_, view.gray_body_radiance(hottest_K, 0.0));
      const double floor = coldest_K > 0 ? (1.0 - top) * view.gray_body_radiance(coldest_K, 0.0) +
                                               top * s->emission_radiance(coldest_K)
                                         : 0.0;
      emission_floor_ = std::min(emission_floor_, std::max(floor, 0.0));
      srf_bound_ = std::max(srf_bound_, top * s->max_srf());
      reflection_bound_per_sr_ =
          std::max(reflection_bound_per_sr_, top * s->max_srf() * s->brdf().max_projected_value_per_sr());
    };
    for (const PartSurface& s : parts_) scaled(s.spectrum);
    for (const auto* s : geography_.class_spectra) scaled(s);
  }
  // The cloud top: its own temperature (a blend lies between its layers).
  if (const SurfaceSpectrum* cloud = geography_.cloud_spectrum; cloud && geography_.clouds) {
    const double L = cloud->emission_radiance(geography_.cloud_temperature_K);
    cloud_emission_ = L;
    emission_bound_ = std::max(emission_bound_, L);
    emission_floor_ = std::min(emission_floor_, L);
    srf_bound_ = std::max(srf_bound_, cloud->max_srf());
    reflection_bound_per_sr_ =
        std::max(reflection_bound_per_sr_, cloud->max_srf() * cloud->brdf().max_projected_value_per_sr());
  }
}

SurfacePoint SurfaceModel::at(const SurfaceSite& site) const {
  SurfacePoint point = located(site);
  read_maps(point);
  return point;
}

SurfacePoint SurfaceModel::located(const SurfaceSite& site) const {
  SurfacePoint point{site, parts_[index(site.part)].spectrum};
  const Geography& g = geography_;
  if (g.bitmap() || g.clouds || (g.climatology && g.land_mask))
    g.locate(site.point_body_m, point);
  return point;
}

void SurfaceModel::prefetch_maps(const SurfacePoint& point) const {
  const Geography& g = geography_;
  for (const universe::RasterLevel* map : {g.land_cover, g.land_brightness, g.albedo})
    if (map) map->prefetch(point.latitude_deg, point.longitude_deg);
  if (g.climatology && g.land_mask) g.land_mask->prefetch(point.latitude_deg, point.longitude_deg);  // (temperature_K)
}

void SurfaceModel::read_maps(SurfacePoint& point) const {
  const Geography& g = geography_;
  if (g.clouds)  // (bilinear: the map's 0.7-deg cells are wider than a GEO view's samples)
    point.cloud_fraction = std::clamp(g.clouds->interpolated(point.latitude_deg, point.longitude_deg), 0.0, 1.0);
  if (g.land_cover) {
    constexpr std::uint8_t water = 17;  // IGBP water bodies (data/earth/README.md)
    const std::uint8_t c = g.land_cover->at(point.latitude_deg, point.longitude_deg);
    if (c < g.class_spectra.size() && g.class_spectra[c]) point.spectrum = g.class_spectra[c];
    if (g.land_brightness && c != water && point.spectrum->max_srf() > 0) {
      const universe::RasterLevel& b = *g.land_brightness;
      point.reflectance_scale =
          std::clamp(b.value_offset() + b.value_scale() * b.at(point.latitude_deg, point.longitude_deg), 0.0,
                     1.0 / point.spectrum->max_srf());
    }
  } else if (g.albedo) {
    if (const SurfaceSpectrum* s = g.albedo_spectra[g.albedo->at(point.latitude_deg, point.longitude_deg)])
      point.spectrum = s;
  }
}

double SurfaceModel::temperature_K(const SurfacePoint& point) const {
  const PartSurface& part = parts_[index(point.site.part)];
  if (part.emits_only) return part.temperature_K;  // a plume keeps its own, whatever the body's thermal model
  const Geography& g = geography_;
  if (!g.climatology || !g.land_mask) return thermal_.at(point.site.normal_body, part.temperature_K);
  const auto kind = g.land_mask->at(point.latitude_deg, point.longitude_deg) ? universe::SurfaceKind::land
                                                                             : universe::SurfaceKind::water;
  return g.climatology_now.tabulated_temperature_K(kind, point.latitude_deg, point.sin_latitude,
                                                   point.cos_latitude, point.longitude_deg);
}

void SurfaceModel::add_emission(const SurfacePoint& point, std::vector<double>& out) const {
  if (!self_radiance_.empty()) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += self_radiance_[i];
    return;
  }
  if (const std::vector<double>& own = parts_[index(point.site.part)].self_radiance; !own.empty()) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += own[i];
    return;
  }
  const double f = point.cloud_fraction, s = point.reflectance_scale;
  if (f == 0.0 && s == 1.0) return point.spectrum->add_emission(temperature_K(point), out);
  // Emissivity 1 - s SRF: (1 - s) B + s (1 - SRF) B; the cloud top's by its fraction.
  thread_local std::vector<double> black, surface, cloud;  // per-sample scratch
  const double T = temperature_K(point);
  black.assign(out.size(), 0.0);
  surface.assign(out.size(), 0.0);
  cloud.assign(out.size(), 0.0);
  if (f < 1.0) {
    view_->add_gray_body_spectrum(T, 0.0, black);
    point.spectrum->add_emission(T, surface);
  }
  if (f > 0.0) geography_.cloud_spectrum->add_emission(geography_.cloud_temperature_K, cloud);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] += (1.0 - f) * ((1.0 - s) * black[i] + s * surface[i]) + f * cloud[i];
}

double SurfaceModel::emission_radiance(const SurfacePoint& point) const {
  if (!varying() || !parts_[index(point.site.part)].self_radiance.empty()) return part_radiance(point.site.part);
  const double f = point.cloud_fraction, s = point.reflectance_scale;
  if (f == 0.0 && s == 1.0) return point.spectrum->emission_radiance(temperature_K(point));
  double L = 0;
  if (f < 1.0) {
    const double T = temperature_K(point);
    L = (1.0 - f) * point.spectrum->scaled_emission_radiance(s, T);
  }
  if (f > 0.0) L += f * cloud_emission_;
  return L;
}

void SurfaceModel::add_srf(const SurfacePoint& point, double weight, std::vector<double>& srf) const {
  const double f = point.cloud_fraction;
  if (point.spectrum->reflects()) {
    const double w = weight * (1.0 - f) * point.reflectance_scale;
    for (std::size_t i = 0; i < srf.size(); ++i) srf[i] += w * point.spectrum->srf()[i];
  }
  if (f > 0.0)
    for (std::size_t i = 0; i < srf.size(); ++i) srf[i] += weight * f * geography_.cloud_spectrum->srf()[i];
}

double SurfaceModel::emission_radiance_interpolated(const SurfacePoint& point) const {
  const PartSurface& part = parts_[index(point.site.part)];
  if (!part.self_radiance.empty()) return part_radiance(point.site.part);
  if (part.emits_only) return emission_radiance(point);  // (outside the L(T) table's range)
  if (!thermal_.subsolar || table_.empty() || geography_.bitmap() || geography_.climatology || geography_.clouds)
    return emission_radiance(point);
  const auto& row = table_[index(point.site.part)];
  const double last = static_cast<double>(row.size() - 1);
  const double u = std::clamp((temperature_K(point) - table_T0_) / table_dT_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(u), row.size() - 2);
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

}  // namespace eoir::scene
