#include "scene/sight_lines.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace eoir::scene {
namespace {
// Nodes (by default, the fidelity's atmosphere_sight_line_nodes n = 33 and
// atmosphere_sky_azimuths 49): n lines that meet the ground, from above:
// mu_g = (k / (n - 1))^2 there; m = (3 (n - 1) + 2) / 4 + 1 (25) lines through
// the limb: tangent altitude top (k / (m - 1))^2, and from inside, above the
// horizon: (pi / 2) (k / (m - 1))^1.6; azimuths 0..pi from the Sun's
// vertical plane (3.75 deg apart).
int other_nodes(int ground_nodes) { return (3 * (ground_nodes - 1) + 2) / 4 + 1; }

// atan2(y, x) for y >= 0, in [0, pi], within 1e-5 rad (Abramowitz and
// Stegun 4.4.49): a per-sample lookup's azimuth.
double azimuth_rad(double y, double x) {
  const double ax = std::fabs(x);
  const double big = std::max(ax, y), small = std::min(ax, y);
  if (!(big > 0)) return 0.0;
  const double t = small / big, t2 = t * t;
  double a = t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
  if (y > ax) a = 0.5 * constants::pi - a;
  return x < 0 ? constants::pi - a : a;
}
}  // namespace

SightLines SightLines::make(const atmosphere::PathOptics& optics, const atmosphere::EarthFigure& figure,
                            double observer_altitude_m, int ground_nodes) {
  const int kGroundNodes = std::max(2, ground_nodes);
  const int kLimbNodes = std::max(2, other_nodes(kGroundNodes)), kElevationNodes = kLimbNodes;
  SightLines s;
  const atmosphere::AtmosphereProfile& profile = optics.profile();
  atmosphere::EarthFigure earth = figure;
  earth.centre_m = Vec3::Zero();
  const Vec3 up = earth.pole.unitOrthogonal(), across = earth.pole.cross(up);  // the equator: a circle of radius a
  const double a = earth.equatorial_radius_m, top = profile.top_altitude_m(), r_top = a + top;
  s.above = observer_altitude_m >= top;
  s.top_radius_m = r_top;
  const auto add = [&](double at, const atmosphere::PathColumns& path) {
    s.node.push_back(at);
    s.paths.push_back(atmosphere::ScatterPath::make(optics, path));
  };
  if (s.above) {
    // Down the line x = p across + t (-up), from where it enters the top.
    const auto line = [&](double p, double end_t) {
      const Vec3 entry = p * across + std::sqrt(std::max(0.0, r_top * r_top - p * p)) * up;
      return atmosphere::path_between(profile, earth, entry, entry - end_t * up);
    };
    for (int k = kGroundNodes - 1; k >= 0; --k) {
      const double mu = std::pow(static_cast<double>(k) / (kGroundNodes - 1), 2.0);
      const double p = a * std::sqrt(1.0 - mu * mu);
      add(p, line(p, std::sqrt(r_top * r_top - p * p) - std::sqrt(std::max(0.0, a * a - p * p))));
    }
    for (int k = 1; k < kLimbNodes; ++k) {
      const double p = a + top * std::pow(static_cast<double>(k) / (kLimbNodes - 1), 2.0);
      add(p, line(p, 2.0 * std::sqrt(std::max(0.0, r_top * r_top - p * p))));
    }
    return s;
  }
  // Inside: lines below the horizon as from above, by the ground point's
  // zenith cosine and the tangent altitude below the observer (dense toward
  // the dip of the horizon); above it by elevation (dense toward it).
  const double h = std::max(0.0, observer_altitude_m);
  const double r_observer = a + h;
  const Vec3 observer = r_observer * up;
  const auto add_elevation = [&](double e) {
    bool ground = false;
    add(e, atmosphere::refracted_path_to_space(profile, earth, observer, std::sin(e) * up + std::cos(e) * across,
                                               ground));
  };
  const auto elevation_of = [&](double p) { return -std::acos(std::min(1.0, p / r_observer)); };
  for (int k = kGroundNodes - 1; k >= 0; --k) {
    const double mu = std::pow(static_cast<double>(k) / (kGroundNodes - 1), 2.0);
    add_elevation(elevation_of(a * std::sqrt(1.0 - mu * mu)));
  }
  if (h > 0)
    for (int k = 1; k < kLimbNodes; ++k) add_elevation(elevation_of(a + h * std::pow(static_cast<double>(k) / (kLimbNodes - 1), 2.0)));
  for (int k = 1; k < kElevationNodes; ++k)
    add_elevation(0.5 * constants::pi * std::pow(static_cast<double>(k) / (kElevationNodes - 1), 1.6));
  return s;
}

