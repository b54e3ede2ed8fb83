// The central bodies of the modeled universe (spec 4.3.1): fixed physical
// dimensions and positions from ERFA's analytic ephemerides.
#pragma once
#include <string>
#include <vector>

#include "core/frames.hpp"
#include "core/time.hpp"

namespace eoir::universe {

enum class CentralBody : int { sun, mercury, venus, earth, mars, jupiter, saturn, uranus, neptune, moon };

// The axes of a central body's body frame: Earth-fixed (ITRS, ERFA) for the
// Earth; the IAU rotational elements for the others (rotation_models.hpp).
enum class BodyAxes : int { iau, earth_fixed };

struct CentralBodyInfo {
  CentralBody id;
  const char* name;
  double equatorial_radius_m;
  double polar_radius_m;
  int erfa_planet;  // planet number (1 Mercury .. 8 Neptune: VSOP87, ERFA), 0 for Sun, Earth, Moon
  BodyAxes axes;
  double solar_day_s;  // mean solar day (NASA NSSDC planetary fact sheets; the Moon's synodic month)
};

// What a central body is made of and how hot it is until the user says
// otherwise (its properties' defaults).
struct CentralBodySurface {
  const char* material;        // "gray_body" or a data-folder material
  double reflectance;          // gray-body SRF
  double temperature_K;        // uniform thermal model; the subsolar model's T_ss
  double night_temperature_K;  // subsolar model only (0: uniform)
  bool climatology;            // the Earth's land/water thermal model
  const char* albedo_map_material = "gray_body";  // its albedo map's values (bitmap mode): a gray body's SRF
};
const CentralBodySurface& central_body_surface(CentralBody id);

// Sun, Mercury..Neptune, Moon, in CentralBody order. Radii: IAU WG on
// cartographic coordinates (2015) mean values; Earth is WGS84.
const std::vector<CentralBodyInfo>& central_bodies();
const CentralBodyInfo& central_body_info(CentralBody id);
// nullptr if `name` is not a central body.
const CentralBodyInfo* find_central_body(const std::string& name);

// Geocentric J2000 position (m) and velocity (m/s) of a central body: the
// Sun from eraEpv00 (the Earth's heliocentric state), the planets from the
// complete VSOP87B series (universe/vsop87.hpp; within 2" of JPL DE405)
// minus the Earth's (geometric, no light time), the Moon from eraMoon98,
// the Earth at the origin; the series at nodes kEphemerisGridStep_s apart
// (TT), cubic Lagrange interpolation through the four nodes around t:
// positions within 5 mm of the series' (the Moon; the Earth 1 mm, Mars
// 2 mm), against their own accuracy of km (Moon98 ~10 km, Epv00 ~1 km). The
// grid is fixed in TT, so results do not depend on what was asked before.
constexpr double kEphemerisGridStep_s = 1800.0;
void central_body_state_j2000(const CentralBodyInfo& body, const EngineTime& t, frames::Vec3& r_m,
                              frames::Vec3& v_m_s);

}  // namespace eoir::universe
