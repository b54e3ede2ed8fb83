// The atmosphere along the observer's lines of sight (spec 4.1.5.3 eq. 9,
// 4.3.1.1; DESIGN "The atmosphere in the world": tabulated over the view
// where the terms vary slowly, interpolated per sample): for every line of
// sight from the observer, the sunlight its air scatters toward the sensor
// (L_scatter) and, where it meets nothing, the sky's radiance -- that
// scatter, the path's thermal emission (L_path) and the background light
// seen through the path (E_bkg T / pi). This is the blue daytime sky of a
// ground telescope, the twilight sky, the Earth's limb haze from orbit and
// the haze over the Earth's surface.
//
// Spherical symmetry (in the space where the Earth's ellipsoid is a sphere,
// shell_path.hpp) fixes a line of sight's path by one number: for an
// observer inside the atmosphere its elevation (nodes below the horizon
// placed as from above, dense toward the horizon's dip); for one above it,
// its impact parameter p (the distance of the line from the Earth's
// centre: p < a meets the ground, a <= p < a + top grazes the limb),
// whatever the observer's altitude. Moonlight has a view of its own
// (WorldAtmosphere::moon_sky). The paths' terms on those nodes (SightLines) are
// made once per atmosphere, band and observer altitude; per frame only the
// Sun's geometry: the scatter on (node, azimuth from the Sun's vertical
// plane) cells (SkyView), each made when a line of sight first needs it (a
// narrow field reads a few), interpolated bilinearly.
#pragma once
#include <Eigen/Core>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "atmosphere/airglow.hpp"
#include "atmosphere/path_optics.hpp"
#include "atmosphere/shell_path.hpp"
#include "atmosphere/single_scatter.hpp"
#include "radiometry/spectral_view.hpp"

namespace eoir::scene {

using Vec3 = Eigen::Vector3d;

// The lines of sight of an observer at one altitude (every observer above
// the atmosphere shares one set).
struct SightLines {
  bool above = false;            // nodes are impact parameters (m); else elevations (rad)
  double top_radius_m = 0;       // of the air's top
  std::vector<double> node;      // ascending
  // Per node: the path from the observer (above the atmosphere: from where
  // the line enters it) out, with its terms.
  std::vector<atmosphere::ScatterPath> paths;
  // ground_nodes: lines that meet the ground (the fidelity knob
  // atmosphere_sight_line_nodes; the limb's and the sky's: (3 (n - 1) + 2) / 4 + 1).
  static SightLines make(const atmosphere::PathOptics& optics, const atmosphere::EarthFigure& earth,
                         double observer_altitude_m, int ground_nodes = 33);
};

// Eq. 9's sky terms over the view of one frame.
class SkyView {
 public:
  // earth: the Earth's figure relative to the observer; to_sun: unit;
  // sun_irradiance per interval above the air; background_radiance: E_bkg /
  // pi per interval (empty: none); airglow_zenith: the airglow's zenith
  // radiance per interval (atmosphere/airglow.hpp; empty: none); view:
  // integrates a spectrum (eq. 48).
  SkyView(std::shared_ptr<const SightLines> lines, std::shared_ptr<const atmosphere::SunlightTable> sunlight,
          const atmosphere::EarthFigure& earth, const Vec3& to_sun, const std::vector<double>& sun_irradiance,
          const std::vector<double>& background_radiance, const std::vector<double>& airglow_zenith,
          const radiometry::SpectralView& view, std::size_t azimuths = 49);
  // Band radiance (W cm^-2 sr^-1) of the air along the unit direction d
  // from the observer: the scatter alone (`scatter_band`: the line ends on
  // a surface, whose own T_out and L_path are the surface's) or, for a
  // line that meets nothing, the whole sky (`sky_band`).
  // sky_band and sky are false (out untouched) for a line that crosses no air.
  double scatter_band(const Vec3& d) const;
  bool sky_band(const Vec3& d, double& out) const;
  // The same per interval, into out.
  void scatter(const Vec3& d, std::vector<double>& out) const;
  bool sky(const Vec3& d, std::vector<double>& out) const;
  // A line's own terms per interval: its transmittance and thermal emission
  // (false, untouched, for a line that crosses no air).
  bool path(const Vec3& d, std::vector<double>& transmittance, std::vector<double>& thermal) const;

 private:
  struct Cell {
    std::size_t node = 0, azimuth = 0;
    double weight[4] = {0, 0, 0, 0};  // (node, az), (node + 1, az), (node, az + 1), (node + 1, az + 1)
    bool inside = false;              // the line crosses the air
  };
  Cell cell_of(const Vec3& d) const;
  // Cell k's scatter (made on first use, thread-safe).
  void make_cell(std::size_t k) const;
  const std::vector<double>& cell_scatter(std::size_t k) const;
  double cell_band(std::size_t k) const;
  template <class Value>
  double blend(const Cell& c, Value value) const;
  std::shared_ptr<const SightLines> lines_;
  std::vector<double> coordinate_;  // the nodes as looked up: p, or the sine of the elevation
  std::size_t intervals_ = 0;
  Vec3 centre_;              // the observer relative to the Earth's centre, sphere space
  Vec3 vertical_, x_, y_;    // x_: toward the Sun's azimuth
  atmosphere::EarthFigure earth_;
  std::size_t azimuths_ = 0;
  std::shared_ptr<const atmosphere::SunlightTable> sunlight_;
  Vec3 sun_;                                  // sphere space
  std::vector<double> sun_irradiance_;
  radiometry::SpectralView view_;
  std::unique_ptr<std::atomic<bool>[]> made_;  // per cell: its scatter is ready
  mutable std::mutex making_;
  mutable std::vector<std::vector<double>> scatter_;  // [node * azimuths + azimuth][interval]
  mutable std::vector<double> scatter_band_;
  std::vector<double> sky_band_;              // per node, what does not depend on the Sun
  std::vector<std::vector<double>> sky_;      // per node per interval
};

}  // namespace eoir::scene
