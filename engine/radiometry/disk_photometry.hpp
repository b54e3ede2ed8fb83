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
//    Left out: the Mars rotational and orbital terms (up to ~0.06 and ~0.09
//    mag), Saturn's rings (the globe alone, eqs. 11-12), the Uranus
//    sub-latitude term (-0.00084 mag/deg), Neptune before 2000 (eq. 16's
//    secular brightening). Past the last tabulated angle the law goes on as a
//    Lambertian sphere from there (continuous, no extrapolated polynomial).
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
//    near-side mean is p, data/moon/README.md) follow the same law.
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

// Mallama & Hilton (2018): V(1, alpha) [mag] of a planet at 1 au from the
// Sun and the observer, alpha in degrees within [0, upper limit]; and the
// last phase angle their formulas cover (the observed range).
double mallama_hilton_v_1_alpha(DiskPhaseLaw planet, double phase_angle_deg);
double mallama_hilton_upper_limit_deg(DiskPhaseLaw planet);

class DiskPhotometry {
 public:
  explicit DiskPhotometry(DiskPhaseLaw law = DiskPhaseLaw::lambertian_sphere) : law_(law) {}
  DiskPhaseLaw law() const { return law_; }
  bool lambertian() const { return law_ == DiskPhaseLaw::lambertian_sphere; }
  // p / SRF: 2/3 for a Lambertian sphere and the planets' gray bodies, 1 for
  // the Moon's Lommel-Seeliger surface (SRF = normal albedo = p).
  double geometric_albedo_per_srf() const;
  // Phase(psi) from cos psi (clamped to [-1, 1]); 1 at psi = 0.
  double phase(double cos_psi) const;

 private:
  DiskPhaseLaw law_;
};

}  // namespace eoir::radiometry
