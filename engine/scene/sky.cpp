#include "scene/sky.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "radiometry/background_light.hpp"
#include "radiometry/stellar_photometry.hpp"
#include "scene/apparent_grid.hpp"
#include "scene/world.hpp"

namespace eoir::scene {
namespace {

constexpr double kMasToRad = constants::pi / (180.0 * 3600.0 * 1000.0);
// Culling margin about the field's half-diagonal: aberration (<= 27" for an
// observer at 8 km/s on the Earth's 30 km/s), parallax (< 1") and the
// position of the apparent place on the sample grid, with room to spare.
constexpr double kCullMargin_rad = 2.0e-3;

// Whether some object of the world lies along the direction (from the
// observer, toward infinity; both where they appear): an angular
// bounding-sphere test first, one occlusion ray only where a sphere covers
// the direction.
bool hidden(const World& w, const Vec3& direction) {
  for (const auto& o : w.objects) {
    const Vec3& c = o->seen.position_m;
    const double along = c.dot(direction), radius = o->bounding_radius_m;
    if (along < -radius) continue;
    if ((c - along * direction).squaredNorm() > radius * radius) continue;
    return w.caster.occluded(direction, std::numeric_limits<double>::infinity());
  }
  return false;
}

void build_background(World& w, const universe::StarFieldProperties& p, const universe::Library& library,
                      const std::string& field, double imaged_v0_stars) {
  radiometry::BackgroundLightParameters parameters;
  parameters.zodiacal_scale = p.zodiacal_light_scale;
  // The atmosphere's airglow layer replaces the spec's three lines.
  if (w.atmosphere.on() && w.atmosphere.settings.airglow) parameters.airglow_total_irradiance_W_cm2 = 0.0;
  // Spec 4.1.4's integrated starlight less the stars imaged as points.
  parameters.starlight_S10V = radiometry::diffuse_starlight_S10V(imaged_v0_stars);
  const TabulatedFunction& sun = library.spectra.sun().radiance_W_cm2_sr_um;
  const double sun_at_1_au_sr = universe::sun_projected_solid_angle_sr(constants::au_m);
  const TabulatedFunction& mars = library.materials.get("mars_surface", field).reflectance;
  const radiometry::BackgroundLight light([&](double l) { return sun(l) * sun_at_1_au_sr; },
                                          [&](double l) { return mars(l); }, parameters);
  Sky& sky = w.sky;
  sky.background = true;
  sky.background_irradiance = light.interval_mean_irradiances(w.view.spectral.band);
  sky.background_radiance_W_cm2_sr = w.view.spectral.integrate(sky.background_irradiance) / constants::pi;
}

}  // namespace

void build_sky(World& w, const universe::Object& star_field, const universe::Library& library) {
  Sky& sky = w.sky;
  const universe::StarFieldProperties& p = star_field.stars;
  sky.present = true;
  sky.star_field = star_field.name;
  sky.catalogue = library.star_catalog(p.catalog_file, p.catalog_epoch_year);
  const universe::StarCatalog& catalogue = *sky.catalogue;
  // The stars drawn as points are the catalogue's to the limit: the
  // background's starlight is the rest (spec 4.1.4).
  if (p.background_light)
    build_background(w, p, library, star_field.name + ".background_light",
                     catalogue.v0_equivalent_stars(p.limiting_magnitude));
  const universe::ApparentPlaceContext context = universe::apparent_place_context_geocentric(
      w.time, w.observer.position_m, w.observer.velocity_m_s, catalogue.epoch_julian_year());

  // Cull on the catalogue positions: the cone about the boresight holding the
  // whole sample grid, widened by proper motion since the epoch and by the
  // refraction of an observer inside the atmosphere; the catalogue's sky
  // cells give the stars of that cone brighter than the limit.
  const geometry::SampleGrid& grid = w.grid();
  const ApparentGrid apparent(w);
  const double half_diagonal = std::atan(std::hypot(grid.tan_x(0), grid.tan_y(0)));
  const double moved = catalogue.max_proper_motion_mas_yr() * std::fabs(context.proper_motion_years) * kMasToRad;
  const double cone_rad =
      std::min(constants::pi, half_diagonal + kCullMargin_rad + moved + apparent.max_refraction_rad());
  const double cos_limit = std::cos(cone_rad);
  const Vec3 boresight = w.observer.body_to_j2000.col(2);
  const universe::StarSelection selection = catalogue.select_in_cone(boresight, cone_rad, p.limiting_magnitude);
  sky.warning = selection.warning;
  sky.stars_considered = selection.indices.size();
  const radiometry::SpectralView& view = w.view.spectral;
  for (const std::size_t i : selection.indices) {
    if (catalogue.unit_vector(i).dot(boresight) < cos_limit) continue;
    const universe::CatalogStar star = catalogue.star(i);
    // d: the apparent place (geometric: truth's RA/Dec); on the grid and
    // behind the objects where it appears, refracted from inside the
    // atmosphere.
    const Vec3 d = universe::apparent_direction(star, context);
    GridPlace place;
    if (!apparent.star(d, place) || !grid.in_field(place.column, place.row, 1e-4)) continue;
    if (hidden(w, w.atmosphere.apparent_direction(d))) continue;
    WorldStar s;
    s.catalogue_index = i;
    s.id = star.id;
    s.v_mag = star.v_mag;
    s.b_v_mag = star.b_v_mag;
    s.direction_j2000 = d;
    s.column = place.column;
    s.row = place.row;
    s.streak_columns = place.streak_columns;
    s.streak_rows = place.streak_rows;
    // Spec 4.1.6.1: E = m0 B(T), band-integrated as the view integrates;
    // through the atmosphere's path toward the star (eq. 9's T_out).
    const double T = radiometry::temperature_from_b_v(star.b_v_mag);
    const std::vector<double> through = w.atmosphere.to_space(Vec3::Zero(), d);
    if (through.empty()) {
      s.irradiance_W_cm2 = radiometry::m0_sr(star.v_mag, T) * view.gray_body_radiance(T, 0.0);
    } else {
      std::vector<double> e(view.sample_wavelengths_um.size(), 0.0);
      view.add_gray_body_spectrum(T, 0.0, e);
      for (std::size_t k = 0; k < e.size(); ++k) e[k] *= through[k];
      s.irradiance_W_cm2 = radiometry::m0_sr(star.v_mag, T) * view.integrate(e);
    }
    sky.stars.push_back(std::move(s));
  }
}

}  // namespace eoir::scene
