// Rayleigh scattering by air (Bodhaine, Wood, Dutton and Slusser 1999, "On
// Rayleigh optical depth calculations", J. Atmos. Oceanic Technol. 16,
// 1854): the cross section per molecule of dry air with 360 ppm CO2 from
// their eq. 30 fit of the sea-level optical depth (1013.25 hPa, 45 deg
// latitude), divided by that column's molecules: p A / (m_a g) with g at the
// column's mass-weighted altitude (their eqs. 11 and 12).
#pragma once

namespace eoir::atmosphere {

// Bodhaine eq. 30: the optical depth of the standard sea-level column at
// wavelength lambda (0.25-4 um; the fit's lambda^-4 behaviour beyond).
double rayleigh_sea_level_optical_depth(double wavelength_um);
// Molecules per m^2 of that column.
double rayleigh_reference_column_m2();
// Cross section per air molecule (m^2).
double rayleigh_cross_section_m2(double wavelength_um);
// The phase function of air (normalised to 4 pi) at the cosine of the
// scattering angle, with the molecules' depolarisation (Chandrasekhar 1950;
// depolarisation factor 0.0279, Young 1980, as Bodhaine's cross section
// assumes): 3 / (4 (1 + 2 gamma)) ((1 + 3 gamma) + (1 - gamma) cos^2),
// gamma = rho / (2 - rho).
double rayleigh_phase(double cos_scattering);

}  // namespace eoir::atmosphere
