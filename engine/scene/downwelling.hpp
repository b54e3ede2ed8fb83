// DownWelling (spec 4.1.5.3 eq. 9; ERRATA 4.1.5.3: on by default, the
// Earth's `downwelling` property switches it off to reproduce single-scatter
// references): the diffuse irradiance of the sky on a horizontal surface of
// the ground, E_down = integral over the upper hemisphere of L_sky cos(z)
// dOmega, with L_sky the sunlight the air scatters (single scatter,
// atmosphere/single_scatter.hpp) and the air's thermal emission. Surfaces
// reflect it as eq. 9 says, DownWelling / pi times their SRF: the blue
// sky's light in shadows and on lit ground, twilight on the ground after
// sunset, and the sky's emission reflected in the thermal bands. Made once
// per atmosphere and band from a ground observer's lines of sight
// (SightLines), per unit solar irradiance over the Sun's zenith cosine (40
// nodes from 12 deg below the horizon to the zenith; linear between).
#pragma once
#include <vector>

#include "atmosphere/path_optics.hpp"
#include "atmosphere/single_scatter.hpp"

namespace eoir::scene {

class Downwelling {
 public:
  // sun_nodes over the Sun's zenith cosine (the fidelity knob
  // atmosphere_downwelling_nodes), the sky's lines of sight as SightLines::make's.
  Downwelling(const atmosphere::PathOptics& optics, const atmosphere::SunlightTable& sunlight,
              const atmosphere::EarthFigure& earth, int sun_nodes = 40, int sight_line_nodes = 33);
  // Adds E_down / pi per interval (what a reflector of unit SRF returns of
  // it, W cm^-2 sr^-1 um^-1) for a Sun whose zenith cosine is mu_sun over
  // the surface, of irradiance sun_irradiance per interval above the air.
  void add_over_pi(double mu_sun, const std::vector<double>& sun_irradiance, std::vector<double>& out) const;
  // Its scatter per unit solar irradiance.
  void scatter_per_sun(double mu_sun, std::vector<double>& out) const;

 private:
  std::vector<double> sun_mu_;  // nodes: the Sun's zenith cosine
  std::vector<std::vector<double>> scatter_;  // [node][interval], per unit solar irradiance
  std::vector<double> thermal_;
};

}  // namespace eoir::scene