SkyView::SkyView(std::shared_ptr<const SightLines> lines, std::shared_ptr<const atmosphere::SunlightTable> sunlight,
                 const atmosphere::EarthFigure& earth, const Vec3& to_sun, const std::vector<double>& sun_irradiance,
                 const std::vector<double>& background_radiance, const std::vector<double>& airglow_zenith,
                 const radiometry::SpectralView& view, std::size_t azimuths)
    : lines_(std::move(lines)),
      intervals_(sunlight->intervals()),
      earth_(earth),
      azimuths_(std::max<std::size_t>(2, azimuths)),
      sunlight_(std::move(sunlight)),
      sun_irradiance_(sun_irradiance),
      view_(view) {
  const SightLines& L = *lines_;
  centre_ = atmosphere::to_sphere_space(earth, -earth.centre_m);
  vertical_ = centre_.normalized();
  sun_ = atmosphere::to_sphere_space(earth, to_sun).normalized();
  x_ = sun_ - sun_.dot(vertical_) * vertical_;
  x_ = x_.norm() > 1e-9 ? x_.normalized() : vertical_.unitOrthogonal();
  y_ = vertical_.cross(x_);
  for (const double node : L.node) coordinate_.push_back(L.above ? node : std::sin(node));
  scatter_.resize(L.node.size() * azimuths_);
  scatter_band_.resize(scatter_.size());
  made_ = std::make_unique<std::atomic<bool>[]>(scatter_.size());
  for (std::size_t k = 0; k < scatter_.size(); ++k) made_[k].store(false, std::memory_order_relaxed);
  for (std::size_t j = 0; j < L.node.size(); ++j) {
    // What the line's air adds without the Sun: its emission, the background
    // seen through it, and the airglow's layer (its near pass above nearly
    // all the air, the far one through the line's).
    std::vector<double> sky = L.paths[j].terms.thermal;
    const std::vector<double>& T = L.paths[j].terms.transmittance;
    if (!background_radiance.empty())
      for (std::size_t i = 0; i < intervals_; ++i) sky[i] += background_radiance[i] * T[i];
    if (!airglow_zenith.empty()) {
      const double r = centre_.norm(), q = L.above ? L.node[j] / r : 0.0;
      const double mu = L.above ? -std::sqrt(std::max(0.0, 1.0 - q * q)) : std::sin(L.node[j]);
      const atmosphere::Airglow::Passes g = atmosphere::Airglow::passes(earth.equatorial_radius_m, r, mu);
      for (std::size_t i = 0; i < intervals_; ++i) sky[i] += airglow_zenith[i] * (g.near + g.far * T[i]);
    }
    sky_band_.push_back(view.integrate(sky));
    sky_.push_back(std::move(sky));
  }
}

void SkyView::make_cell(std::size_t k) const {
  const SightLines& L = *lines_;
  const std::size_t j = k / azimuths_, m = k % azimuths_;
  const double psi = constants::pi * static_cast<double>(m) / static_cast<double>(azimuths_ - 1);
  const Vec3 horizontal = std::cos(psi) * x_ + std::sin(psi) * y_;
  Vec3 d, start = centre_;
  if (L.above) {
    const double p = L.node[j], r_o = centre_.norm();
    const double mu = -std::sqrt(std::max(0.0, 1.0 - (p / r_o) * (p / r_o)));
    d = mu * vertical_ + std::sqrt(std::max(0.0, 1.0 - mu * mu)) * horizontal;
    // (the path begins where the line enters the top of the air)
    const double r_top = L.top_radius_m;
    start = centre_ + (-centre_.dot(d) - std::sqrt(std::max(0.0, r_top * r_top - p * p))) * d;
  } else {
    const double e = L.node[j];
    d = std::sin(e) * vertical_ + std::cos(e) * horizontal;
  }
  std::vector<double> out(intervals_, 0.0);
  atmosphere::add_single_scatter(L.paths[j], start, d, sun_, sun_irradiance_, *sunlight_, out);
  scatter_band_[k] = view_.integrate(out);
  scatter_[k] = std::move(out);
}

const std::vector<double>& SkyView::cell_scatter(std::size_t k) const {
  if (!made_[k].load(std::memory_order_acquire)) {
    const std::lock_guard<std::mutex> lock(making_);
    if (!made_[k].load(std::memory_order_relaxed)) {
      make_cell(k);
      made_[k].store(true, std::memory_order_release);
    }
  }
  return scatter_[k];
}

double SkyView::cell_band(std::size_t k) const {
  cell_scatter(k);
  return scatter_band_[k];
}

