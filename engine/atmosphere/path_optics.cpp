#include "atmosphere/path_optics.hpp"

#include <algorithm>
#include <cmath>

#include "atmosphere/molecular_absorption.hpp"
#include "atmosphere/rayleigh.hpp"
#include "radiometry/planck.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {
const char* aerosol_name(universe::AerosolModel m) {
  switch (m) {
    case universe::AerosolModel::urban: return "urban";
    case universe::AerosolModel::maritime: return "maritime";
    default: return "rural";
  }
}
// LOWTRAN 7's humidity of the tropospheric aerosol above the boundary layer.
constexpr double kBackgroundHumidity_pct = 70.0;
}  // namespace

PathOptics::PathOptics(std::shared_ptr<const AtmosphereProfile> profile, const universe::AtmosphereSettings& settings,
                       const std::string& data_dir, const radiometry::SpectralBand& band,
                       double sub_sample_spacing_cm1)
    : profile_(std::move(profile)), band_(band) {
  const double dl = band.interval_um();
  for (std::int64_t i = 0; i < band.intervals; ++i) {
    first_.push_back(wavelength_um_.size());
    const double lo = band.low_um + static_cast<double>(i) * dl, hi = lo + dl;
    const double width_cm1 = 1e4 / lo - 1e4 / hi;
    const int n = std::max(1, static_cast<int>(std::ceil(width_cm1 / sub_sample_spacing_cm1)));
    for (int s = 0; s < n; ++s) wavelength_um_.push_back(lo + (s + 0.5) / n * dl);
  }
  first_.push_back(wavelength_um_.size());
  const Densities ground = profile_->levels().front().at;
  const AerosolSpectra boundary =
      AerosolSpectra::load(data_dir, aerosol_name(settings.aerosol), relative_humidity_pct(ground.h2o_m3, ground.temperature_K));
  const AerosolSpectra background = AerosolSpectra::load(data_dir, "tropospheric", kBackgroundHumidity_pct);
  for (const double l : wavelength_um_) {
    rayleigh_m2_.push_back(rayleigh_cross_section_m2(l));
    const AerosolOptics b = boundary.at(l), t = background.at(l);
    boundary_per_550_.push_back(b.extinction_per_550);
    background_per_550_.push_back(t.extinction_per_550);
    boundary_albedo_.push_back(b.single_scatter_albedo);
    background_albedo_.push_back(t.single_scatter_albedo);
    boundary_g_.push_back(b.asymmetry);
    background_g_.push_back(t.asymmetry);
  }
  molecules_ = MolecularAbsorption::load(data_dir);
}

PathOptics::~PathOptics() = default;

void PathOptics::sub_depths(const PathColumns& path, std::vector<double>& rayleigh, std::vector<double>& aerosol,
                            std::vector<double>& absorption) const {
  const std::size_t n = wavelength_um_.size();
  rayleigh.resize(n);
  aerosol.resize(n);
  const double boundary = path.boundary_aerosol_tau_550, background = path.aerosol_tau_550 - boundary;
  for (std::size_t k = 0; k < n; ++k) {
    rayleigh[k] = rayleigh_m2_[k] * path.air_m2;
    aerosol[k] = boundary * boundary_per_550_[k] + background * background_per_550_[k];
  }
  absorption.assign(n, 0.0);
  if (path.crosses) molecules_->optical_depths(path, wavelength_um_, absorption);
}

void PathOptics::sub_transmittance(const PathColumns& path, std::vector<double>& out) const {
  out.assign(wavelength_um_.size(), 1.0);
  if (!path.crosses) return;
  std::vector<double> r, a, m;
  sub_depths(path, r, a, m);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = std::exp(-(r[k] + a[k] + m[k]));
}

void PathOptics::transmittance(const PathColumns& path, std::vector<double>& out) const {
  out.assign(static_cast<std::size_t>(band_.intervals), 1.0);
  if (!path.crosses) return;
  std::vector<double> t;
  sub_transmittance(path, t);
  for (std::size_t i = 0; i < out.size(); ++i) {
    double sum = 0;
    for (std::size_t k = first_[i]; k < first_[i + 1]; ++k) sum += t[k];
    out[i] = sum / static_cast<double>(first_[i + 1] - first_[i]);
  }
}

