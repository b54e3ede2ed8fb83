#include "motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "iso_time.hpp"

namespace eoir::cli {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

// Wraps an angle into [-pi, pi).
double wrap_pi(double a) {
  a = std::fmod(a + kPi, kTwoPi);
  if (a < 0) a += kTwoPi;
  return a - kPi;
}
}  // namespace

// --------------------------------------------------------------- Kepler
double solve_kepler(double mean_anomaly, double e) {
  if (!(e >= 0.0 && e < 1.0)) throw std::invalid_argument("eccentricity must be in [0, 1)");
  if (!std::isfinite(mean_anomaly)) throw std::invalid_argument("mean anomaly is not finite");
  const double m = wrap_pi(mean_anomaly);
  const double turns = mean_anomaly - m;  // multiple of 2 pi that was removed
  // f(E) = E - e sin E - M is increasing; its root lies in [M - e, M + e].
  double lo = m - e, hi = m + e;
  // Danby's start: good for all e, and inside the bracket.
  double E = m + 0.85 * e * (std::sin(m) >= 0 ? 1.0 : -1.0);
  E = std::clamp(E, lo, hi);
  for (int i = 0; i < 100; ++i) {
    const double f = E - e * std::sin(E) - m;
    if (f > 0) hi = E; else lo = E;
    const double fp = 1.0 - e * std::cos(E);
    double next = E - f / fp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // bisection step
    if (std::fabs(next - E) <= 1e-15 * std::max(1.0, std::fabs(E))) {
      E = next;
      break;
    }
    E = next;
  }
  return E + turns;
}

double eccentric_to_true_anomaly(double E, double e) {
  return 2.0 * std::atan2(std::sqrt(1.0 + e) * std::sin(E / 2), std::sqrt(1.0 - e) * std::cos(E / 2));
}

double true_to_mean_anomaly(double nu, double e) {
  const double E = 2.0 * std::atan2(std::sqrt(1.0 - e) * std::sin(nu / 2), std::sqrt(1.0 + e) * std::cos(nu / 2));
  return E - e * std::sin(E);
}

KeplerOrbit::KeplerOrbit(const KeplerElements& el) : el_(el) {
  if (!(el.semi_major_axis_m > 0) || !std::isfinite(el.semi_major_axis_m))
    throw std::invalid_argument("semi_major_axis_km: must be positive");
  if (!(el.eccentricity >= 0 && el.eccentricity < 1))
    throw std::invalid_argument("eccentricity: must be in [0, 1) (elliptic orbits only)");
  if (el.semi_major_axis_m * (1 - el.eccentricity) < 1.0)
    throw std::invalid_argument("semi_major_axis_km: perigee radius below 1 m");
  if (!(el.mu_m3s2 > 0)) throw std::invalid_argument("mu: must be positive");
  for (double a : {el.inclination, el.raan, el.arg_perigee, el.mean_anomaly_at_epoch, el.epoch_s})
    if (!std::isfinite(a)) throw std::invalid_argument("angles and epoch must be finite");
  mean_motion_ = std::sqrt(el.mu_m3s2 / (el.semi_major_axis_m * el.semi_major_axis_m * el.semi_major_axis_m));
  const double cO = std::cos(el.raan), sO = std::sin(el.raan);
  const double ci = std::cos(el.inclination), si = std::sin(el.inclination);
  const double cw = std::cos(el.arg_perigee), sw = std::sin(el.arg_perigee);
  pq_[0] = {cO * cw - sO * sw * ci, sO * cw + cO * sw * ci, sw * si};
  pq_[1] = {-cO * sw - sO * cw * ci, -sO * sw + cO * cw * ci, cw * si};
}

double KeplerOrbit::period_s() const { return kTwoPi / mean_motion_; }

