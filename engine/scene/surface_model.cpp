#include "scene/surface_model.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::scene {

SurfaceModel::SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal,
                           const radiometry::SpectralView& view, std::int64_t temperature_table_size)
    : parts_(std::move(parts)), thermal_(thermal), view_(&view) {
  for (const PartSurface& s : parts_) part_radiance_.push_back(view.gray_body_radiance(s.temperature_K, s.reflectance));
  if (!varying() || temperature_table_size <= 0) return;
  const auto n = temperature_table_size;
  table_T0_ = std::min(thermal_.night_K, thermal_.subsolar_K);
  table_dT_ = std::max(std::fabs(thermal_.subsolar_K - thermal_.night_K), 1e-9) / static_cast<double>(n - 1);
  for (const PartSurface& s : parts_) {
    std::vector<double> row(static_cast<std::size_t>(n + 1));
    for (std::int64_t k = 0; k <= n; ++k)
      row[static_cast<std::size_t>(k)] =
          view.gray_body_radiance(table_T0_ + static_cast<double>(k) * table_dT_, s.reflectance);
    table_.push_back(std::move(row));
  }
}

double SurfaceModel::temperature_K(std::int32_t part, const Vec3& normal_body) const {
  return thermal_.at(normal_body, parts_[index(part)].temperature_K);
}

std::vector<double> SurfaceModel::spectral_radiance(std::int32_t part, const Vec3& normal_body) const {
  return view_->gray_body_spectrum(temperature_K(part, normal_body), parts_[index(part)].reflectance);
}

double SurfaceModel::effective_radiance(std::int32_t part, const Vec3& normal_body) const {
  if (!varying()) return part_radiance(part);
  return view_->gray_body_radiance(temperature_K(part, normal_body), parts_[index(part)].reflectance);
}

double SurfaceModel::effective_radiance_interpolated(std::int32_t part, const Vec3& normal_body) const {
  if (!varying() || table_.empty()) return effective_radiance(part, normal_body);
  const auto& row = table_[index(part)];
  const double last = static_cast<double>(row.size() - 1);
  const double u = std::clamp((temperature_K(part, normal_body) - table_T0_) / table_dT_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(u), row.size() - 2);
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

}  // namespace eoir::scene
