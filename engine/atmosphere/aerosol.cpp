#include "atmosphere/aerosol.hpp"

#include <algorithm>
#include <cmath>

#include "atmosphere/data_table.hpp"
#include "atmosphere/profile.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {

constexpr double kBoundaryTop_m = kBoundaryLayerTop_m;
// The tabulated boundary-layer visibilities (km), in the file's column order.
constexpr double kVisibilities_km[] = {50.0, 23.0, 10.0, 5.0, 2.0};
const char* const kBoundaryColumns[] = {"boundary_50km", "boundary_23km", "boundary_10km", "boundary_5km",
                                        "boundary_2km"};

}  // namespace

AerosolProfile AerosolProfile::make(const universe::AtmosphereSettings& settings, const std::string& data_dir) {
  AerosolProfile p;
  if (settings.aerosol == universe::AerosolModel::none) {
    p.altitude_m_ = {0.0, 1e5};
    p.extinction_per_m_ = {0.0, 0.0};
    return p;
  }
  const std::string path = data_dir + "/atmosphere/aerosol_profile_lowtran7.csv";
  const DataTable t = read_data_table(path);
  const std::size_t z_col = t.column("altitude_km");
  std::size_t b_cols[5];
  for (int i = 0; i < 5; ++i) b_cols[i] = t.column(kBoundaryColumns[i], true);
  const std::size_t tro = t.column("troposphere_spring_summer", true);
  const std::size_t strat = t.column("stratosphere_background_spring_summer", true);
  const std::size_t upper = t.column("upper_atmosphere", true);
  // The visibility's place among the tabulated ones, linear in 1 / V
  // (extrapolated past 2 and 50 km; the ground value then set exactly).
  const double inv = 1.0 / settings.visibility_km;
  int j = 0;
  while (j < 3 && inv > 1.0 / kVisibilities_km[j + 1]) ++j;
  const double f = (inv - 1.0 / kVisibilities_km[j]) / (1.0 / kVisibilities_km[j + 1] - 1.0 / kVisibilities_km[j]);
  const double ground_per_km = std::max(0.0, 3.912 / settings.visibility_km - kRayleighExtinction550_per_km);
  double tabulated_ground_per_km = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<double>& row = t.rows[r];
    for (const double x : row)
      if (x < 0) throw Error(Status::corrupt_file, path + ":" + std::to_string(t.line[r]) + ": a negative value");
    const double z_km = row[z_col];
    double beta = std::nan("");
    if (z_km < kBoundaryTop_m / 1e3 && !std::isnan(row[b_cols[j]]) && !std::isnan(row[b_cols[j + 1]])) {
      beta = std::max(0.0, row[b_cols[j]] + f * (row[b_cols[j + 1]] - row[b_cols[j]]));
      if (z_km == 0.0) tabulated_ground_per_km = beta;
    } else if (z_km == kBoundaryTop_m / 1e3 && !std::isnan(row[b_cols[1]])) {
      beta = row[b_cols[1]];  // the boundary layer's top, the same for every visibility
    } else if (!std::isnan(row[tro]) && z_km > kBoundaryTop_m / 1e3) {
      beta = row[tro];
    } else if (!std::isnan(row[strat])) {
      beta = row[strat];
    } else if (!std::isnan(row[upper])) {
      beta = row[upper];
    }
    if (std::isnan(beta)) continue;
    if (!p.altitude_m_.empty() && !(z_km * 1e3 > p.altitude_m_.back()))
      throw Error(Status::corrupt_file, path + ": altitude_km must increase");
    p.altitude_m_.push_back(z_km * 1e3);
    p.extinction_per_m_.push_back(beta * 1e-3);
  }
  if (p.altitude_m_.size() < 2 || p.altitude_m_.front() != 0.0)
    throw Error(Status::corrupt_file, path + ": the profile must start at 0 km");
  // The boundary layer scaled so that its ground value is Koschmieder's.
  if (tabulated_ground_per_km > 0) {
    const double scale = ground_per_km / tabulated_ground_per_km;
    for (std::size_t i = 0; i < p.altitude_m_.size() && p.altitude_m_[i] < kBoundaryTop_m; ++i)
      p.extinction_per_m_[i] *= scale;
  }
  return p;
}

double AerosolProfile::extinction_550_per_m(double altitude_m) const {
  if (altitude_m <= altitude_m_.front()) return extinction_per_m_.front();
  if (altitude_m >= altitude_m_.back()) return altitude_m > altitude_m_.back() ? 0.0 : extinction_per_m_.back();
  const auto it = std::upper_bound(altitude_m_.begin(), altitude_m_.end(), altitude_m);
  const std::size_t i = static_cast<std::size_t>(it - altitude_m_.begin()) - 1;
  const double f = (altitude_m - altitude_m_[i]) / (altitude_m_[i + 1] - altitude_m_[i]);
  const double a = extinction_per_m_[i], b = extinction_per_m_[i + 1];
  return a > 0 && b > 0 ? a * std::pow(b / a, f) : a + f * (b - a);
}

}  // namespace eoir::atmosphere