PosVel KeplerOrbit::at(double t_s) const {
  const double e = el_.eccentricity, a = el_.semi_major_axis_m;
  // Reduce the mean anomaly before adding to keep precision over many orbits.
  const double dm = std::fmod(mean_motion_ * (t_s - el_.epoch_s), kTwoPi);
  const double E = solve_kepler(el_.mean_anomaly_at_epoch + dm, e);
  const double cE = std::cos(E), sE = std::sin(E);
  const double b = a * std::sqrt(1 - e * e);
  const double r = a * (1 - e * cE);
  // Perifocal position and velocity from the eccentric anomaly.
  const double xp = a * (cE - e), yp = b * sE;
  const double edot = mean_motion_ * a / r;
  const double vxp = -a * sE * edot, vyp = b * cE * edot;
  PosVel s;
  for (int k = 0; k < 3; ++k) {
    s.position[k] = xp * pq_[0][k] + yp * pq_[1][k];
    s.velocity[k] = vxp * pq_[0][k] + vyp * pq_[1][k];
  }
  return s;
}

double orbital_energy(const PosVel& s, double mu) {
  return 0.5 * dot(s.velocity, s.velocity) - mu / norm(s.position);
}

// ------------------------------------------------------------ Ephemeris
Ephemeris::Ephemeris(std::vector<EphemerisPoint> points, bool has_velocity) : points_(std::move(points)) {
  if (points_.size() < 2) throw std::invalid_argument("an ephemeris needs at least 2 points");
  for (std::size_t i = 1; i < points_.size(); ++i)
    if (!(points_[i].t_s > points_[i - 1].t_s))
      throw std::invalid_argument("points[" + std::to_string(i) + "].time: times must increase strictly");
  if (!has_velocity) {
    const std::size_t n = points_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
      points_[i].velocity = scale(sub(points_[b].position, points_[a].position),
                                  1.0 / (points_[b].t_s - points_[a].t_s));
    }
  }
}

PosVel Ephemeris::at(double t) const {
  if (!(t >= begin_s() && t <= end_s()))
    throw std::out_of_range("time " + format_iso(t) + " outside the ephemeris [" + format_iso(begin_s()) + ", " +
                            format_iso(end_s()) + "]");
  auto it = std::upper_bound(points_.begin(), points_.end(), t,
                             [](double x, const EphemerisPoint& p) { return x < p.t_s; });
  if (it == points_.end()) --it;  // t == end
  const EphemerisPoint& p1 = *it;
  const EphemerisPoint& p0 = *(it - 1);
  const double h = p1.t_s - p0.t_s, s = (t - p0.t_s) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  PosVel out;
  for (int k = 0; k < 3; ++k) {
    out.position[k] = h00 * p0.position[k] + h10 * h * p0.velocity[k] + h01 * p1.position[k] + h11 * h * p1.velocity[k];
    out.velocity[k] = (d00 * p0.position[k] + d01 * p1.position[k]) / h + d10 * p0.velocity[k] + d11 * p1.velocity[k];
  }
  if (s == 0.0) out = {p0.position, p0.velocity};
  if (s == 1.0) out = {p1.position, p1.velocity};
  return out;
}

