#include "scene/surface_model.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "core/vector_math.hpp"
#include "scene/thermal_models.hpp"

namespace eoir::scene {

void Geography::locate(SurfacePoint* const* points, std::size_t n) const {
  // Each point's longitude atan2(y, x) and latitude atan2(u, v); the angles
  // of a batch at once (vector maths, core/vector_math.hpp), one point's by
  // libm. (The two may differ by rounding: a patch centre of a central body
  // lies on its maps' cell edges, where rounding picks the cell, so points
  // located one by one keep libm's angles.)
  constexpr std::size_t kBatch = 64;
  double y[2 * kBatch], x[2 * kBatch], angle[2 * kBatch];
  bool off_surface[kBatch];
  const double a = equatorial_radius_m, c = polar_radius_m;
  for (std::size_t first = 0; first < n; first += kBatch) {
    const std::size_t m = std::min(kBatch, n - first);
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3& p = points[first + k]->site.point_body_m;
      const double rho = std::sqrt(p.x() * p.x() + p.y() * p.y());
      y[k] = p.y();
      x[k] = p.x();
      y[kBatch + k] = p.z();  // planetocentric: atan2(z, rho)
      x[kBatch + k] = rho;
      off_surface[k] = false;
      if (!geodetic) continue;
      // On the spheroid (a ray's hit) the geodetic latitude is the normal's
      // elevation, tan(lat) = (a/c)^2 z / rho; off it (a patch centre)
      // WGS84's geodetic inverse (GeographicLib), below.
      const double on_surface = (rho / a) * (rho / a) + (p.z() / c) * (p.z() / c) - 1.0;
      off_surface[k] = !(std::fabs(on_surface) <= 1e-12);
      y[kBatch + k] = a * a * p.z();
      x[kBatch + k] = c * c * rho;
    }
    if (m < kBatch) {  // the latitudes' arguments follow the longitudes'
      std::copy_n(y + kBatch, m, y + m);
      std::copy_n(x + kBatch, m, x + m);
    }
    if (n > 1) {
      vector_math::atan2(y, x, angle, 2 * m);
    } else {
      angle[0] = std::atan2(y[0], x[0]);
      angle[1] = std::atan2(y[1], x[1]);
    }
    for (std::size_t k = 0; k < m; ++k) {
      SurfacePoint& point = *points[first + k];
      if (off_surface[k]) {
        const Vec3& p = point.site.point_body_m;
        double h = 0;
        GeographicLib::Geocentric(a, (a - c) / a)
            .Reverse(p.x(), p.y(), p.z(), point.latitude_deg, point.longitude_deg, h);
        const double lat = point.latitude_deg * constants::rad_per_deg;
        point.sin_latitude = std::sin(lat);
        point.cos_latitude = std::cos(lat);
        continue;
      }
      point.longitude_deg = angle[k] * constants::deg_per_rad;
      // The latitude's sine and cosine u / |(u, v)|, v / |(u, v)|.
      const double u = y[m + k], v = x[m + k], r = std::sqrt(u * u + v * v);
      point.latitude_deg = angle[m + k] * constants::deg_per_rad;
      point.sin_latitude = r > 0 ? u / r : 0.0;
      point.cos_latitude = r > 0 ? v / r : 1.0;
    }
  }
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
  mask_on_cover_cells_ = geography_.land_cover && geography_.land_mask &&
                         geography_.land_cover->same_grid(*geography_.land_mask);
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
    brdf_bound_per_sr_ = std::max(brdf_bound_per_sr_, s->brdf().max_projected_value_per_sr());
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
    brdf_bound_per_sr_ = std::max(brdf_bound_per_sr_, cloud->brdf().max_projected_value_per_sr());
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
  SurfacePoint point = unlocated(site);
  SurfacePoint* one = &point;
  locate(&one, 1);
  return point;
}

void SurfaceModel::prefetch_maps(const SurfacePoint& point) const {
  const Geography& g = geography_;
  const bool mask = g.climatology && g.land_mask;  // (the land mask: temperature_term)
  if (g.land_cover) {
    const universe::RasterLevel::Cell cell = g.land_cover->cell_of(point.latitude_deg, point.longitude_deg);
    g.land_cover->prefetch(cell);
    if (mask && mask_on_cover_cells_) g.land_mask->prefetch(cell);
  }
  for (const universe::RasterLevel* map : {g.land_brightness, g.albedo, mask && !mask_on_cover_cells_ ? g.land_mask : nullptr})
    if (map) map->prefetch(point.latitude_deg, point.longitude_deg);
}

