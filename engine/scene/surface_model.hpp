// What one object's surface is made of and how hot it is (spec 4.1.4.1,
// 4.3.1.3): per shape part its material as the view sees it and its
// temperature, the thermal field that varies it, or a tabulated
// self-radiance (spec 4.1.4) in place of eps B(T). The world combines it with
// the light that reaches a point (eq. 4).
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "radiometry/spectral_view.hpp"
#include "scene/surface_spectrum.hpp"
#include "scene/thermal_field.hpp"

namespace eoir::scene {

using Vec3 = Eigen::Vector3d;

struct PartSurface {
  const SurfaceSpectrum* spectrum = nullptr;  // the world's, shared by parts of the same material
  double temperature_K = 0.0;                 // the uniform thermal model's (or the eclipse model's result)
};

class SurfaceModel {
 public:
  // self_radiance: the tabulated spectral radiance at the view's wavelengths
  // (interval means), or empty. temperature_table_size > 0 builds the L(T)
  // table of interpolated emission (smooth mode) where the temperature varies.
  SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal, std::vector<double> self_radiance,
               const radiometry::SpectralView& view, std::int64_t temperature_table_size);
  const PartSurface& part(std::int32_t i) const { return parts_[index(i)]; }
  std::size_t part_count() const { return parts_.size(); }
  // Some part reflects light in the band (SRF > 0 somewhere).
  bool reflects() const { return reflects_; }
  bool reflects(std::int32_t part) const { return self_radiance_.empty() && parts_[index(part)].spectrum->reflects(); }
  // The temperature varies over a part (the subsolar model).
  bool varying_temperature() const { return thermal_.subsolar; }
  // One radiance per part, whatever the point and the light.
  bool plain() const { return !reflects_ && !varying_temperature(); }

  double temperature_K(std::int32_t part, const Vec3& normal_body) const;
  // Self-emission eps B(T) (or the tabulated radiance) at the view's
  // wavelengths added to `out`, and its band integral (eq. 48; exact where
  // the view says), and the same through the L(T) table.
  void add_emission(std::int32_t part, const Vec3& normal_body, std::vector<double>& out) const;
  double emission_radiance(std::int32_t part, const Vec3& normal_body) const;
  double emission_radiance_interpolated(std::int32_t part, const Vec3& normal_body) const;
  // plain(): the effective radiance of a whole part.
  double part_radiance(std::int32_t part) const { return part_radiance_[index(part)]; }

 private:
  static std::size_t index(std::int32_t part) { return static_cast<std::size_t>(part < 0 ? 0 : part); }
  std::vector<PartSurface> parts_;
  ThermalField thermal_;
  std::vector<double> self_radiance_;
  const radiometry::SpectralView* view_;
  bool reflects_ = false;
  std::vector<double> part_radiance_;
  double table_T0_ = 0, table_dT_ = 1;
  std::vector<std::vector<double>> table_;  // per part, L at T0 + k dT
};

}  // namespace eoir::scene
