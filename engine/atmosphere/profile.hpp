// The state of the Earth's atmosphere against altitude (spec 4.3.1.1): the
// levels of a model profile with temperature, pressure and the number
// densities of air, H2O and O3, and the aerosol's extinction at 0.55 um;
// densities log-linear in altitude between levels (exact for the
// exponential fall of a layer of constant scale height). Made once per
// atmosphere setting (AtmosphereProfile::make) and shared by every path.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "universe/atmosphere_settings.hpp"

namespace eoir::atmosphere {

// The gases of the AFGL profiles besides H2O and O3 (uniformly mixed, or
// nearly), in the order of their columns.
enum class MixedGas : std::size_t { co2 = 0, n2o = 1, co = 2, ch4 = 3, o2 = 4 };
constexpr std::size_t kMixedGases = 5;

// What one absorber or the aerosol amounts to at a point: number densities
// (m^-3) and the aerosol's extinction coefficient at 0.55 um (m^-1).
struct Densities {
  double air_m3 = 0, h2o_m3 = 0, o3_m3 = 0, aerosol_550_per_m = 0;
  std::array<double, kMixedGases> mixed_m3{};
  double boundary_aerosol_550_per_m = 0;  // the part of the boundary-layer model (0-2 km)
  double temperature_K = 0, pressure_Pa = 0;
};

struct ProfileLevel {
  double altitude_m = 0;
  Densities at;
};

// Amounts above a point, straight up (m^-2; the aerosol's optical depth).
struct VerticalColumns {
  double air_m2 = 0, h2o_m2 = 0, o3_m2 = 0, aerosol_tau_550 = 0;
};

// The top of the boundary layer, whose aerosol is the model the settings
// name; above it the tropospheric model (LOWTRAN 7).
constexpr double kBoundaryLayerTop_m = 2000.0;

// Conversions for reports and tests.
constexpr double kH2OMolarMass_kg_mol = 18.01528e-3;
constexpr double kAvogadro_per_mol = 6.02214076e23;
constexpr double kLoschmidt_m3 = 2.6867811e25;  // molecules per m^3 at 273.15 K, 101325 Pa: 1 atm-cm = this x 1e-2 m
// A water column (molecules m^-2) in g cm^-2 (precipitable cm), and any
// gas's in atm-cm.
inline double precipitable_water_g_cm2(double h2o_m2) { return h2o_m2 * kH2OMolarMass_kg_mol / kAvogadro_per_mol * 0.1; }
inline double atm_cm(double molecules_m2) { return molecules_m2 / kLoschmidt_m3 * 1e2; }

class AtmosphereProfile {
 public:
  // The profile the settings name, from the data folder's atmosphere/ files
  // (throws io or corrupt_file naming the file and line).
  // layer_stride keeps every n-th level (the first and the last always).
  static std::shared_ptr<const AtmosphereProfile> make(const universe::AtmosphereSettings& settings,
                                                       const std::string& data_dir, std::size_t layer_stride = 1);
  // From levels (ascending altitude, at least two): tests and user profiles.
  explicit AtmosphereProfile(std::vector<ProfileLevel> levels);

  const std::vector<ProfileLevel>& levels() const { return levels_; }
  double top_altitude_m() const { return levels_.back().altitude_m; }
  // The state at an altitude (clamped to the profile: below the first level
  // as at it; above the top, nothing).
  Densities at(double altitude_m) const;
  // The layer (index of its lower level) holding an altitude.
  std::size_t layer_of(double altitude_m) const;
  // Exact integral of the log-linear densities from an altitude to the top.
  VerticalColumns vertical_columns_above(double altitude_m) const;

 private:
  std::vector<ProfileLevel> levels_;
};

}  // namespace eoir::atmosphere