SkyView::Cell SkyView::cell_of(const Vec3& direction) const {
  Cell c;
  const SightLines& L = *lines_;
  const Vec3 d = atmosphere::to_sphere_space(earth_, direction).normalized();
  double x;
  if (L.above) {
    if (centre_.dot(d) >= 0) return c;  // heading away from the air
    x = centre_.cross(d).norm();
    if (x >= L.node.back()) return c;
  } else {
    x = d.dot(vertical_);  // the sine of the elevation
  }
  c.inside = true;
  const std::vector<double>& n = coordinate_;
  const double xc = std::clamp(x, n.front(), n.back());
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(std::upper_bound(n.begin(), n.end(), xc) - n.begin()),
                                              n.size() - 1);
  c.node = k == 0 ? 0 : k - 1;
  const double fn = n[c.node + 1] > n[c.node] ? (xc - n[c.node]) / (n[c.node + 1] - n[c.node]) : 0.0;
  const double psi = azimuth_rad(std::fabs(d.dot(y_)), d.dot(x_));  // 0..pi
  const double a = psi / constants::pi * static_cast<double>(azimuths_ - 1);
  c.azimuth = std::min<std::size_t>(static_cast<std::size_t>(a), azimuths_ - 2);
  const double fa = std::clamp(a - static_cast<double>(c.azimuth), 0.0, 1.0);
  c.weight[0] = (1 - fn) * (1 - fa);
  c.weight[1] = fn * (1 - fa);
  c.weight[2] = (1 - fn) * fa;
  c.weight[3] = fn * fa;
  return c;
}

template <class Value>
double SkyView::blend(const Cell& c, Value value) const {
  const std::size_t A = azimuths_;
  const std::size_t i00 = c.node * A + c.azimuth;
  const std::size_t idx[4] = {i00, i00 + A, i00 + 1, i00 + A + 1};
  double sum = 0;
  for (int q = 0; q < 4; ++q)
    if (c.weight[q] != 0) sum += c.weight[q] * value(idx[q]);
  return sum;
}

double SkyView::scatter_band(const Vec3& d) const {
  const Cell c = cell_of(d);
  if (!c.inside) return 0.0;
  return blend(c, [&](std::size_t i) { return cell_band(i); });
}

bool SkyView::sky_band(const Vec3& d, double& out) const {
  const Cell c = cell_of(d);
  if (!c.inside) return false;
  const double own = (c.weight[0] + c.weight[2]) * sky_band_[c.node] + (c.weight[1] + c.weight[3]) * sky_band_[c.node + 1];
  out = own + blend(c, [&](std::size_t i) { return cell_band(i); });
  return true;
}

void SkyView::scatter(const Vec3& d, std::vector<double>& out) const {
  out.assign(intervals_, 0.0);
  const Cell c = cell_of(d);
  if (!c.inside) return;
  const std::size_t A = azimuths_, i00 = c.node * A + c.azimuth;
  const std::size_t idx[4] = {i00, i00 + A, i00 + 1, i00 + A + 1};
  for (int q = 0; q < 4; ++q) {
    if (c.weight[q] == 0) continue;
    const std::vector<double>& v = cell_scatter(idx[q]);
    for (std::size_t i = 0; i < intervals_; ++i) out[i] += c.weight[q] * v[i];
  }
}

bool SkyView::sky(const Vec3& d, std::vector<double>& out) const {
  const Cell c = cell_of(d);
  if (!c.inside) return false;
  scatter(d, out);
  const double w0 = c.weight[0] + c.weight[2], w1 = c.weight[1] + c.weight[3];
  for (std::size_t i = 0; i < intervals_; ++i) out[i] += w0 * sky_[c.node][i] + w1 * sky_[c.node + 1][i];
  return true;
}

bool SkyView::path(const Vec3& d, std::vector<double>& T, std::vector<double>& thermal) const {
  const Cell c = cell_of(d);
  if (!c.inside) return false;
  const double w0 = c.weight[0] + c.weight[2], w1 = c.weight[1] + c.weight[3];
  const atmosphere::PathTerms& a = lines_->paths[c.node].terms;
  const atmosphere::PathTerms& b = lines_->paths[c.node + 1].terms;
  T.resize(intervals_);
  thermal.resize(intervals_);
  for (std::size_t i = 0; i < intervals_; ++i) {
    T[i] = w0 * a.transmittance[i] + w1 * b.transmittance[i];
    thermal[i] = w0 * a.thermal[i] + w1 * b.thermal[i];
  }
  return true;
}

}  // namespace eoir::scene