void SurfaceModel::read_maps(SurfacePoint& point) const {
  const Geography& g = geography_;
  const bool mask = g.climatology && g.land_mask;
  if (g.clouds)  // (bilinear: the map's 0.7-deg cells are wider than a GEO view's samples)
    point.cloud_fraction = std::clamp(g.clouds->interpolated(point.latitude_deg, point.longitude_deg), 0.0, 1.0);
  if (mask && !mask_on_cover_cells_) point.on_land = g.land_mask->at(point.latitude_deg, point.longitude_deg) != 0;
  if (g.land_cover) {
    constexpr std::uint8_t water = 17;  // IGBP water bodies (data/earth/README.md)
    const universe::RasterLevel::Cell cell = g.land_cover->cell_of(point.latitude_deg, point.longitude_deg);
    if (mask && mask_on_cover_cells_) point.on_land = g.land_mask->at(cell) != 0;
    const std::uint8_t c = g.land_cover->at(cell);
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

TemperatureTerm SurfaceModel::temperature_term(const SurfacePoint& point) const {
  const PartSurface& part = parts_[index(point.site.part)];
  // (a plume keeps its own, whatever the body's thermal model)
  if (part.emits_only) return TemperatureTerm::constant(part.temperature_K);
  const Geography& g = geography_;
  if (!g.climatology || !g.land_mask)
    return TemperatureTerm::constant(thermal_.at(point.site.normal_body, part.temperature_K));
  const auto kind = point.on_land ? universe::SurfaceKind::land : universe::SurfaceKind::water;  // (read_maps)
  return g.climatology_now.latitude_table(kind).temperature_term(point.latitude_deg, point.sin_latitude,
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

template <class TemperatureK>
double SurfaceModel::emission_radiance(const SurfacePoint& point, TemperatureK temperature) const {
  if (!varying() || !parts_[index(point.site.part)].self_radiance.empty()) return part_radiance(point.site.part);
  const double f = point.cloud_fraction, s = point.reflectance_scale;
  if (f == 0.0 && s == 1.0) return point.spectrum->emission_radiance(temperature());
  double L = 0;
  if (f < 1.0) L = (1.0 - f) * point.spectrum->scaled_emission_radiance(s, temperature());
  if (f > 0.0) L += f * cloud_emission_;
  return L;
}

double SurfaceModel::emission_radiance(const SurfacePoint& point) const {
  return emission_radiance(point, [&] { return temperature_K(point); });
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

template <class TemperatureK>
double SurfaceModel::emission_radiance_interpolated(const SurfacePoint& point, TemperatureK temperature) const {
  const PartSurface& part = parts_[index(point.site.part)];
  if (!part.self_radiance.empty()) return part_radiance(point.site.part);
  if (part.emits_only) return emission_radiance(point, temperature);  // (outside the L(T) table's range)
  if (!thermal_.subsolar || table_.empty() || geography_.bitmap() || geography_.climatology || geography_.clouds)
    return emission_radiance(point, temperature);
  const auto& row = table_[index(point.site.part)];
  const double last = static_cast<double>(row.size() - 1);
  const double u = std::clamp((temperature() - table_T0_) / table_dT_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(u), row.size() - 2);
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

void SurfaceModel::emission_radiances(const SurfacePoint* const* points, std::size_t n, bool interpolated,
                                      double* out) const {
  constexpr std::size_t kBatch = 64;
  TemperatureTerm terms[kBatch];
  double T[kBatch];
  for (std::size_t first = 0; first < n; first += kBatch) {
    const std::size_t m = std::min(kBatch, n - first);
    // (only where the emission reads a temperature: a varying surface's parts
    // without a tabulated radiance, as emission_radiance)
    for (std::size_t k = 0; k < m; ++k)
      terms[k] = varying() && parts_[index(points[first + k]->site.part)].self_radiance.empty()
                     ? temperature_term(*points[first + k])
                     : TemperatureTerm::constant(0.0);
    temperature_terms_K(terms, m, T);
    for (std::size_t k = 0; k < m; ++k) {
      const auto temperature = [&] { return T[k]; };
      out[first + k] = interpolated ? emission_radiance_interpolated(*points[first + k], temperature)
                                    : emission_radiance(*points[first + k], temperature);
    }
  }
}

}  // namespace eoir::scene
