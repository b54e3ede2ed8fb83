// The planets' heliocentric places from the complete VSOP87B series
// (Bretagnon & Francou 1988, A&A 202, 309), compiled into the engine from
// Debian's kstars-data at build time (data/planets/README.md): within about
// 1" of JPL's DE ephemerides over 2000 BC - 6000 AD for Mercury to Mars, a
// few arcseconds over 1000-3000 AD for Jupiter and Saturn (Bretagnon &
// Francou, Table 6); tests/scene_units/planet_ephemeris_test.cpp checks the
// geocentric places within 2" of DE405.
#pragma once
#include <cstddef>

namespace eoir::universe::vsop87 {

struct Term {
  double amplitude, phase_rad, frequency_rad_per_millennium;  // A cos(B + C tau)
};
struct Series {
  std::size_t first, count;  // into kTerms
};

// Generated (convert_vsop87.py): every term, and per planet (0 Mercury ..
// 7 Neptune; 2 is the Earth), coordinate (L, B, R) and power of tau (0..5)
// its series. kTermCount 0: built without kstars-data.
extern const char kSource[];
extern const std::size_t kTermCount;
extern const Term kTerms[];
extern const Series kSeries[8][3][6];

inline bool available() { return kTermCount > 0; }

// Heliocentric position [au] and velocity [au/day] of planet 1 (Mercury) ..
// 8 (Neptune) at TDB jd1 + jd2, in the axes of the mean equator and equinox
// of J2000.0 (VSOP87's rotation from its dynamical ecliptic to FK5). Throws
// eoir::Error(out_of_range) for another planet number, (not_allowed) when
// the series were not built in.
void heliocentric_state(int planet, double tdb_jd1, double tdb_jd2, double position_au[3],
                        double velocity_au_per_day[3]);

}  // namespace eoir::universe::vsop87
