#include "scene/astrometric_frame.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "universe/astrometric_place.hpp"

namespace eoir::scene {

AstrometricFrame::AstrometricFrame(const World& w)
    : context_(universe::apparent_place_context_geocentric(w.time, w.observer.position_m, w.observer.velocity_m_s)) {
  // The image maps pixels to apparent directions by the gnomonic projection
  // about the boresight (geometry/sample_grid.hpp); composed with the
  // astrometric map it is the TAN projection about the boresight's
  // astrometric place with a linear part that the CD matrix holds at the
  // centre (aberration is conformal: the map differs from a TAN one by
  // (v/c) theta^2, 1e-8 of a 3 deg field). The derivatives are central
  // differences over one pixel (the map is smooth: no truncation error
  // above 1e-12 of the pitch).
  const geometry::SampleGrid& g = w.grid();
  const Mat3& to_j2000 = w.observer.body_to_j2000;
  const double cx = 0.5 * static_cast<double>(g.pixels_x - 1), cy = 0.5 * static_cast<double>(g.pixels_y - 1);
  const double pitch_x = g.pitch_x_cm / g.focal_length_cm, pitch_y = g.pitch_y_cm / g.focal_length_cm;
  const auto seen = [&](double column, double row) {
    const Vec3 body((cx - column) * pitch_x, (cy - row) * pitch_y, 1.0);  // column toward body -x, row toward -y
    return astrometric(to_j2000 * body);
  };
  const Vec3 centre = seen(cx, cy);
  const double polar = std::hypot(centre.x(), centre.y());  // 0 at a pole: RA 0's east
  const Vec3 east = polar > 0 ? Vec3(-centre.y() / polar, centre.x() / polar, 0.0) : Vec3::UnitY();
  const Vec3 north = centre.cross(east);
  const auto standard = [&](const Vec3& q, double& xi, double& eta) {  // gnomonic, degrees
    xi = q.dot(east) / q.dot(centre) * constants::deg_per_rad;
    eta = q.dot(north) / q.dot(centre) * constants::deg_per_rad;
  };
  double xi_p = 0, eta_p = 0, xi_m = 0, eta_m = 0;
  standard(seen(cx + 1, cy), xi_p, eta_p);
  standard(seen(cx - 1, cy), xi_m, eta_m);
  wcs_.cd_deg[0] = 0.5 * (xi_p - xi_m);
  wcs_.cd_deg[2] = 0.5 * (eta_p - eta_m);
  standard(seen(cx, cy + 1), xi_p, eta_p);
  standard(seen(cx, cy - 1), xi_m, eta_m);
  wcs_.cd_deg[1] = 0.5 * (xi_p - xi_m);
  wcs_.cd_deg[3] = 0.5 * (eta_p - eta_m);
  wcs_.ra_deg = std::atan2(centre.y(), centre.x()) * constants::deg_per_rad;
  if (wcs_.ra_deg < 0) wcs_.ra_deg += 360.0;
  wcs_.dec_deg = std::asin(std::fmax(-1.0, std::fmin(1.0, centre.z()))) * constants::deg_per_rad;
}

Vec3 AstrometricFrame::astrometric(const Vec3& d) const { return universe::astrometric_direction(d, context_); }

}  // namespace eoir::scene