// ----------------------------------------------------------- Ballistic
BallisticArc::BallisticArc(double lat1, double lon1, double lat2, double lon2, double launch_s, double burn_s,
                           double apogee_height_m)
    : launch_s_(launch_s), burn_s_(burn_s) {
  for (double v : {lat1, lon1, lat2, lon2, launch_s})
    if (!std::isfinite(v))
      throw std::invalid_argument("launch_lat_deg: launch and impact coordinates and times must be finite");
  if (!(burn_s >= 0) || !std::isfinite(burn_s)) throw std::invalid_argument("burn_s: must be >= 0");
  // The directions of the geodetic surface points (the arc ends on them).
  const auto unit = [](double lat, double lon) { return normalize(geodetic_to_ecef(lat, lon, 0.0)); };
  const Vec3 u1 = unit(lat1, lon1), u2 = unit(lat2, lon2);
  theta_ = std::atan2(norm(cross(u1, u2)), dot(u1, u2));
  const double R = kBallisticEarthRadius_m;
  if (!(theta_ * R > 1e3))
    throw std::invalid_argument("impact_lat_deg: the impact lies within 1 km of the launch point");
  if (!(theta_ < kPi - 1e-6))
    throw std::invalid_argument("impact_lat_deg: the impact is antipodal to the launch point (no single plane)");
  e1_ = u1;
  e2_ = normalize(sub(u2, scale(u1, dot(u1, u2))));
  const double c = std::cos(theta_ / 2), s = std::sin(theta_ / 2);
  if (std::isnan(apogee_height_m)) {  // minimum energy
    a_ = R * (1 + s) / 2;
    e_ = c / (1 + s);
  } else {
    if (!(apogee_height_m >= 1e3) || !std::isfinite(apogee_height_m))
      throw std::invalid_argument("apogee_height_m: must be at least 1 km");
    const double ra = R + apogee_height_m;
    e_ = (ra - R) / (ra - R * c);
    a_ = ra / (1 + e_);
  }
  const double mu = kMuEarthKm3s2 * 1e9;
  n_ = std::sqrt(mu / (a_ * a_ * a_));
  // The launch point at true anomaly pi - theta/2 (apogee at pi), the impact
  // at pi + theta/2: symmetric mean anomalies pi -/+ delta.
  const double delta = kPi - true_to_mean_anomaly(kPi - theta_ / 2, e_);
  m0_ = kPi - delta;
  flight_s_ = 2 * delta / n_;
  if (!(burn_s < 2 * flight_s_))
    throw std::invalid_argument("burn_s: must be below twice the free flight (" + std::to_string(flight_s_) + " s)");
}

PosVel BallisticArc::kepler_at(double tau) const {
  const double E = solve_kepler(m0_ + n_ * tau, e_);
  double nu = eccentric_to_true_anomaly(E, e_);
  if (nu < 0) nu += kTwoPi;
  const double phi = nu - kPi + theta_ / 2;  // from the launch point in the plane
  const double p = a_ * (1 - e_ * e_), r = p / (1 + e_ * std::cos(nu));
  const double k = std::sqrt(kMuEarthKm3s2 * 1e9 / p);
  const Vec3 radial = add(scale(e1_, std::cos(phi)), scale(e2_, std::sin(phi)));
  const Vec3 along = add(scale(e1_, -std::sin(phi)), scale(e2_, std::cos(phi)));
  return PosVel{scale(radial, r), add(scale(radial, k * e_ * std::sin(nu)), scale(along, k * (1 + e_ * std::cos(nu))))};
}

PosVel BallisticArc::at(double t) const {
  const double s = std::clamp(t - launch_s_, 0.0, burn_s_ / 2 + flight_s_);
  double tau = s - burn_s_ / 2, rate = 1;
  if (s < burn_s_) {  // powered: tau = s^2 / (2 burn), d tau / ds = s / burn
    tau = s * s / (2 * burn_s_);
    rate = s / burn_s_;
  }
  PosVel out = kepler_at(std::clamp(tau, 0.0, flight_s_));
  out.velocity = scale(out.velocity, rate);
  if (t < launch_s_ || t - launch_s_ >= burn_s_ / 2 + flight_s_) out.velocity = {0, 0, 0};  // on the pad, landed
  // Height above the sphere laid above the WGS84 ellipsoid along the same direction.
  constexpr double a = 6378137.0, b = 6356752.314245;
  const Vec3 u = normalize(out.position);
  const double ellipsoid = 1.0 / std::sqrt((u[0] * u[0] + u[1] * u[1]) / (a * a) + u[2] * u[2] / (b * b));
  out.position = add(out.position, scale(u, ellipsoid - kBallisticEarthRadius_m));
  return out;
}

// ------------------------------------------------------------- vectors
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 normalize(const Vec3& a) {
  const double n = norm(a);
  if (!(n > 0) || !std::isfinite(n)) throw std::domain_error("cannot normalize a zero or non-finite vector");
  return scale(a, 1.0 / n);
}

Quat normalize(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 0) || !std::isfinite(n)) throw std::domain_error("quaternion is zero or not finite");
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

