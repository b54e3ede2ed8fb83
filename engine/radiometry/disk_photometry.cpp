#include "radiometry/disk_photometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::radiometry {
namespace {

constexpr double kDeg = constants::pi / 180.0;
// Past this, Allen's lunar law is held (Krisciunas & Schaefer 1991).
constexpr double kLunarLawLimitDeg = 150.0;

double poly(double x, std::initializer_list<double> c) {  // c0 + c1 x + c2 x^2 + ...
  double sum = 0, power = 1;
  for (const double k : c) {
    sum += k * power;
    power *= x;
  }
  return sum;
}

}  // namespace

DiskPhaseLaw disk_phase_law(universe::CentralBody body) {
  using universe::CentralBody;
  switch (body) {
    case CentralBody::moon: return DiskPhaseLaw::moon;
    case CentralBody::mercury: return DiskPhaseLaw::mercury;
    case CentralBody::venus: return DiskPhaseLaw::venus;
    case CentralBody::mars: return DiskPhaseLaw::mars;
    case CentralBody::jupiter: return DiskPhaseLaw::jupiter;
    case CentralBody::saturn: return DiskPhaseLaw::saturn;
    case CentralBody::uranus: return DiskPhaseLaw::uranus;
    case CentralBody::neptune: return DiskPhaseLaw::neptune;
    default: return DiskPhaseLaw::lambertian_sphere;
  }
}

double lambertian_sphere_phase(double cos_psi) {
  const double c = std::clamp(cos_psi, -1.0, 1.0);
  return (std::sqrt((1.0 - c) * (1.0 + c)) + (constants::pi - std::acos(c)) * c) / constants::pi;
}

double lommel_seeliger_sphere_phase(double g) {
  g = std::clamp(g, 0.0, constants::pi);
  if (g < 1e-9) return 1.0;
  if (g > constants::pi - 1e-9) return 0.0;
  return std::max(0.0, 1.0 - std::sin(g / 2) * std::tan(g / 2) * std::log(1.0 / std::tan(g / 4)));
}

double lunar_phase_magnitude(double phase_angle_deg) {
  const double g = std::min(std::fabs(phase_angle_deg), kLunarLawLimitDeg);
  return 0.026 * g + 4.0e-9 * g * g * g * g;
}

double lunar_surface_phase(double phase_angle_rad) {
  const double g = std::min(std::clamp(phase_angle_rad, 0.0, constants::pi), kLunarLawLimitDeg * kDeg);
  if (g < 1e-9) return 1.0;
  return std::pow(10.0, -0.4 * lunar_phase_magnitude(g / kDeg)) / lommel_seeliger_sphere_phase(g);
}

double lunar_surface_phase_max() {
  static const double most = [] {
    double m = 0;
    for (int k = 0; k <= 1800; ++k) m = std::max(m, lunar_surface_phase(constants::pi * k / 1800.0));
    return m;
  }();
  return most;
}

double mallama_hilton_upper_limit_deg(DiskPhaseLaw planet) {
  switch (planet) {  // the observed ranges (Mallama & Hilton 2018, Table 2 and their code)
    case DiskPhaseLaw::mercury: return 170.0;
    case DiskPhaseLaw::venus: return 179.0;
    case DiskPhaseLaw::mars: return 120.0;
    case DiskPhaseLaw::jupiter: return 130.0;
    case DiskPhaseLaw::saturn: return 150.0;
    case DiskPhaseLaw::uranus: return 154.0;
    case DiskPhaseLaw::neptune: return 133.14;
    default: throw Error(Status::out_of_range, "disk photometry: not a planet of Mallama & Hilton (2018)");
  }
}

double mallama_hilton_v_1_alpha(DiskPhaseLaw planet, double a) {
  if (!std::isfinite(a) || a < 0 || a > mallama_hilton_upper_limit_deg(planet))
    throw Error(Status::out_of_range, "disk photometry: phase angle outside Mallama & Hilton's range");
  switch (planet) {
    case DiskPhaseLaw::mercury:  // eq. 2
      return poly(a, {-0.613, 6.3280e-02, -1.6336e-03, 3.3644e-05, -3.4265e-07, 1.6893e-09, -3.0334e-12});
    case DiskPhaseLaw::venus:  // eqs. 3 and 4
      return a < 163.7 ? poly(a, {-4.384, -1.044e-03, 3.687e-04, -2.814e-06, 8.938e-09})
                       : poly(a, {236.05828, -2.81914, 8.39034e-03});
    case DiskPhaseLaw::mars:  // eqs. 6 and 7 (without L(lambda_e), L(Ls))
      return a <= 50.0 ? poly(a, {-1.601, 2.267e-02, -1.302e-04}) : poly(a, {-0.367, -0.02573, 0.0003445});
    case DiskPhaseLaw::jupiter: {  // eqs. 8 and 9
      if (a <= 12.0) return poly(a, {-9.395, -3.7e-04, 6.16e-04});
      return -9.428 - 2.5 * std::log10(poly(a / 180.0, {1.0, -1.507, -0.363, -0.062, 2.809, -1.876}));
    }
    case DiskPhaseLaw::saturn:  // eqs. 11 and 12, the globe alone
      return a <= 6.5 ? poly(a, {-8.95, -3.7e-04, 6.16e-04}) : poly(a, {-8.94, 2.446e-04, 2.672e-04, -1.506e-06, 4.767e-09});
    case DiskPhaseLaw::uranus:  // eqs. 13 and 14 (sub-latitude term left out)
      return a <= 3.1 ? -7.110 : poly(a, {-7.110, 6.587e-03, 1.045e-04});
    case DiskPhaseLaw::neptune:  // eqs. 16 (after 2000.0) and 17
      return a <= 1.9 ? -7.00 : poly(a, {-7.00, 7.944e-03, 9.617e-05});
    default: throw Error(Status::out_of_range, "disk photometry: not a planet of Mallama & Hilton (2018)");
  }
}

double DiskPhotometry::geometric_albedo_per_srf() const { return law_ == DiskPhaseLaw::moon ? 1.0 : 2.0 / 3.0; }

double DiskPhotometry::phase(double cos_psi) const {
  if (law_ == DiskPhaseLaw::lambertian_sphere) return lambertian_sphere_phase(cos_psi);
  const double psi = std::acos(std::clamp(cos_psi, -1.0, 1.0));
  if (law_ == DiskPhaseLaw::moon) return lommel_seeliger_sphere_phase(psi) * lunar_surface_phase(psi);
  const double limit_deg = mallama_hilton_upper_limit_deg(law_);
  const double v0 = mallama_hilton_v_1_alpha(law_, 0.0);
  const double a = std::min(psi / kDeg, limit_deg);
  const double in_range = std::pow(10.0, -0.4 * (mallama_hilton_v_1_alpha(law_, a) - v0));
  if (psi / kDeg <= limit_deg) return in_range;
  // Past the observed range: a Lambertian sphere's fall from the last angle.
  const double at_limit = lambertian_sphere_phase(std::cos(limit_deg * kDeg));
  return at_limit > 0 ? in_range * lambertian_sphere_phase(cos_psi) / at_limit : 0.0;
}

}  // namespace eoir::radiometry
