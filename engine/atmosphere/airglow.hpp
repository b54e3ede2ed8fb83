// The night airglow (issue 20 item 6): the light the upper atmosphere emits
// from a layer about 85-95 km up (O I 557.7 and 630 nm, Na D, the O2 and OH
// Meinel bands, a faint continuum; data/atmosphere/airglow_nightglow.csv
// names the sources), the night sky's brightest part in the visible at a
// dark site. A line of sight sees the zenith radiance times the length it
// runs inside the layer over the layer's thickness: 1 at the zenith, van
// Rhijn's 1 / sqrt(1 - (R / (R + h))^2 sin^2 z) toward zenith angle z from
// below, some 50 x along the limb from orbit. It replaces spec 4.1.4's
// three airglow lines (5.1e-18 W/cm^2 in all, some 1e7 times fainter than
// the ~2e-11 W cm^-2 sr^-1 this layer gives in 0.5-0.6 um at the zenith).
#pragma once
#include <string>
#include <vector>

namespace eoir::atmosphere {

constexpr double airglow_layer_bottom_m = 85.0e3, airglow_layer_top_m = 95.0e3;

class Airglow {
 public:
  // Reads data_dir/atmosphere/airglow_nightglow.csv (throws io or corrupt_file naming it).
  static Airglow load(const std::string& data_dir);
  // The zenith spectral radiance above the air's absorption (W cm^-2 sr^-1
  // um^-1), each interval's mean, of `intervals` intervals from low_um.
  std::vector<double> zenith_radiance(double low_um, double interval_um, std::size_t intervals) const;

  // The lengths (in layer thicknesses) a line runs inside the layer: from a
  // point at radius r_m from the Earth's centre (where the Earth is a
  // sphere of radius earth_radius_m) along a direction whose cosine to the
  // local vertical is mu, stopping at the ground. `near` is its first pass
  // through the layer's shell, `far` the second (beyond the tangent point,
  // or the only one from below the layer).
  struct Passes {
    double near = 0, far = 0;
  };
  static Passes passes(double earth_radius_m, double r_m, double mu);

 private:
  struct Feature {
    double low_um = 0, high_um = 0, zenith_R = 0;
  };
  std::vector<Feature> features_;
};

}  // namespace eoir::atmosphere
