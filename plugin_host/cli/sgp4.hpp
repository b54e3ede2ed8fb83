// SGP4/SDP4 orbit propagation from two-line elements (host-side motion, like
// the Kepler and ephemeris models of motion.hpp).
//
// A port of the reference implementation of D. A. Vallado, P. Crawford,
// R. Hujsak and T. S. Kelso, "Revisiting Spacetrack Report #3", AIAA
// 2006-6753 (Vallado's sgp4unit.cpp, version of 7 Dec 2015), following the
// structure of its line-by-line Python port in python-sgp4
// (sgp4/propagation.py and sgp4/io.py, MIT licence): the same procedures
// (initl, dscom, dpper, dsinit, dspace, sgp4init, sgp4), the same WGS72
// constants and the "improved" operation mode ('i'). Checked against
// python3-sgp4 on the SGP4-VER.TLE verification set (tests/cli).
//
// Output is in TEME (true equator, mean equinox of the epoch of date), km
// and km/s; teme_to_j2000() rotates it into the engine's J2000 (GCRS) axes.
#pragma once
#include <array>
#include <stdexcept>
#include <string>

namespace eoir::cli {

// An SGP4 error at a time (Vallado's error codes): 1 mean eccentricity out of
// range, 2 mean motion negative, 3 perturbed eccentricity out of range,
// 4 semi-latus rectum negative, 6 the satellite has decayed (radius below
// one Earth radius).
class Sgp4Error : public std::runtime_error {
 public:
  Sgp4Error(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

struct TemeState {
  std::array<double, 3> r_km{};
  std::array<double, 3> v_km_s{};
};

class Sgp4 {
 public:
  // Parses the two lines and initialises the propagator. Strict: 69
  // columns each (line ends aside), every field of the form the TLE format
  // gives it (digits where it has digits: no exponents, hex or
  // signs on angles), a checksum digit in column 69, angles in range
  // (inclination [0, 180], the others [0, 360)), the epoch day within its
  // year, mean motion > 0. Throws std::invalid_argument naming the line and
  // field ("line 2 inclination: 181.0000 outside [0, 180]"). check_checksum
  // false (test vectors only) skips comparing the digit with the line's sum.
  static Sgp4 from_tle(const std::string& line1, const std::string& line2, bool check_checksum = true);

  // Position and velocity (TEME) at `minutes` since the epoch. Throws
  // Sgp4Error. The deep-space integrator restarts from the epoch on each
  // call, so the result does not depend on earlier calls.
  TemeState at_minutes(double minutes) const;

  // The epoch as a UTC Julian date (whole part and fraction, as python-sgp4's
  // jdsatepoch and jdsatepochF).
  double epoch_jd() const { return jd_epoch_; }
  double epoch_jd_fraction() const { return jd_epoch_fraction_; }
  long satellite_number() const { return satnum_; }
  // Mean-element perigee and apogee radii, km (WGS72 Earth radius 6378.135 km).
  double perigee_radius_km() const;
  double apogee_radius_km() const;
  bool deep_space() const { return s_.method == 'd'; }

 private:
  struct Satrec {
    // constants (WGS72)
    double tumin, mu, radiusearthkm, xke, j2, j3, j4, j3oj2;
    // elements
    double bstar, ndot, nddot, ecco, argpo, inclo, mo, no_kozai, nodeo, no_unkozai;
    double a, alta, altp;
    // near earth
    int isimp;
    char method, init, operationmode;
    double aycof, con41, cc1, cc4, cc5, d2, d3, d4, delmo, eta, argpdot, omgcof, sinmao, t, t2cof, t3cof, t4cof,
        t5cof, x1mth2, x7thm1, mdot, nodedot, xlcof, xmcof, nodecf;
    // deep space
    int irez;
    double d2201, d2211, d3210, d3222, d4410, d4422, d5220, d5232, d5421, d5433, dedt, del1, del2, del3, didt, dmdt,
        dnodt, domdt, e3, ee2, peo, pgho, pho, pinco, plo, se2, se3, sgh2, sgh3, sgh4, sh2, sh3, si2, si3, sl2, sl3,
        sl4, gsto, xfact, xgh2, xgh3, xgh4, xh2, xh3, xi2, xi3, xl2, xl3, xl4, xlamo, zmol, zmos, atime, xli, xni;
  };
  void init(double epoch_days_1950);
  TemeState propagate(Satrec& s, double tsince) const;

  Satrec s_{};
  double jd_epoch_ = 0, jd_epoch_fraction_ = 0;
  long satnum_ = 0;
};

// TEME -> J2000 (GCRS axes) at a UTC Julian date (two parts), with ERFA:
// a rotation about the pole by GAST - GMST (TEME -> true equator and equinox
// of date; GAST of IAU 2006/2000A, eraGst06a, and SGP4's GMST of IAU 1982,
// eraGmst82: the equation of the equinoxes plus the difference of the two
// GMST models), then the transpose of the IAU 2006/2000A bias-precession-
// nutation matrix (eraPnm06a; true of date -> GCRS), at TT. Approximations:
// UT1 = UTC (as the engine; it cancels to first order in GAST - GMST), no
// celestial-pole offsets, and the velocity rotated without the frame's tiny
// rotation rate (< 1e-11 rad/s). Agrees with astropy's TEME -> GCRS (through
// ITRS with IERS data) to a few milliarcseconds (tests/cli/check_sgp4.py).
std::array<double, 9> teme_to_j2000_matrix(double jd_utc1, double jd_utc2);

}  // namespace eoir::cli