void PathOptics::path_radiance(const PathColumns& path, std::vector<double>& out) const {
  if (!path.crosses) {
    out.assign(static_cast<std::size_t>(band_.intervals), 0.0);
    return;
  }
  out = terms(path).thermal;
}

PathTerms PathOptics::terms(const PathColumns& path) const {
  const std::size_t intervals = static_cast<std::size_t>(band_.intervals), n = wavelength_um_.size();
  PathTerms t;
  t.transmittance.assign(intervals, 1.0);
  t.thermal.assign(intervals, 0.0);
  if (!path.crosses) return t;
  const auto interval_means = [&](const std::vector<double>& sub, std::vector<double>& out) {
    out.assign(intervals, 0.0);
    for (std::size_t i = 0; i < intervals; ++i) {
      for (std::size_t k = first_[i]; k < first_[i + 1]; ++k) out[i] += sub[k];
      out[i] /= static_cast<double>(first_[i + 1] - first_[i]);
    }
  };
  std::vector<double> thermal(n, 0.0), near(n, 1.0), far, wr(n), wa(n), g_weighted(n), mean_g;
  PathColumns prefix;
  prefix.crosses = true;
  for (const PathSegment& s : path.segments) {
    append_segment(prefix, s);
    sub_transmittance(prefix, far);
    const double boundary = s.boundary_aerosol_tau_550, background = s.aerosol_tau_550 - boundary;
    for (std::size_t k = 0; k < n; ++k) {
      const double lost = std::max(0.0, near[k] - far[k]);
      // Schwarzschild: B(T_segment) (T(0, near) - T(0, far)).
      thermal[k] += radiometry::planck_radiance(wavelength_um_[k], s.temperature_K) * lost;
      const double tau_r = rayleigh_m2_[k] * s.air_m2;
      const double tau_b = boundary * boundary_per_550_[k] * boundary_albedo_[k];
      const double tau_t = background * background_per_550_[k] * background_albedo_[k];
      const double tau_a = tau_b + tau_t;
      const double tau_e = far[k] > 0 && near[k] > far[k] ? std::log(near[k] / far[k]) : 0.0;
      // (T_near - T_far) / tau_e -> T_near for a thin segment.
      const double per_tau = tau_e > 1e-9 ? lost / tau_e : near[k];
      const double scale = tau_e > 1e-9 ? std::min(1.0, tau_e / std::max(tau_r + tau_a, 1e-300)) : 1.0;
      wr[k] = per_tau * tau_r * scale;
      wa[k] = per_tau * tau_a * scale;
      const double g = tau_a > 0 ? (tau_b * boundary_g_[k] + tau_t * background_g_[k]) / tau_a : 0.0;
      g_weighted[k] = g * wa[k];
    }
    t.rayleigh.emplace_back();
    t.aerosol.emplace_back();
    interval_means(wr, t.rayleigh.back());
    interval_means(wa, t.aerosol.back());
    interval_means(g_weighted, mean_g);
    for (std::size_t i = 0; i < intervals; ++i)
      if (t.aerosol.back()[i] > 0) mean_g[i] /= t.aerosol.back()[i];
    t.asymmetry.push_back(mean_g);
    near.swap(far);
  }
  interval_means(thermal, t.thermal);
  interval_means(near, t.transmittance);
  return t;
}

OpticalDepths PathOptics::optical_depths(const PathColumns& path) const {
  std::vector<double> r, a, m;
  sub_depths(path, r, a, m);
  OpticalDepths d;
  const std::size_t n = static_cast<std::size_t>(band_.intervals);
  d.rayleigh.assign(n, 0.0);
  d.aerosol.assign(n, 0.0);
  d.absorption.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double count = static_cast<double>(first_[i + 1] - first_[i]);
    for (std::size_t k = first_[i]; k < first_[i + 1]; ++k) {
      d.rayleigh[i] += r[k] / count;
      d.aerosol[i] += a[k] / count;
      d.absorption[i] += m[k] / count;
    }
  }
  return d;
}

}  // namespace eoir::atmosphere
