#include "universe/astrometric_place.hpp"

#include <cmath>

#include "core/error.hpp"

namespace eoir::universe {

Vec3 astrometric_direction(const Vec3& apparent, const ApparentPlaceContext& context) {
  const double norm = apparent.norm();
  if (!std::isfinite(norm) || !(norm > 0.0))
    throw Error(Status::out_of_range, "apparent: not a finite non-zero direction");
  const Vec3 target = apparent / norm;
  // The chain's deflection and aberration only (a "star" at p, at rest).
  ApparentPlaceOptions only_deflection_and_aberration;
  only_deflection_and_aberration.proper_motion = false;
  only_deflection_and_aberration.parallax = false;
  CatalogStar at;
  Vec3 p = target;
  for (int i = 0; i < 8; ++i) {
    at.ra_rad = std::atan2(p.y(), p.x());
    at.dec_rad = std::asin(std::fmax(-1.0, std::fmin(1.0, p.z())));
    const Vec3 miss = target - apparent_direction(at, context, only_deflection_and_aberration);
    p = (p + miss).normalized();
    if (miss.norm() < 1e-15) break;
  }
  return p;
}

}  // namespace eoir::universe