Quat quat_from_axes(const Vec3& x, const Vec3& y, const Vec3& z) {
  // R = [x y z] (columns); Shepperd's method.
  const double m00 = x[0], m11 = y[1], m22 = z[2];
  const double tr = m00 + m11 + m22;
  Quat q;
  if (tr > 0) {
    const double s = std::sqrt(tr + 1.0) * 2;
    q = {0.25 * s, (y[2] - z[1]) / s, (z[0] - x[2]) / s, (x[1] - y[0]) / s};
  } else if (m00 > m11 && m00 > m22) {
    const double s = std::sqrt(1.0 + m00 - m11 - m22) * 2;
    q = {(y[2] - z[1]) / s, 0.25 * s, (y[0] + x[1]) / s, (z[0] + x[2]) / s};
  } else if (m11 > m22) {
    const double s = std::sqrt(1.0 + m11 - m00 - m22) * 2;
    q = {(z[0] - x[2]) / s, (y[0] + x[1]) / s, 0.25 * s, (z[1] + y[2]) / s};
  } else {
    const double s = std::sqrt(1.0 + m22 - m00 - m11) * 2;
    q = {(x[1] - y[0]) / s, (z[0] + x[2]) / s, (z[1] + y[2]) / s, 0.25 * s};
  }
  if (q[0] < 0) q = {-q[0], -q[1], -q[2], -q[3]};
  return normalize(q);
}

Vec3 rotate(const Quat& q, const Vec3& v) {
  const Vec3 u{q[1], q[2], q[3]};
  const Vec3 t = scale(cross(u, v), 2.0);
  return add(add(v, scale(t, q[0])), cross(u, t));
}

Quat multiply(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

Quat conjugate(const Quat& q) { return {q[0], -q[1], -q[2], -q[3]}; }

Quat heading_pitch_roll(double heading_deg, double pitch_deg, double roll_deg) {
  constexpr double rad = 3.14159265358979323846 / 180.0;
  return normalize(multiply(axis_angle({0, 0, 1}, heading_deg * rad),
                            multiply(axis_angle({0, 1, 0}, pitch_deg * rad), axis_angle({1, 0, 0}, roll_deg * rad))));
}

Quat axis_angle(const Vec3& axis, double angle_rad) {
  const Vec3 u = normalize(axis);
  const double s = std::sin(0.5 * angle_rad);
  return {std::cos(0.5 * angle_rad), u[0] * s, u[1] * s, u[2] * s};
}

Vec3 angular_velocity(const Quat& q0, const Quat& q1, double dt_s) {
  Quat d = multiply(q1, conjugate(q0));  // q1 = d q0: d turns frame vectors
  if (d[0] < 0) d = {-d[0], -d[1], -d[2], -d[3]};
  const double s = std::sqrt(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
  if (s == 0) return {0, 0, 0};
  const double angle = 2.0 * std::atan2(s, d[0]);
  return scale(Vec3{d[1] / s, d[2] / s, d[3] / s}, angle / dt_s);
}

Quat point_z_axis(const Vec3& boresight, const Vec3& hint) {
  const Vec3 z = normalize(boresight);
  Vec3 x = sub(hint, scale(z, dot(hint, z)));
  if (!(norm(x) > 1e-9 * std::max(1.0, norm(hint)))) {
    // Hint parallel to the boresight (or zero): the frame axis least along z.
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(z[i]) < std::fabs(z[k])) k = i;
    Vec3 axis{0, 0, 0};
    axis[k] = 1;
    x = sub(axis, scale(z, dot(axis, z)));
  }
  x = normalize(x);
  const Vec3 y = cross(z, x);
  return quat_from_axes(x, y, z);
}

Quat velocity_attitude(const PosVel& s) {
  return norm(s.velocity) > 0 ? point_z_axis(s.velocity, s.position) : point_z_axis(s.position, {0, 0, 1});
}

Quat nadir_attitude(const PosVel& s) { return point_z_axis(scale(s.position, -1.0), s.velocity); }

Vec3 geodetic_to_ecef(double lat_deg, double lon_deg, double h) {
  constexpr double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double lat = lat_deg * kPi / 180, lon = lon_deg * kPi / 180;
  const double n = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
  return {(n + h) * std::cos(lat) * std::cos(lon), (n + h) * std::cos(lat) * std::sin(lon),
          (n * (1 - e2) + h) * std::sin(lat)};
}

}  // namespace eoir::cli
