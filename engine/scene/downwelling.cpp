#include "scene/downwelling.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "scene/sight_lines.hpp"

namespace eoir::scene {
namespace {
constexpr double kLowestSun_deg = -12.0;
constexpr int kAzimuths = 25;  // 0..pi, 7.5 deg apart (the hemisphere's integral)

// Trapezoid weights of nodes x over [x.front(), x.back()].
std::vector<double> trapezoid(const std::vector<double>& x) {
  std::vector<double> w(x.size(), 0.0);
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    w[k] += 0.5 * (x[k + 1] - x[k]);
    w[k + 1] += 0.5 * (x[k + 1] - x[k]);
  }
  return w;
}
}  // namespace

Downwelling::Downwelling(const atmosphere::PathOptics& optics, const atmosphere::SunlightTable& sunlight,
                         const atmosphere::EarthFigure& figure, int sun_nodes, int sight_line_nodes) {
  // sun_nodes uniform in the Sun's zenith cosine, from sin(-12 deg) to 1
  const int kSunNodes = std::max(2, sun_nodes);
  atmosphere::EarthFigure earth = figure;
  earth.centre_m = Vec3::Zero();
  const SightLines lines = SightLines::make(optics, earth, 0.0, sight_line_nodes);
  const Vec3 up = earth.pole.unitOrthogonal(), across = earth.pole.cross(up), side = up.cross(across);
  const Vec3 ground = earth.equatorial_radius_m * up;
  const std::size_t n = static_cast<std::size_t>(optics.band().intervals);
  // The upward lines (elevation >= 0) and their weights in the integral of
  // L sin(e) cos(e) de dpsi (cos z dOmega).
  std::vector<std::size_t> upward;
  std::vector<double> elevation;
  for (std::size_t j = 0; j < lines.node.size(); ++j)
    if (lines.node[j] >= 0) {
      upward.push_back(j);
      elevation.push_back(lines.node[j]);
    }
  std::vector<double> we = trapezoid(elevation);
  for (std::size_t k = 0; k < we.size(); ++k) we[k] *= std::sin(elevation[k]) * std::cos(elevation[k]);
  std::vector<double> psi;
  for (int m = 0; m < kAzimuths; ++m) psi.push_back(constants::pi * m / (kAzimuths - 1));
  std::vector<double> wpsi = trapezoid(psi);
  for (double& w : wpsi) w *= 2.0;  // both sides of the Sun's plane
  thermal_.assign(n, 0.0);
  for (std::size_t k = 0; k < upward.size(); ++k)
    for (std::size_t i = 0; i < n; ++i)
      thermal_[i] += 2.0 * constants::pi * we[k] * lines.paths[upward[k]].terms.thermal[i];
  const std::vector<double> unit(n, 1.0);
  std::vector<double> L(n);
  const double mu_low = std::sin(kLowestSun_deg * constants::pi / 180.0);
  for (int node = 0; node < kSunNodes; ++node) {
    const double mu = mu_low + (1.0 - mu_low) * node / (kSunNodes - 1);
    sun_mu_.push_back(mu);
    const Vec3 to_sun = mu * up + std::sqrt(1.0 - mu * mu) * across;
    std::vector<double> E(n, 0.0);
    for (std::size_t k = 0; k < upward.size(); ++k) {
      if (!(we[k] > 0)) continue;
      const double e = elevation[k];
      for (std::size_t m = 0; m < psi.size(); ++m) {
        const Vec3 d = std::sin(e) * up + std::cos(e) * (std::cos(psi[m]) * across + std::sin(psi[m]) * side);
        std::fill(L.begin(), L.end(), 0.0);
        atmosphere::add_single_scatter(lines.paths[upward[k]], ground, d, to_sun, unit, sunlight, L);
        for (std::size_t i = 0; i < n; ++i) E[i] += we[k] * wpsi[m] * L[i];
      }
    }
    scatter_.push_back(std::move(E));
  }
}

void Downwelling::scatter_per_sun(double mu_sun, std::vector<double>& out) const {
  const std::size_t n = thermal_.size();
  out.assign(n, 0.0);
  const std::vector<double>& x = sun_mu_;
  if (mu_sun <= x.front()) return;  // night (nautical twilight's end)
  const double node = std::min((mu_sun - x.front()) / (x[1] - x[0]), static_cast<double>(x.size() - 1) - 1e-12);
  const std::size_t k = static_cast<std::size_t>(node);
  const double f = node - static_cast<double>(k);
  for (std::size_t i = 0; i < n; ++i) out[i] = (1.0 - f) * scatter_[k][i] + f * scatter_[k + 1][i];
}

void Downwelling::add_over_pi(double mu_sun, const std::vector<double>& sun_irradiance, std::vector<double>& out) const {
  thread_local std::vector<double> S;
  scatter_per_sun(mu_sun, S);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] += (S[i] * sun_irradiance[i] + thermal_[i]) / constants::pi;
}

}  // namespace eoir::scene
