// The sky of a world (spec 4.1.4, 4.1.6.1, 4.3.2): the background light that
// every surface reflects (E_bkg SRF / pi of eq. 4) and that samples seeing no
// object show (E_bkg / pi, radiometry/background_light.hpp), and the
// catalogue stars in the field of view at their apparent places (ERFA chain,
// universe/star_catalog.hpp) as blackbody point sources E = m0 B(T)
// (radiometry/stellar_photometry.hpp). Present only when the universe holds
// a star field object; without one the sky is black. The background's
// integrated starlight leaves out the catalogue's stars to the field's limit,
// which are drawn as points (issue 21).
#pragma once
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "universe/library.hpp"
#include "universe/object.hpp"
#include "universe/star_catalog.hpp"

namespace eoir::scene {

class World;

// A catalogue star imaged by the sensor: inside the field of view, not hidden
// by any object.
struct WorldStar {
  std::size_t catalogue_index = 0;
  std::string id;          // the catalogue's id ("HIP<n>", "HT<n>" or the user's)
  double v_mag = 0, b_v_mag = 0;
  Eigen::Vector3d direction_j2000 = Eigen::Vector3d::UnitZ();  // apparent place, from the observer
  double column = 0, row = 0;                   // fractional sample coordinates at the frame time
  double streak_columns = 0, streak_rows = 0;   // displacement over the integration time (sensor rotation)
  double irradiance_W_cm2 = 0;                  // band-integrated at the aperture (eq. 48 of m0 B(T))
};

struct Sky {
  bool present = false;              // the universe holds a star field
  std::string star_field;            // its name
  bool background = false;           // background light on
  std::vector<double> background_irradiance;  // E_bkg, interval means on the view (W cm^-2 um^-1)
  double background_radiance_W_cm2_sr = 0;    // band integral of E_bkg / pi (eq. 48)
  std::shared_ptr<const universe::StarCatalog> catalogue;
  std::vector<WorldStar> stars;      // imaged, in catalogue order
  std::size_t stars_considered = 0;  // brighter than the limit in the sky cells the field's cone meets
  std::string warning;               // e.g. a limit past the catalogue's faintest star
};

// Fills world.sky from the universe's star field (after the world's objects,
// observer and ray caster are built). Throws what the catalogue loader throws
// (io, corrupt_file naming the file and line).
void build_sky(World& world, const universe::Object& star_field, const universe::Library& library);

}  // namespace eoir::scene
