// What one object's surface is made of and how hot it is (spec 4.1.4.1,
// 4.3.1.3), and the radiance it sends toward the observer (spec 4.1.5.3,
// eq. 4). The one radiance path: images, picks, point sources and target
// metrics all evaluate it here. Today eq. 4 holds its self-emission term,
// eps_lambda B_lambda(T) with eps = 1 - SRF for gray bodies; the reflected
// and background terms join it here.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "radiometry/spectral_view.hpp"
#include "scene/thermal_field.hpp"

namespace eoir::scene {

using Vec3 = Eigen::Vector3d;

// The material of one shape part: uniform temperature (the uniform thermal
// model) and gray-body spectral reflectance.
struct PartSurface {
  double temperature_K = 0.0;
  double reflectance = 0.0;
};

class SurfaceModel {
 public:
  // `view` must outlive the model. temperature_table_size > 0 builds the
  // L(T) table of interpolated shading (smooth mode) for varying surfaces.
  SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal, const radiometry::SpectralView& view,
               std::int64_t temperature_table_size);
  // True where the radiance varies over a part (the subsolar model).
  bool varying() const { return thermal_.subsolar; }
  const PartSurface& part(std::int32_t i) const { return parts_[index(i)]; }
  std::size_t part_count() const { return parts_.size(); }

  // At a point of `part` whose outward normal is normal_body (body frame):
  double temperature_K(std::int32_t part, const Vec3& normal_body) const;
  // eq. 4 at the view's sample wavelengths, W cm^-2 sr^-1 um^-1;
  std::vector<double> spectral_radiance(std::int32_t part, const Vec3& normal_body) const;
  // its band integral (eq. 48), W cm^-2 sr^-1 (exact when the view says so);
  double effective_radiance(std::int32_t part, const Vec3& normal_body) const;
  // the same through the L(T) table (the smooth shading of varying surfaces).
  double effective_radiance_interpolated(std::int32_t part, const Vec3& normal_body) const;
  // Uniform surfaces: the effective radiance of a whole part.
  double part_radiance(std::int32_t part) const { return part_radiance_[index(part)]; }

 private:
  static std::size_t index(std::int32_t part) { return static_cast<std::size_t>(part < 0 ? 0 : part); }
  std::vector<PartSurface> parts_;
  ThermalField thermal_;
  const radiometry::SpectralView* view_;
  std::vector<double> part_radiance_;
  double table_T0_ = 0, table_dT_ = 1;
  std::vector<std::vector<double>> table_;  // per part, L at T0 + k dT
};

}  // namespace eoir::scene
