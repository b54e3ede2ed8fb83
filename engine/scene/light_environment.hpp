// The light that can reach a surface of the world (spec 4.1.5.3, eq. 4): the
// Sun (eq. 6, E = L_tab dOmega_sun, times the visible fraction of its disc),
// and every other object as a source: reduced to a Lambertian sphere of equal
// volume with its phase law (eq. 7; natural bodies' observed laws,
// radiometry/disk_photometry.hpp) or, when it looks larger than the Sun or
// the Moon from the Earth, summed over its tessellation (eq. 8). The
// background term E_bkg / pi joins here with the sky's background light.
// Single bounce: the light a source reflects is the Sun's only (4.1.6.1).
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/eclipse.hpp"
#include "radiometry/brdf.hpp"
#include "radiometry/disk_photometry.hpp"

namespace eoir::scene {

using Vec3 = Eigen::Vector3d;

// An object as a source of eq. 7.
struct ObjectLight {
  std::int32_t object = -1;           // world id
  Vec3 position_m = Vec3::Zero();     // observer-relative
  double radius_m = 0.0;              // volumetric mean radius of its true shape
  double bounding_radius_m = 0.0;
  bool area_source = false;           // its tessellation can serve eq. 8 (resolved objects)
  Vec3 to_sun = Vec3::UnitX();        // unit, from the source toward the Sun
};

// The spectra of an eq. 7 source (WorldObject::light_spectra, made on first use).
struct LightSpectra {
  // E_sun(lambda) p(lambda) / pi at the source (p = 2/3 SRF for a
  // Lambertian sphere, radiometry/disk_photometry.hpp), times its visible
  // fraction of the Sun: multiply by Phase(psi) dOmega (W cm^-2 sr^-1 um^-1).
  std::vector<double> reflected;
  // Overall emittance times B(T_eff): multiply by dOmega.
  std::vector<double> emitted;
  bool reflects = false;  // some reflected value is not 0 (not eclipsed, not black)
  // reflected + emitted where the source's phase law stays within 1 (the
  // Moon's, a Lambertian sphere's): at least its light per dOmega at any
  // phase angle; empty for other laws (no bound kept).
  std::vector<double> bound;
  // bound's band integral (eq. 48), W cm^-2 sr^-1 per dOmega; infinity
  // where no bound is kept.
  double bound_band_W_cm2_sr = std::numeric_limits<double>::infinity();
};


}  // namespace eoir::scene
