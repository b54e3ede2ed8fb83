#include "atmosphere/profile.hpp"

#include <algorithm>
#include <cmath>

#include "atmosphere/aerosol.hpp"
#include "atmosphere/data_table.hpp"
#include "atmosphere/us_standard_1976.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {

// The AFGL 1986 table of a profile (data/atmosphere/README.md), up to the
// model's top (100 km: 4e-6 of the air column lies above).
struct AfglRow {
  double altitude_km, pressure_hPa, temperature_K, air_cm3, h2o_ppmv, o3_ppmv;
  std::array<double, kMixedGases> mixed_ppmv;
};

std::vector<AfglRow> read_afgl(const std::string& path) {
  const DataTable t = read_data_table(path);
  const auto c = [&](const char* name) { return t.column(name); };
  const std::size_t z = c("altitude_km"), p = c("pressure_hPa"), T = c("temperature_K"), air = c("air_cm3");
  const std::size_t h2o = c("h2o_ppmv"), o3 = c("o3_ppmv");
  const std::size_t mixed[kMixedGases] = {c("co2_ppmv"), c("n2o_ppmv"), c("co_ppmv"), c("ch4_ppmv"), c("o2_ppmv")};
  std::vector<AfglRow> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<double>& v = t.rows[r];
    const std::string where = path + ":" + std::to_string(t.line[r]);
    for (const double x : v)
      if (x < 0) throw Error(Status::corrupt_file, where + ": a negative value");
    rows.push_back(AfglRow{v[z], v[p], v[T], v[air], v[h2o], v[o3],
                           {v[mixed[0]], v[mixed[1]], v[mixed[2]], v[mixed[3]], v[mixed[4]]}});
    if (rows.size() > 1 && !(rows.back().altitude_km > rows[rows.size() - 2].altitude_km))
      throw Error(Status::corrupt_file, where + ": altitude_km must increase");
  }
  if (rows.size() < 2) throw Error(Status::corrupt_file, path + ": fewer than two levels");
  return rows;
}

std::string afgl_file(universe::AtmosphereProfileName p) {
  switch (p) {
    case universe::AtmosphereProfileName::tropical: return "afgl_1986_tropical.csv";
    case universe::AtmosphereProfileName::midlatitude_summer: return "afgl_1986_midlatitude_summer.csv";
    case universe::AtmosphereProfileName::midlatitude_winter: return "afgl_1986_midlatitude_winter.csv";
    case universe::AtmosphereProfileName::subarctic_summer: return "afgl_1986_subarctic_summer.csv";
    case universe::AtmosphereProfileName::subarctic_winter: return "afgl_1986_subarctic_winter.csv";
    case universe::AtmosphereProfileName::us_standard_1976: break;
  }
  return "afgl_1986_us_standard.csv";
}

// Integral over [z0, z1] of a quantity log-linear between v0 and v1 (linear
// where either is 0).
double layer_integral(double v0, double v1, double dz) {
  if (!(v0 > 0) || !(v1 > 0)) return 0.5 * (v0 + v1) * dz;
  const double r = std::log(v1 / v0);
  if (std::fabs(r) < 1e-9) return 0.5 * (v0 + v1) * dz;
  return (v1 - v0) / r * dz;
}

double interpolate(double v0, double v1, double f) {
  if (!(v0 > 0) || !(v1 > 0)) return v0 + f * (v1 - v0);
  return v0 * std::pow(v1 / v0, f);
}
}  // namespace

AtmosphereProfile::AtmosphereProfile(std::vector<ProfileLevel> levels) : levels_(std::move(levels)) {
  if (levels_.size() < 2) throw Error(Status::out_of_range, "atmosphere profile: fewer than two levels");
}

