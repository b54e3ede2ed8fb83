#include "scene/pick.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace eoir::scene {

void ra_dec_deg(const Vec3& d, double& ra, double& dec) {
  ra = std::atan2(d.y(), d.x()) * constants::deg_per_rad;
  if (ra < 0) ra += 360.0;
  dec = std::asin(std::clamp(d.z() / d.norm(), -1.0, 1.0)) * constants::deg_per_rad;
}

Pick pick_sample(const World& world, double effective_radiance_W_cm2_sr, const SampleHit& sample_hit, std::int64_t c,
                 std::int64_t r) {
  const Vec3 d = world.sample_direction(c, r);
  Pick pick;
  pick.effective_radiance_W_cm2_sr = effective_radiance_W_cm2_sr;
  ra_dec_deg(d, pick.right_ascension_deg, pick.declination_deg);
  pick.wavelengths_um = world.spectral().sample_wavelengths_um;
  pick.spectral_radiance_W_cm2_sr_um.assign(pick.wavelengths_um.size(), 0.0);
  pick.range_m = geometry::sky_range_m;
  if (sample_hit.object_id < 0) {
    pick.terms = world.sky_terms(d);
    pick.spectral_radiance_W_cm2_sr_um = pick.terms.at_sensor;
    return pick;
  }
  // Cast this one sample's ray again, with range, point and normal.
  const geometry::Hit hit = world.caster.cast(d, geometry::RayQuery{geometry::ray_mask_extended, -1});
  if (hit.object_id < 0) {
    pick.terms = world.sky_terms(d);
    pick.spectral_radiance_W_cm2_sr_um = pick.terms.at_sensor;
    return pick;
  }
  const WorldObject& o = *world.objects[static_cast<std::size_t>(hit.object_id)];
  pick.hit = true;
  pick.object = o.name;
  pick.range_m = hit.range_m;
  const Vec3 normal_body = o.direction_to_body(hit.normal_frame);
  pick.patch =
      geometry::patch_at_facet(o.tessellation(), o.placed.parts, hit.part, hit.facet, hit.point_body_m, normal_body);
  // The same surface point, normal and direction the image's sample used.
  Vec3 point_body, shading_normal;
  o.shading_point(hit.part, hit.point_body_m, normal_body, point_body, shading_normal, hit.facet);
  pick.temperature_K = o.surface->temperature_K(o.surface->at(SurfaceSite{hit.part, point_body, shading_normal}));
  pick.terms = o.eq9_terms(hit.part, point_body, shading_normal);
  pick.spectral_radiance_W_cm2_sr_um = pick.terms.at_sensor;
  if (o.central_body) {
    // Geodetic latitude/longitude on the body's ellipsoid (GeographicLib):
    // WGS84 on the Earth-fixed Earth; planetocentric on the others (IAU axes).
    const double a = o.equatorial_radius_m, flattening = (a - o.polar_radius_m) / a;
    double h = 0;
    GeographicLib::Geocentric(a, flattening)
        .Reverse(hit.point_body_m.x(), hit.point_body_m.y(), hit.point_body_m.z(), pick.latitude_deg,
                 pick.longitude_deg, h);
    pick.has_geodetic = true;
  }
  return pick;
}

}  // namespace eoir::scene
