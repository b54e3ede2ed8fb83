// The effective radiance (eq. 48) leaving an object's surface, for the scene
// generator, picks and target metrics alike. Uniform surfaces have one value
// per shape part. Surfaces whose temperature varies (the subsolar model of
// spec 4.3.1.3) are shaded per patch dA in coarse mode (spec 4.2.1: the
// value at the patch's centre, computed once per patch) and at each
// sample's own surface point in smooth mode (4.2.2; through a table of L(T),
// which takes the place of interpolating between patches). Patch radiances
// are computed the first time a sample (or a patch sum) asks for them, so
// patches never hit are never shaded; lookups are safe from many threads.
#pragma once
#include <atomic>
#include <vector>

#include "geometry/scene_geometry.hpp"
#include "scene/frame.hpp"

namespace eoir::scene {

class SurfaceShader {
 public:
  SurfaceShader(const FrameObject& object, const geometry::PlacedObject& placed, const SpectralView& view,
                bool smooth);
  bool varying() const { return object_->thermal.subsolar; }
  // Uniform surfaces: the radiance of a part.
  double part_radiance(std::int32_t part) const { return part_radiance_[index(part)]; }
  // Any surface: the radiance and temperature at a point of `part` (body frame).
  double radiance_at(std::int32_t part, const geometry::Vec3& point_body) const;
  double temperature_at(std::int32_t part, const geometry::Vec3& point_body) const;
  // The radiance of patch k at its centre (for sums over patches).
  double patch_radiance(std::int32_t patch) const;

 private:
  static std::size_t index(std::int32_t part) { return static_cast<std::size_t>(part < 0 ? 0 : part); }
  geometry::Vec3 normal_at(std::int32_t part, const geometry::Vec3& point_body) const;
  double radiance_of_temperature(std::int32_t part, double T) const;
  const FrameObject* object_;
  const geometry::PlacedObject* placed_;
  const SpectralView* view_;
  bool smooth_;
  std::vector<double> part_radiance_;
  mutable std::vector<std::atomic<double>> patch_radiance_;  // varying surfaces; NaN until computed
  // Varying surfaces in smooth mode: L(T) per part on a uniform T grid.
  double table_T0_ = 0, table_dT_ = 1;
  std::vector<std::vector<double>> table_;
};

}  // namespace eoir::scene
