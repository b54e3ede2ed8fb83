// Orientation of the central bodies other than the Earth (whose rotation is
// ERFA's IAU 2006/2000A, core/frames.hpp): the IAU WGCCRE rotational elements
// (Archinal et al. 2011, Celest. Mech. Dyn. Astr. 109, 101; the Moon's series
// as in the 2000 report, Seidelmann et al. 2002) -- the pole's right
// ascension alpha0 and declination delta0 in ICRF/J2000 and the prime
// meridian's angle W, so that body coordinates (planetocentric, the Moon's
// mean-Earth selenographic) map to J2000 as
//   r_J2000 = Rz(alpha0 + 90 deg) Rx(90 deg - delta0) Rz(W) r_body.
#pragma once
#include <Eigen/Core>

#include "core/time.hpp"
#include "universe/central_bodies.hpp"

namespace eoir::universe {

struct RotationalElements {
  double pole_ra_deg = 0, pole_dec_deg = 90, prime_meridian_deg = 0;
};

// At TDB time t (d days and T centuries since J2000.0). The Earth is not
// covered (use frames::j2000_to_earth_fixed).
RotationalElements rotational_elements(CentralBody body, const EngineTime& t);
// The rotation taking body-fixed vectors to J2000.
Eigen::Matrix3d body_to_j2000(CentralBody body, const EngineTime& t);

}  // namespace eoir::universe
