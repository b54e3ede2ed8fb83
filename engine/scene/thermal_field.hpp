// How an object's surface temperature varies over its surface (spec 4.3.1.3).
#pragma once
#include <Eigen/Core>
#include <cmath>

#include "scene/thermal_models.hpp"

namespace eoir::scene {

struct ThermalField {
  bool subsolar = false;  // eq. 12 by day; otherwise each part's own temperature
  double subsolar_K = 0, night_K = 0;
  Eigen::Vector3d sun_body = Eigen::Vector3d::UnitX();  // unit vector toward the Sun, body frame
  // Central bodies: the night side cools from dusk toward night_K at dawn as
  // T^(-1/4) of the time in shadow (scene/thermal_models.hpp); other objects
  // keep night_K all night.
  bool airless_night = false;
  Eigen::Vector3d spin_axis_body = Eigen::Vector3d::UnitZ();
  double solar_day_s = 0;
  // Temperature where the outward surface normal is n (body frame).
  double at(const Eigen::Vector3d& normal_body, double uniform_K) const {
    if (!subsolar) return uniform_K;
    if (airless_night)
      return airless_surface_temperature_K(AirlessThermal{subsolar_K, night_K, solar_day_s}, normal_body, sun_body,
                                           spin_axis_body);
    const double c = normal_body.dot(sun_body);
    return c > 0 ? subsolar_K * std::pow(c, 0.25) : night_K;  // T_ss cos^(1/4)(phi)
  }
};

}  // namespace eoir::scene
