#include "scene/surface_shader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/shape_intersect.hpp"

namespace eoir::scene {
namespace {
constexpr int kTableSize = 4096;
}

SurfaceShader::SurfaceShader(const FrameObject& object, const geometry::PlacedObject& placed, const SpectralView& view,
                             bool smooth)
    : object_(&object), placed_(&placed), view_(&view), smooth_(smooth) {
  for (const SurfacePoint& s : object.parts) part_radiance_.push_back(effective_radiance(s, view));
  if (!varying()) return;
  const ThermalField& th = object.thermal;
  patch_radiance_ = std::vector<std::atomic<double>>(placed.tessellation.patches.size());
  for (auto& value : patch_radiance_) value.store(std::numeric_limits<double>::quiet_NaN(), std::memory_order_relaxed);
  if (!smooth) return;
  table_T0_ = std::min(th.night_K, th.subsolar_K);
  table_dT_ = std::max(std::fabs(th.subsolar_K - th.night_K), 1e-9) / (kTableSize - 1);
  for (std::size_t p = 0; p < object.parts.size(); ++p) {
    std::vector<double> row(kTableSize + 1);
    for (int k = 0; k <= kTableSize; ++k)
      row[static_cast<std::size_t>(k)] =
          effective_radiance(SurfacePoint{table_T0_ + k * table_dT_, object.parts[p].reflectance}, view);
    table_.push_back(std::move(row));
  }
}

double SurfaceShader::radiance_of_temperature(std::int32_t part, double T) const {
  return effective_radiance(SurfacePoint{T, object_->part(part).reflectance}, *view_);
}

geometry::Vec3 SurfaceShader::normal_at(std::int32_t part, const geometry::Vec3& point_body) const {
  const geometry::ShapePart& sp = placed_->parts[index(part)];
  const geometry::Vec3 local = sp.orientation.conjugate() * (point_body - sp.offset_m);
  return (sp.orientation * geometry::shape_normal(geometry::shape_geom(sp), local)).normalized();
}

double SurfaceShader::temperature_at(std::int32_t part, const geometry::Vec3& point_body) const {
  const double uniform = object_->part(part).temperature_K;
  if (!varying()) return uniform;
  if (!smooth_) {
    const std::int32_t k = geometry::patch_at(placed_->tessellation, placed_->parts, part, point_body);
    return object_->thermal.at(placed_->tessellation.patches[static_cast<std::size_t>(k)].normal_body, uniform);
  }
  return object_->thermal.at(normal_at(part, point_body), uniform);
}

double SurfaceShader::radiance_at(std::int32_t part, const geometry::Vec3& point_body) const {
  if (!varying()) return part_radiance(part);
  if (!smooth_) return patch_radiance(geometry::patch_at(placed_->tessellation, placed_->parts, part, point_body));
  const double u = std::clamp((temperature_at(part, point_body) - table_T0_) / table_dT_, 0.0, double(kTableSize));
  const auto k = std::min(static_cast<std::size_t>(u), static_cast<std::size_t>(kTableSize - 1));
  const auto& row = table_[index(part)];
  return row[k] + (u - static_cast<double>(k)) * (row[k + 1] - row[k]);
}

double SurfaceShader::patch_radiance(std::int32_t patch) const {
  const geometry::Patch& p = placed_->tessellation.patches[static_cast<std::size_t>(patch)];
  if (!varying()) return part_radiance(p.part);
  std::atomic<double>& cached = patch_radiance_[static_cast<std::size_t>(patch)];
  double L = cached.load(std::memory_order_relaxed);
  if (std::isnan(L)) {  // two threads may both compute it: the same value
    L = radiance_of_temperature(p.part, object_->thermal.at(p.normal_body, object_->part(p.part).temperature_K));
    cached.store(L, std::memory_order_relaxed);
  }
  return L;
}

}  // namespace eoir::scene
