// How bright a body's disc is as a whole (spec 4.1.6.1, eq. 7: the simple
// point source and the light a body sheds on others), and the lunar surface
// law that the Moon's patches, images and disc share.
//
// Eq. 7 writes the disc's irradiance at distance d as
//   E = E_sun(lambda) p(lambda) Phase(psi) (R / d)^2,
// p the geometric albedo and Phase(psi) the disc's phase law, 1 at psi = 0
// (psi: the Sun-body-observer angle). A Lambertian sphere has p = 2/3 SRF and
// Phase = (sin psi + (pi - psi) cos psi) / pi. Natural bodies follow their
// observed laws instead:
//  - the planets (Mercury..Neptune): Mallama & Hilton (2018), "Computing
//    apparent planetary magnitudes for The Astronomical Almanac", Astronomy
//    and Computing 25, 10-24, eqs. 2-17: V(1, alpha) over the phase angles
//    they tabulate; Phase = 10^(-0.4 (V(1, alpha) - V(1, 0))). Their default
//    gray-body SRF is 1.5 p with p from V(1, 0) (universe/central_bodies.cpp).
//    The terms that depend on the face seen (DiscView, face_terms_mag):
//    Mars' rotational and seasonal corrections L(lambda_e) + L(Ls) (eqs.
//    6-7; Mallama 2007 Tables 6 and 8, data/planets/
//    mars_brightness_corrections.csv), Saturn's rings (eq. 10, an option of
//    the planet, on by default: observed magnitudes include them), the
//    Uranus sub-latitude term (eqs. 13-14: -0.00084 mag per degree of the
//    mean planetographic sub-solar and sub-observer latitude). Left out:
//    Neptune before 2000 (eq. 16's secular brightening). Past the last
//    tabulated angle the law goes on as a Lambertian sphere from there
//    (continuous, no extrapolated polynomial). A resolved planet's patches
//    are Lambertian, their sunlight scaled by Phase(view) / Phase_Lambert
//    toward the observer or receiver (scene/world.cpp), so that the disc's
//    total is the law's.
//  - the Moon: a Lommel-Seeliger surface (radiance factor
//    I/F = A 2 mu0 / (mu0 + mu) f(g), A the normal albedo, f(0) = 1), whose
//    sphere has p = A (its full disc is uniform) and the disc law
//    Phase = Phi_LS(g) f(g), Phi_LS(g) = 1 - sin(g/2) tan(g/2) ln cot(g/4)
//    (the Lommel-Seeliger integral phase function). The surface phase
//    function f(g) (shadow hiding and the opposition surge of the regolith)
//    is the observed lunar phase law divided by Phi_LS: Allen (1973),
//    Astrophysical Quantities, 3rd ed., p. 144, as Krisciunas & Schaefer
//    (1991, PASP 103, 1033) eq. 20 write it,
//      Delta V(g) = 0.026 |g| + 4e-9 g^4  (g in degrees, to 150 deg),
//    constant past 150 deg. So the disc (simple model) and the sum over the
//    Moon's patches or pixels (detailed model, images; the albedo map's
//    near-side mean is p, data/moon/README.md) follow the same law; with the
//    map, the disc's SRF is the map's mean over the disc it shows (scene/
//    world.cpp, WorldObject::light_spectra), not over the sphere.
#pragma once
#include "universe/central_bodies.hpp"

