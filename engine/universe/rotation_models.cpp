#include "universe/rotation_models.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "core/constants.hpp"

namespace eoir::universe {
namespace {
double sind(double deg) { return std::sin(deg * constants::rad_per_deg); }
double cosd(double deg) { return std::cos(deg * constants::rad_per_deg); }

// The Moon (IAU 2000 report, the 13 arguments E1..E13).
RotationalElements moon(double d, double T) {
  const double E1 = 125.045 - 0.0529921 * d, E2 = 250.089 - 0.1059842 * d, E3 = 260.008 + 13.0120009 * d,
               E4 = 176.625 + 13.3407154 * d, E5 = 357.529 + 0.9856003 * d, E6 = 311.589 + 26.4057084 * d,
               E7 = 134.963 + 13.0649930 * d, E8 = 276.617 + 0.3287146 * d, E9 = 34.226 + 1.7484877 * d,
               E10 = 15.134 - 0.1589763 * d, E11 = 119.743 + 0.0036096 * d, E12 = 239.961 + 0.1643573 * d,
               E13 = 25.053 + 12.9590088 * d;
  RotationalElements r;
  r.pole_ra_deg = 269.9949 + 0.0031 * T - 3.8787 * sind(E1) - 0.1204 * sind(E2) + 0.0700 * sind(E3) -
                  0.0172 * sind(E4) + 0.0072 * sind(E6) - 0.0052 * sind(E10) + 0.0043 * sind(E13);
  r.pole_dec_deg = 66.5392 + 0.0130 * T + 1.5419 * cosd(E1) + 0.0239 * cosd(E2) - 0.0278 * cosd(E3) +
                   0.0068 * cosd(E4) - 0.0029 * cosd(E6) + 0.0009 * cosd(E7) + 0.0008 * cosd(E10) - 0.0009 * cosd(E13);
  r.prime_meridian_deg = 38.3213 + 13.17635815 * d - 1.4e-12 * d * d + 3.5610 * sind(E1) + 0.1208 * sind(E2) -
                         0.0642 * sind(E3) + 0.0158 * sind(E4) + 0.0252 * sind(E5) - 0.0066 * sind(E6) -
                         0.0047 * sind(E7) - 0.0046 * sind(E8) + 0.0028 * sind(E9) + 0.0052 * sind(E10) +
                         0.0040 * sind(E11) + 0.0019 * sind(E12) - 0.0044 * sind(E13);
  return r;
}
}  // namespace

RotationalElements rotational_elements(CentralBody body, const EngineTime& t) {
  const JulianDate tdb = t.to(TimeScale::tdb);
  const double d = (tdb.jd1 - 2451545.0) + tdb.jd2, T = d / 36525.0;
  switch (body) {
    case CentralBody::moon: return moon(d, T);
    case CentralBody::sun: return {286.13, 63.87, 84.176 + 14.1844000 * d};
    case CentralBody::mercury: return {281.0097 - 0.0328 * T, 61.4143 - 0.0049 * T, 329.5469 + 6.1385025 * d};
    case CentralBody::venus: return {272.76, 67.16, 160.20 - 1.4813688 * d};
    case CentralBody::mars: return {317.68143 - 0.1061 * T, 52.88650 - 0.0609 * T, 176.630 + 350.89198226 * d};
    case CentralBody::jupiter:
      return {268.056595 - 0.006499 * T, 64.495303 + 0.002413 * T, 284.95 + 870.5360000 * d};
    case CentralBody::saturn: return {40.589 - 0.036 * T, 83.537 - 0.004 * T, 38.90 + 810.7939024 * d};
    case CentralBody::uranus: return {257.311, -15.175, 203.81 - 501.1600928 * d};
    case CentralBody::neptune: {
      const double N = 357.85 + 52.316 * T;
      return {299.36 + 0.70 * sind(N), 43.46 - 0.51 * cosd(N), 253.18 + 536.3128492 * d - 0.48 * sind(N)};
    }
    case CentralBody::earth: break;
  }
  return {};
}

Eigen::Matrix3d body_to_j2000(CentralBody body, const EngineTime& t) {
  const RotationalElements e = rotational_elements(body, t);
  const double rad = constants::rad_per_deg;
  return (Eigen::AngleAxisd((e.pole_ra_deg + 90.0) * rad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd((90.0 - e.pole_dec_deg) * rad, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(std::fmod(e.prime_meridian_deg, 360.0) * rad, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

}  // namespace eoir::universe
