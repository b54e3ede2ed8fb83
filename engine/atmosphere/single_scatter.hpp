// Single scatter of sunlight into a line of sight (spec 4.1.5.3 eq. 9's
// L_scatter; 4.3.1.1: "an approach evolved from Nishita, Sirai, Tadamura
// and Nakamae 1993"): along the path, each segment scatters the sunlight
// that reaches it, E_sun T_sun(point), by its air (Rayleigh phase function)
// and aerosol (Henyey-Greenstein), and the path's transmittance carries it
// to the path's first point:
//   L_i = sum over segments k of E_sun,i T_sun,i(h_k, mu_k)
//         [w^R_ki P_R(Theta) + w^A_ki P_HG(g_ki, Theta)] / (4 pi),
// with w the segment's scatter weights (PathTerms), h_k its altitude, mu_k
// the cosine of the Sun's zenith angle there and Theta the scattering
// angle. As Nishita does, T_sun comes from a table over (altitude, Sun
// zenith cosine) made once per atmosphere and band; the Earth's shadow is
// where the Sun's ray meets the ground. Light scattered more than once is
// beyond the spec (the ground's sky light is DownWelling's).
#pragma once
#include <vector>

#include "atmosphere/path_optics.hpp"
#include "atmosphere/shell_path.hpp"

namespace eoir::atmosphere {

// T_sun per interval over the altitude of a point and the cosine mu of the
// Sun's zenith angle there, on the profile's levels and on nodes dense
// toward the ray that grazes the ground: x = (mu - mu_g) / (1 - mu_g) =
// (k / (n - 1))^2, mu_g(h) = -sqrt(1 - (a / (a + h))^2). Straight rays
// (refraction moves the shadow's edge by about a kilometre); 0 below mu_g.
class SunlightTable {
 public:
  // nodes: per level over mu (at least 2; the fidelity knob atmosphere_sun_nodes).
  SunlightTable(const PathOptics& optics, const EarthFigure& earth, int nodes = kDefaultNodes);
  static constexpr int kDefaultNodes = 33;
  std::size_t intervals() const { return intervals_; }
  // Bilinear weights of the four table rows around (h, mu); weight 0 in
  // the Earth's shadow.
  struct Corners {
    const double* row[4];
    double weight[4];
  };
  Corners at(double altitude_m, double mu) const;

 private:
  double radius_m_;
  std::size_t intervals_ = 0;
  int nodes_ = kDefaultNodes;
  std::vector<double> altitude_m_;  // the profile's levels
  std::vector<double> table_;       // [altitude][node][interval]
};

// A line of sight as single scatter needs it: the segments' middles (along
// the path from its first point, and their altitudes) and eq. 9's path
// terms.
struct ScatterPath {
  std::vector<double> mid_distance_m, mid_altitude_m;
  PathTerms terms;
  static ScatterPath make(const PathOptics& optics, const PathColumns& path);
};

// Adds L_scatter (per interval, W cm^-2 sr^-1 um^-1) toward the path's
// first point: `start` that point relative to the Earth's centre, `direction`
// the unit direction of the path from it, `to_sun` the unit direction of the
// Sun, sun_irradiance its irradiance per interval above the atmosphere
// (W cm^-2 um^-1). The local vertical of each segment is that of a sphere
// about the centre.
void add_single_scatter(const ScatterPath& path, const Vec3& start, const Vec3& direction, const Vec3& to_sun,
                        const std::vector<double>& sun_irradiance, const SunlightTable& sunlight,
                        std::vector<double>& out);

}  // namespace eoir::atmosphere
