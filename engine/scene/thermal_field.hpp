// How an object's surface temperature varies over its surface (spec 4.3.1.3).
#pragma once
#include <Eigen/Core>
#include <cmath>

namespace eoir::scene {

struct ThermalField {
  bool subsolar = false;  // eq. 12; otherwise each part's own temperature
  double subsolar_K = 0, night_K = 0;
  Eigen::Vector3d sun_body = Eigen::Vector3d::UnitX();  // unit vector toward the Sun, body frame
  // Temperature where the outward surface normal is n (body frame).
  double at(const Eigen::Vector3d& normal_body, double uniform_K) const {
    if (!subsolar) return uniform_K;
    const double c = normal_body.dot(sun_body);
    return c > 0 ? subsolar_K * std::pow(c, 0.25) : night_K;  // T_ss cos^(1/4)(phi)
  }
};

}  // namespace eoir::scene
