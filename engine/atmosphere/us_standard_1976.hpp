// The U.S. Standard Atmosphere 1976 (NOAA/NASA/USAF, NOAA-S/T 76-1562) from
// its defining equations: temperature, pressure and mass density against
// geometric altitude. 0-86 km: the seven layers of linear molecular-scale
// temperature in geopotential altitude (Table 4) with the hydrostatic
// pressure of eqs. 33a/33b and M/M0 of Table 8 above 80 km; 86-100 km: the
// kinetic temperature of eqs. 25-27 (isothermal to 91 km, then the
// elliptical segment), pressure by hydrostatic integration at the
// sea-level molar mass (the standard's own values come from its species
// densities: within 3 % at 100 km, where 4e-6 of the air column lies).
#pragma once

namespace eoir::atmosphere {

struct StandardAtmosphereState {
  double temperature_K = 0;  // kinetic temperature
  double pressure_Pa = 0;
  double density_kg_m3 = 0;
};

constexpr double us76_sea_level_pressure_Pa = 101325.0;
constexpr double us76_sea_level_temperature_K = 288.15;
constexpr double us76_g0_m_s2 = 9.80665;
constexpr double us76_molar_mass_kg_mol = 28.9644e-3;  // M0
constexpr double us76_gas_constant_J_mol_K = 8.31432;  // R* of the standard
constexpr double us76_earth_radius_m = 6356766.0;      // r0 of eq. 18
constexpr double us76_top_altitude_m = 100000.0;       // the top of the model here

// The state at geometric altitude z in [0, 100 km] (clamped to it).
StandardAtmosphereState us_standard_1976(double altitude_m);

}  // namespace eoir::atmosphere
