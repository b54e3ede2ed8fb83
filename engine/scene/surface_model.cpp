#include "scene/surface_model.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::scene {

SurfaceModel::SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal, std::vector<double> self_radiance,
                           const radiometry::SpectralView& view, std::int64_t temperature_table_size)
    : parts_(std::move(parts)), thermal_(thermal), self_radiance_(std::move(self_radiance)), view_(&view) {
  if (!self_radiance_.empty()) thermal_.subsolar = false;  // a tabulated radiance has no temperature
  for (std::size_t p = 0; p < parts_.size(); ++p) reflects_ = reflects_ || reflects(static_cast<std::int32_t>(p));
  for (const PartSurface& s : parts_)
    part_radiance_.push_back(self_radiance_.empty() ? s.spectrum->emission_radiance(s.temperature_K)
                                                    : view.integrate(self_radiance_));
  if (!varying_temperature() || temperature_table_size <= 0) return;
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

double SurfaceModel::temperature_K(std::int32_t part, const Vec3& normal_body) const {
  return thermal_.at(normal_body, parts_[index(part)].temperature_K);
}

void SurfaceModel::add_emission(std::int32_t part, const Vec3& normal_body, std::vector<double>& out) const {
  if (!self_radiance_.empty()) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += self_radiance_[i];
    return;
  }
  parts_[index(part)].spectrum->add_emission(temperature_K(part, normal_body), out);
}

double SurfaceModel::emission_radiance(std::int32_t part, const Vec3& normal_body) const {
  if (!varying_temperature()) return part_radiance(part);
  return parts_[index(part)].spectrum->emission_radiance(temperature_K(part, normal_body));
}

double SurfaceModel::emission_radiance_interpolated(std::int32_t part, const Vec3& normal_body) const {
  if (!varying_temperature() || table_.empty()) return emission_radiance(part, normal_body);
  const auto& row = table_[index(part)];
  const double last = static_cast<double>(row.size() - 1);
  const double u = std::clamp((temperature_K(part, normal_body) - table_T0_) / table_dT_, 0.0, last);
  const auto k = std::min(static_cast<std::size_t>(u), row.size() - 2);
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

}  // namespace eoir::scene