std::shared_ptr<const AtmosphereProfile> AtmosphereProfile::make(const universe::AtmosphereSettings& settings,
                                                                 const std::string& data_dir, std::size_t layer_stride) {
  const std::string path = data_dir + "/atmosphere/" + afgl_file(settings.profile);
  const std::vector<AfglRow> rows = read_afgl(path);
  const AerosolProfile aerosol = AerosolProfile::make(settings, data_dir);
  const bool us76 = settings.profile == universe::AtmosphereProfileName::us_standard_1976;
  std::vector<ProfileLevel> levels;
  for (const AfglRow& r : rows) {
    const double z = r.altitude_km * 1e3;
    if (z > us76_top_altitude_m + 1.0) break;
    ProfileLevel l;
    l.altitude_m = z;
    Densities& d = l.at;
    if (us76) {  // the standard's own equations; the AFGL US-standard absorbers
      const StandardAtmosphereState s = us_standard_1976(z);
      d.temperature_K = s.temperature_K;
      d.pressure_Pa = s.pressure_Pa;
      d.air_m3 = s.density_kg_m3 / us76_molar_mass_kg_mol * kAvogadro_per_mol;
    } else {
      d.temperature_K = r.temperature_K;
      d.pressure_Pa = r.pressure_hPa * 100.0;
      d.air_m3 = r.air_cm3 * 1e6;
    }
    d.h2o_m3 = d.air_m3 * r.h2o_ppmv * 1e-6 * settings.water_vapor_scale;
    d.o3_m3 = d.air_m3 * r.o3_ppmv * 1e-6 * settings.ozone_scale;
    for (std::size_t g = 0; g < kMixedGases; ++g) d.mixed_m3[g] = d.air_m3 * r.mixed_ppmv[g] * 1e-6;
    d.aerosol_550_per_m = aerosol.extinction_550_per_m(z);
    d.boundary_aerosol_550_per_m = z <= kBoundaryLayerTop_m ? d.aerosol_550_per_m : 0.0;
    levels.push_back(l);
  }
  if (layer_stride > 1) {
    std::vector<ProfileLevel> kept;
    for (std::size_t i = 0; i < levels.size(); i += layer_stride) kept.push_back(levels[i]);
    if (kept.back().altitude_m != levels.back().altitude_m) kept.push_back(levels.back());
    levels = std::move(kept);
  }
  return std::make_shared<const AtmosphereProfile>(std::move(levels));
}

std::size_t AtmosphereProfile::layer_of(double altitude_m) const {
  const auto it = std::upper_bound(levels_.begin(), levels_.end(), altitude_m,
                                   [](double z, const ProfileLevel& l) { return z < l.altitude_m; });
  const auto i = static_cast<std::size_t>(it - levels_.begin());
  return std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, levels_.size() - 2);
}

Densities AtmosphereProfile::at(double altitude_m) const {
  if (altitude_m > top_altitude_m()) return Densities{};
  if (altitude_m <= levels_.front().altitude_m) return levels_.front().at;
  const std::size_t k = layer_of(altitude_m);
  const Densities& a = levels_[k].at;
  const Densities& b = levels_[k + 1].at;
  const double f = (altitude_m - levels_[k].altitude_m) / (levels_[k + 1].altitude_m - levels_[k].altitude_m);
  Densities d;
  d.air_m3 = interpolate(a.air_m3, b.air_m3, f);
  d.h2o_m3 = interpolate(a.h2o_m3, b.h2o_m3, f);
  d.o3_m3 = interpolate(a.o3_m3, b.o3_m3, f);
  for (std::size_t g = 0; g < kMixedGases; ++g) d.mixed_m3[g] = interpolate(a.mixed_m3[g], b.mixed_m3[g], f);
  d.aerosol_550_per_m = interpolate(a.aerosol_550_per_m, b.aerosol_550_per_m, f);
  d.boundary_aerosol_550_per_m = altitude_m <= kBoundaryLayerTop_m ? d.aerosol_550_per_m : 0.0;
  d.pressure_Pa = interpolate(a.pressure_Pa, b.pressure_Pa, f);
  d.temperature_K = a.temperature_K + f * (b.temperature_K - a.temperature_K);
  return d;
}

VerticalColumns AtmosphereProfile::vertical_columns_above(double altitude_m) const {
  VerticalColumns c;
  const double z0 = std::max(altitude_m, levels_.front().altitude_m);
  for (std::size_t k = 0; k + 1 < levels_.size(); ++k) {
    const double lo = levels_[k].altitude_m, hi = levels_[k + 1].altitude_m;
    if (hi <= z0) continue;
    const double from = std::max(lo, z0);
    const Densities a = from > lo ? at(from) : levels_[k].at;
    const Densities& b = levels_[k + 1].at;
    const double dz = hi - from;
    c.air_m2 += layer_integral(a.air_m3, b.air_m3, dz);
    c.h2o_m2 += layer_integral(a.h2o_m3, b.h2o_m3, dz);
    c.o3_m2 += layer_integral(a.o3_m3, b.o3_m3, dz);
    c.aerosol_tau_550 += layer_integral(a.aerosol_550_per_m, b.aerosol_550_per_m, dz);
  }
  return c;
}

}  // namespace eoir::atmosphere
