#include "universe/vsop87.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace eoir::universe::vsop87 {
namespace {

constexpr double kJ2000_jd = 2451545.0;
constexpr double kDaysPerMillennium = 365250.0;

// VSOP87's rotation from the dynamical ecliptic and equinox of J2000.0 to
// the mean equator and equinox of J2000.0 (FK5), as its documentation
// (vsop87.doc, CDS VI/81) gives it.
constexpr double kEclipticToEquatorial[3][3] = {{1.0, 0.000000440360, -0.000000190919},
                                               {-0.000000479966, 0.917482137087, -0.397776982902},
                                               {0.0, 0.397776982902, 0.917482137087}};

// One coordinate: its value and derivative per millennium at tau.
void coordinate(const Series (&powers)[6], double tau, double& value, double& rate) {
  value = rate = 0.0;
  double tau_n = 1.0, tau_n_minus_1 = 0.0;  // tau^n, tau^(n-1)
  for (int n = 0; n < 6; ++n) {
    double sum = 0.0, derivative = 0.0;
    const Series& s = powers[n];
    for (std::size_t k = s.first; k < s.first + s.count; ++k) {
      const Term& t = kTerms[k];
      const double angle = t.phase_rad + t.frequency_rad_per_millennium * tau;
      sum += t.amplitude * std::cos(angle);
      derivative -= t.amplitude * t.frequency_rad_per_millennium * std::sin(angle);
    }
    value += tau_n * sum;
    rate += tau_n * derivative + n * tau_n_minus_1 * sum;
    tau_n_minus_1 = tau_n;
    tau_n *= tau;
  }
}

}  // namespace

void heliocentric_state(int planet, double tdb_jd1, double tdb_jd2, double position_au[3],
                        double velocity_au_per_day[3]) {
  if (planet < 1 || planet > 8)
    throw Error(Status::out_of_range, "planet: VSOP87 number " + std::to_string(planet) + " (1 Mercury .. 8 Neptune)");
  if (!available())
    throw Error(Status::not_allowed, "planets: the engine was built without the VSOP87 series (Debian kstars-data)");
  const double tau = ((tdb_jd1 - kJ2000_jd) + tdb_jd2) / kDaysPerMillennium;
  double L, dL, B, dB, R, dR;
  const auto& series = kSeries[planet - 1];
  coordinate(series[0], tau, L, dL);
  coordinate(series[1], tau, B, dB);
  coordinate(series[2], tau, R, dR);
  const double cl = std::cos(L), sl = std::sin(L), cb = std::cos(B), sb = std::sin(B);
  const double ecliptic[3] = {R * cb * cl, R * cb * sl, R * sb};
  const double rate[3] = {dR * cb * cl - R * sb * dB * cl - R * cb * sl * dL,
                          dR * cb * sl - R * sb * dB * sl + R * cb * cl * dL, dR * sb + R * cb * dB};
  for (int i = 0; i < 3; ++i) {
    position_au[i] = velocity_au_per_day[i] = 0.0;
    for (int j = 0; j < 3; ++j) {
      position_au[i] += kEclipticToEquatorial[i][j] * ecliptic[j];
      velocity_au_per_day[i] += kEclipticToEquatorial[i][j] * rate[j] / kDaysPerMillennium;
    }
  }
}

}  // namespace eoir::universe::vsop87
