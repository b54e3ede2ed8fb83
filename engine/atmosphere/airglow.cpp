#include "atmosphere/airglow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "atmosphere/data_table.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {

Airglow Airglow::load(const std::string& data_dir) {
  const std::string path = data_dir + "/atmosphere/airglow_nightglow.csv";
  const DataTable t = read_data_table(path);
  const std::size_t lo = t.column("low_um"), hi = t.column("high_um"), r = t.column("zenith_R");
  Airglow a;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const Feature f{t.rows[i][lo], t.rows[i][hi], t.rows[i][r]};
    if (!(f.low_um > 0 && f.high_um > f.low_um && f.high_um < 1e3 && f.zenith_R >= 0 && f.zenith_R < 1e9))
      throw Error(Status::corrupt_file, path + ":" + std::to_string(t.line[i]) + ": feature '" + t.key[i] +
                                            "' needs 0 < low_um < high_um and zenith_R >= 0");
    a.features_.push_back(f);
  }
  if (a.features_.empty()) throw Error(Status::corrupt_file, path + ": no features");
  return a;
}

std::vector<double> Airglow::zenith_radiance(double low_um, double interval_um, std::size_t intervals) const {
  // 1 R = 1e6 / (4 pi) photons s^-1 cm^-2 sr^-1; a photon of wavelength l um
  // carries h c / (l 1e-6 m) J: spread evenly in photons over [lo, hi], the
  // energy between a and b is R 1e6 / (4 pi) h c 1e6 ln(b / a) / (hi - lo).
  const double per_R = 1e6 / (4.0 * constants::pi) * constants::planck_J_s * constants::speed_of_light_m_per_s * 1e6;
  std::vector<double> L(intervals, 0.0);
  for (std::size_t i = 0; i < intervals; ++i) {
    const double a = low_um + interval_um * static_cast<double>(i), b = a + interval_um;
    for (const Feature& f : features_) {
      const double x = std::max(a, f.low_um), y = std::min(b, f.high_um);
      if (y > x) L[i] += f.zenith_R * per_R * std::log(y / x) / (f.high_um - f.low_um) / interval_um;
    }
  }
  return L;
}

Airglow::Passes Airglow::passes(double earth_radius_m, double r_m, double mu) {
  // Along s >= 0 the radius is sqrt(r^2 + 2 r mu s + s^2): a sphere of radius
  // R is crossed at s = -r mu -+ sqrt(R^2 - p^2), p = r sqrt(1 - mu^2).
  const double p2 = r_m * r_m * std::max(0.0, 1.0 - mu * mu), b = -r_m * mu;
  double end = std::numeric_limits<double>::infinity();
  if (earth_radius_m * earth_radius_m > p2) {
    const double ground = b - std::sqrt(earth_radius_m * earth_radius_m - p2);
    if (ground > 0) end = ground;
  }
  const auto piece = [&](double from, double to) { return std::max(0.0, std::min(to, end) - std::max(from, 0.0)); };
  const double r1 = earth_radius_m + airglow_layer_bottom_m, r2 = earth_radius_m + airglow_layer_top_m;
  if (!(r2 * r2 > p2)) return {};
  const double outer = std::sqrt(r2 * r2 - p2);
  const double inner = r1 * r1 > p2 ? std::sqrt(r1 * r1 - p2) : 0.0;
  const double thickness = r2 - r1;
  return {piece(b - outer, b - inner) / thickness, piece(b + inner, b + outer) / thickness};
}

}  // namespace eoir::atmosphere
