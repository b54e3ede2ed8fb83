#include "atmosphere/single_scatter.hpp"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

#include "atmosphere/aerosol_optics.hpp"
#include "atmosphere/rayleigh.hpp"
#include "core/constants.hpp"

namespace eoir::atmosphere {
namespace {

// The cosine of the zenith angle of the ray from altitude h that grazes the ground.
double grazing_mu(double radius_m, double altitude_m) {
  const double s = radius_m / (radius_m + std::max(altitude_m, 0.0));
  return -std::sqrt(std::max(0.0, 1.0 - s * s));
}
}  // namespace

SunlightTable::SunlightTable(const PathOptics& optics, const EarthFigure& earth, int nodes)
    : radius_m_(earth.equatorial_radius_m), intervals_(static_cast<std::size_t>(optics.band().intervals)),
      nodes_(std::max(2, nodes)) {
  const AtmosphereProfile& profile = optics.profile();
  const Vec3 up = earth.pole.unitOrthogonal(), across = earth.pole.cross(up);
  std::vector<double> T;
  for (const ProfileLevel& l : profile.levels()) {
    altitude_m_.push_back(l.altitude_m);
    const Vec3 point = earth.centre_m + (radius_m_ + l.altitude_m) * up;
    const double mu_g = grazing_mu(radius_m_, l.altitude_m);
    for (int k = 0; k < nodes_; ++k) {
      const double x = std::pow(static_cast<double>(k) / (nodes_ - 1), 2.0);
      const double mu = mu_g + x * (1.0 - mu_g);
      const Vec3 u = mu * up + std::sqrt(std::max(0.0, 1.0 - mu * mu)) * across;
      optics.transmittance(path_to_space(profile, earth, point, u), T);
      table_.insert(table_.end(), T.begin(), T.end());
    }
  }
}

SunlightTable::Corners SunlightTable::at(double altitude_m, double mu) const {
  Corners c{};
  const std::vector<double>& h = altitude_m_;
  const double hc = std::clamp(altitude_m, h.front(), h.back());
  const std::size_t j = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(h.begin(), h.end(), hc) - h.begin()), h.size() - 1);
  const std::size_t lo = j == 0 ? 0 : j - 1;
  const double fh = h[lo + 1] > h[lo] ? (hc - h[lo]) / (h[lo + 1] - h[lo]) : 0.0;
  const std::size_t level[2] = {lo, lo + 1};
  const double level_weight[2] = {1.0 - fh, fh};
  for (int e = 0; e < 2; ++e) {
    const double mu_g = grazing_mu(radius_m_, h[level[e]]);
    const double x = mu < mu_g ? -1.0 : (mu - mu_g) / (1.0 - mu_g);
    const double node = x < 0 ? 0.0 : std::sqrt(std::min(x, 1.0)) * (nodes_ - 1);
    const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(node), static_cast<std::size_t>(nodes_ - 2));
    const double f = node - static_cast<double>(k);
    const double lit = x < 0 ? 0.0 : 1.0;  // in the Earth's shadow: dark
    const std::size_t base = (level[e] * static_cast<std::size_t>(nodes_) + k) * intervals_;
    c.row[2 * e] = &table_[base];
    c.row[2 * e + 1] = &table_[base + intervals_];
    c.weight[2 * e] = lit * level_weight[e] * (1.0 - f);
    c.weight[2 * e + 1] = lit * level_weight[e] * f;
  }
  return c;
}

ScatterPath ScatterPath::make(const PathOptics& optics, const PathColumns& path) {
  ScatterPath s;
  for (const PathSegment& g : path.segments) {
    s.mid_distance_m.push_back(g.mid_distance_m);
    s.mid_altitude_m.push_back(g.mid_altitude_m);
  }
  s.terms = optics.terms(path);
  return s;
}

void add_single_scatter(const ScatterPath& path, const Vec3& start, const Vec3& direction, const Vec3& to_sun,
                        const std::vector<double>& sun_irradiance, const SunlightTable& sunlight,
                        std::vector<double>& out) {
  const std::size_t n = sunlight.intervals();
  const double cos_theta = to_sun.dot(direction);  // between the Sun's light and the light toward the start
  const double rayleigh = rayleigh_phase(cos_theta) / (4.0 * constants::pi);
  for (std::size_t k = 0; k < path.mid_distance_m.size(); ++k) {
    const Vec3 point = start + path.mid_distance_m[k] * direction;
    const double r = point.norm();
    const double mu = r > 0 ? point.dot(to_sun) / r : 1.0;
    const SunlightTable::Corners c = sunlight.at(path.mid_altitude_m[k], mu);
    if (c.weight[0] + c.weight[1] + c.weight[2] + c.weight[3] <= 0) continue;  // in the Earth's shadow
    const std::vector<double>& wr = path.terms.rayleigh[k];
    const std::vector<double>& wa = path.terms.aerosol[k];
    const std::vector<double>& g = path.terms.asymmetry[k];
    for (std::size_t i = 0; i < n; ++i) {
      const double T = c.weight[0] * c.row[0][i] + c.weight[1] * c.row[1][i] + c.weight[2] * c.row[2][i] +
                       c.weight[3] * c.row[3][i];
      const double aerosol = wa[i] > 0 ? wa[i] * henyey_greenstein_phase(g[i], cos_theta) / (4.0 * constants::pi) : 0.0;
      out[i] += sun_irradiance[i] * T * (wr[i] * rayleigh + aerosol);
    }
  }
}

}  // namespace eoir::atmosphere
