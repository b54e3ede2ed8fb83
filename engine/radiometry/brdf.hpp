// PLACEHOLDER (replaced by the BRDF of eq. 1): Lambertian only.
#pragma once
#include <Eigen/Core>

#include "core/constants.hpp"
#include "universe/material.hpp"

namespace eoir::radiometry {
class Brdf {
 public:
  explicit Brdf(const universe::BrdfParameters& p) : p_(p) {}
  double value(const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&) const { return 1.0 / constants::pi; }
  const universe::BrdfParameters& parameters() const { return p_; }

 private:
  universe::BrdfParameters p_;
};
}  // namespace eoir::radiometry