namespace eoir::radiometry {

enum class DiskPhaseLaw { lambertian_sphere, moon, mercury, venus, mars, jupiter, saturn, uranus, neptune };

// The law of a central body (the Sun and the Earth: Lambertian spheres).
DiskPhaseLaw disk_phase_law(universe::CentralBody body);

// Eq. 7's Lambertian sphere, from cos psi (clamped to [-1, 1]).
double lambertian_sphere_phase(double cos_psi);
// Phi_LS(g), g in [0, pi] rad (clamped); 1 at 0, 0 at pi.
double lommel_seeliger_sphere_phase(double phase_angle_rad);
// Allen's lunar Delta V(g) [mag] (g in degrees, |g| <= 150; the value at
// 150 beyond).
double lunar_phase_magnitude(double phase_angle_deg);
// f(g) of the lunar Lommel-Seeliger surface (1 at 0; constant past 150 deg),
// and its largest value over [0, pi] (sampled every 0.1 deg once).
double lunar_surface_phase(double phase_angle_rad);
double lunar_surface_phase_max();
// The same from cos g (clamped to [-1, 1]), tabulated: within 1e-14 of it.
double lunar_surface_phase_of_cos(double cos_g);

// Mallama & Hilton (2018): V(1, alpha) [mag] of a planet at 1 au from the
// Sun and the observer, alpha in degrees within [0, upper limit]; and the
// last phase angle their formulas cover (the observed range).
double mallama_hilton_v_1_alpha(DiskPhaseLaw planet, double phase_angle_deg);
double mallama_hilton_upper_limit_deg(DiskPhaseLaw planet);

// What the face-dependent terms read: unit vectors from the body's centre
// toward the Sun and toward the observer, and its IAU body axes (z the north
// pole, x the prime meridian; universe/rotation_models.hpp), in J2000 axes.
struct DiscView {
  frames::Vec3 to_sun = frames::Vec3::UnitX(), to_observer = frames::Vec3::UnitX();
  frames::Mat3 body_to_j2000 = frames::Mat3::Identity();
};

// The angles those terms are tabulated in [deg].
struct FaceAngles {
  double phase_deg = 0;
  double sub_solar_latitude_deg = 0, sub_observer_latitude_deg = 0;  // planetocentric, on the body's equator
  double sub_solar_west_longitude_deg = 0, sub_observer_west_longitude_deg = 0;  // [0, 360)
  double heliocentric_ecliptic_longitude_deg = 0;  // of the body, J2000 ecliptic, [0, 360)
};
FaceAngles face_angles(const DiscView& view);

// Mars: the effective central meridian (the mean of the sub-observer and
// sub-solar west longitudes across the shorter arc, [0, 360)), Ls as
// Mallama & Hilton take it (heliocentric J2000 ecliptic longitude - 85 deg),
// and the two corrections [mag] interpolated in Mallama's (2007) tables by
// Stirling's central-difference formula (five nodes).
double mars_effective_central_meridian_deg(double sub_observer_west_deg, double sub_solar_west_deg);
double mars_solar_longitude_deg(double heliocentric_ecliptic_longitude_deg);
double mars_rotational_correction_mag(double effective_central_meridian_deg);
double mars_orbital_correction_mag(double solar_longitude_deg);
// Saturn's ring opening as eq. 10 reads it: the geometric mean of the
// planetocentric sub-solar and sub-observer latitudes when they have one
// sign (the lit face is seen), else 0 [deg, >= 0]; and eq. 10, V(1, alpha)
// of globe and rings (alpha <= 6.5 deg, opening <= 27 deg: the observed range).
double saturn_ring_opening_deg(double sub_solar_latitude_deg, double sub_observer_latitude_deg);
double saturn_with_rings_v_1_alpha(double phase_angle_deg, double ring_opening_deg);
// Uranus (eqs. 13-14): -0.00084 mag per degree of the mean of the absolute
// planetographic sub-solar and sub-observer latitudes.
double uranus_sub_latitude_mag(double sub_solar_planetographic_deg, double sub_observer_planetographic_deg);

// The face terms of a law [mag], added to V(1, alpha): 0 for the Moon, the
// Lambertian sphere and the planets without such terms. Saturn with rings:
// eq. 10 less the globe's eq. 11 at the same angle; past 6.5 deg (never seen
// from the Earth) that difference is held at its 6.5 deg value, and the
// opening is taken at most 27 deg.
double face_terms_mag(DiskPhaseLaw law, bool rings, const FaceAngles& angles);

class DiskPhotometry {
 public:
  explicit DiskPhotometry(DiskPhaseLaw law = DiskPhaseLaw::lambertian_sphere, bool rings = false)
      : law_(law), rings_(rings && law == DiskPhaseLaw::saturn) {}
  DiskPhaseLaw law() const { return law_; }
  bool lambertian() const { return law_ == DiskPhaseLaw::lambertian_sphere; }
  bool rings() const { return rings_; }
  // p / SRF: 2/3 for a Lambertian sphere and the planets' gray bodies, 1 for
  // the Moon's Lommel-Seeliger surface (SRF = normal albedo = p).
  double geometric_albedo_per_srf() const;
  // Phase(psi) from cos psi (clamped to [-1, 1]); 1 at psi = 0: the law
  // alone (Saturn's globe).
  double phase(double cos_psi) const;
  // With the face terms: Phase(psi) 10^(-0.4 face_terms_mag) (above 1 where
  // the terms brighten the disc: Saturn's open rings).
  double phase(const DiscView& view) const;
  // Whether the face terms apply (Mars, Uranus, Saturn with rings).
  bool has_face_terms() const;

 private:
  DiskPhaseLaw law_;
  bool rings_;
};

// Mars' tables (generated from data/planets/mars_brightness_corrections.csv):
// the corrections at 0, 10, ..., 350 deg.
namespace mars_corrections {
extern const double kRotationMag[36];
extern const double kOrbitMag[36];
}  // namespace mars_corrections

}  // namespace eoir::radiometry
