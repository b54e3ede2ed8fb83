// SGP4/SDP4 after Vallado et al., AIAA 2006-6753 (see sgp4.hpp). Variable
// names and the order of operations follow the reference code so that the
// two can be compared line by line; angles in radians, time in minutes,
// distances in Earth radii inside the propagator.
#include "sgp4.hpp"

#include <erfa.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace eoir::cli {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double twopi = 2.0 * pi;
constexpr double deg2rad = pi / 180.0;
constexpr double x2o3 = 2.0 / 3.0;

// Python's a % b (result has the sign of b), as the Python port uses it.
double pymod(double a, double b) { return a - b * std::floor(a / b); }
// C's fmod (result has the sign of a), where the reference writes it out.
double cmod(double a, double b) { return std::fmod(a, b); }

double gstime(double jdut1) {
  const double tut1 = (jdut1 - 2451545.0) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;  // seconds
  temp = pymod(temp * deg2rad / 240.0, twopi);
  if (temp < 0.0) temp += twopi;
  return temp;
}

// ------------------------------------------------------------------ TLE text
// The format (CelesTrak, "NORAD Two-Line Element Set Format"): 69 fixed
// columns per line; every field is checked against its pattern before it is
// converted, so no text reaches strtod but digits, one '.' and a sign.
[[noreturn]] void bad(int line, const std::string& field, const std::string& why) {
  throw std::invalid_argument("line " + std::to_string(line) + " " + field + ": " + why);
}

bool digit(char c) { return c >= '0' && c <= '9'; }

// A field at 0-based columns [a, a + strlen(pattern)) of one line.
struct Field {
  const std::string& text;
  int line;
  std::size_t a;
  const char* name;
  const char* pattern;
};

// Checks `f` against its pattern: 'N' a digit (leading ones may be blank,
// down to the last before a '.' or the end), 'S' a sign (' ', '+' or '-'),
// 'E' an exponent sign ('+' or '-'), anything else itself. Returns the text.
std::string checked(const Field& f) {
  const std::string p = f.pattern;
  const std::string t = f.text.substr(f.a, p.size());
  bool leading = true;  // still in the blanks allowed before the first digit
  for (std::size_t i = 0; i < p.size(); ++i) {
    const char c = t[i];
    bool ok;
    if (p[i] == 'N') {
      const bool last_of_run = i + 1 == p.size() || p[i + 1] != 'N';
      ok = digit(c) || (leading && c == ' ' && !last_of_run);
      if (digit(c)) leading = false;
    } else {
      ok = p[i] == 'S' ? (c == ' ' || c == '+' || c == '-') : p[i] == 'E' ? (c == '+' || c == '-') : c == p[i];
      leading = p[i] == 'S';
    }
    if (!ok) bad(f.line, f.name, "'" + t + "' is not of the form " + p);
  }
  return t;
}

// The value of a checked decimal field (digits, blanks, '.', a sign).
double value_of(const std::string& t) {
  std::string s;
  for (char c : t)
    if (c != ' ') s += c;
  return std::strtod(s.c_str(), nullptr);
}

// A checked decimal field within [lo, hi] or, with hi_excluded, [lo, hi).
double decimal(const Field& f, int lo, int hi, bool hi_excluded = false) {
  const std::string t = checked(f);
  const double v = value_of(t);
  if (v < lo || v > hi || (hi_excluded && v == hi))
    bad(f.line, f.name, t.substr(t.find_first_not_of(' ')) + " outside [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + (hi_excluded ? ")" : "]"));
  return v;
}

// "SNNNNNEN": sign, five digits of a fraction (decimal point assumed) and a
// power of ten, as python-sgp4 computes it.
double assumed_point(const Field& f) {
  const std::string t = checked(f);
  std::string digits = t.substr(1, 5);
  for (char& c : digits)
    if (c == ' ') c = '0';
  const double mantissa = std::strtod(((t[0] == '-' ? "-." : ".") + digits).c_str(), nullptr);
  return mantissa * std::pow(10.0, static_cast<double>(t[6] == '-' ? '0' - t[7] : t[7] - '0'));
}

// Satellite numbers: 5 digits (leading ones may be blank), or Alpha-5 (a
// letter, I and O skipped, and 4 digits: A0001 = 100001).
long parse_satellite_number(const std::string& l, int line) {
  const std::string t = l.substr(2, 5);
  const char c = t[0];
  if (c >= 'A' && c <= 'Z' && c != 'I' && c != 'O') {
    if (!(digit(t[1]) && digit(t[2]) && digit(t[3]) && digit(t[4])))
      bad(line, "satellite number", "'" + t + "' is not 5 digits or a letter and 4 digits (Alpha-5)");
    const long letter = c - 'A' + 10 - (c > 'I') - (c > 'O');
    return letter * 10000 + std::strtol(t.c_str() + 1, nullptr, 10);
  }
  std::size_t i = 0;
  while (i < 4 && t[i] == ' ') ++i;
  for (std::size_t k = i; k < 5; ++k)
    if (!digit(t[k])) bad(line, "satellite number", "'" + t + "' is not 5 digits or a letter and 4 digits (Alpha-5)");
  return std::strtol(t.c_str() + i, nullptr, 10);
}

int checksum(const std::string& line) {
  int sum = 0;
  for (std::size_t i = 0; i < 68 && i < line.size(); ++i) {
    if (digit(line[i])) sum += line[i] - '0';
    if (line[i] == '-') sum += 1;
  }
  return sum % 10;
}

// 69 columns (line ends stripped), the line number, blanks between fields
// and the checksum digit in column 69 (matching the line, if asked).
std::string columns_of(const std::string& text, int line, bool check_checksum, const std::vector<std::size_t>& blanks) {
  std::string l = text;
  while (!l.empty() && (l.back() == '\r' || l.back() == '\n')) l.pop_back();
  const char* layout = line == 1 ? "'1 NNNNNC NNNNNAAA NNNNN.NNNNNNNN +.NNNNNNNN +NNNNN-N +NNNNN-N N NNNNN'"
                                 : "'2 NNNNN NNN.NNNN NNN.NNNN NNNNNNN NNN.NNNN NNN.NNNN NN.NNNNNNNNNNNNNN'";
  if (l.size() != 69)
    bad(line, "format", std::to_string(l.size()) + " columns, a TLE line has 69 (" + layout + ")");
  bool ok = l[0] == static_cast<char>('0' + line);
  for (std::size_t i : blanks) ok = ok && l[i] == ' ';
  if (!ok) bad(line, "format", std::string("not a TLE line ") + std::to_string(line) + " (" + layout + ")");
  if (!digit(l[68])) bad(line, "checksum", "column 69 is '" + std::string(1, l[68]) + "', not a digit");
  if (check_checksum && l[68] - '0' != checksum(l))
    bad(line, "checksum", "column 69 is " + std::string(1, l[68]) + " but the line sums to " +
                              std::to_string(checksum(l)));
  return l;
}

// Vallado's days2mdhms and jday.
void days2mdhms(int year, double days, int& mon, int& day, int& hr, int& minute, double& sec) {
  const int lmonth[12] = {31, (year % 4 == 0) ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const int dayofyr = static_cast<int>(std::floor(days));
  int i = 1, inttemp = 0;
  while (dayofyr > inttemp + lmonth[i - 1] && i < 12) {
    inttemp += lmonth[i - 1];
    ++i;
  }
  mon = i;
  day = dayofyr - inttemp;
  double temp = (days - dayofyr) * 24.0;
  hr = static_cast<int>(std::floor(temp));
  temp = (temp - hr) * 60.0;
  minute = static_cast<int>(std::floor(temp));
  sec = (temp - minute) * 60.0;
}

double jday(int year, int mon, int day, int hr, int minute, double sec) {
  return 367.0 * year - std::floor(7.0 * (year + std::floor((mon + 9.0) / 12.0)) * 0.25) +
         std::floor(275.0 * mon / 9.0) + day + 1721013.5 + ((sec / 60.0 + minute) / 60.0 + hr) / 24.0;
}

}  // namespace

// ---------------------------------------------------------------- parsing
Sgp4 Sgp4::from_tle(const std::string& line1, const std::string& line2, bool check_checksum) {
  const std::string l1 = columns_of(line1, 1, check_checksum, {1, 8, 17, 32, 43, 52, 61, 63});
  const std::string l2 = columns_of(line2, 2, check_checksum, {1, 7, 16, 25, 33, 42, 51});
  Sgp4 p;
  p.satnum_ = parse_satellite_number(l1, 1);
  if (l1[7] != 'U' && l1[7] != 'C' && l1[7] != 'S')
    bad(1, "classification", "'" + std::string(1, l1[7]) + "' is not U, C or S");
  for (std::size_t i = 9; i < 17; ++i)
    if (!(digit(l1[i]) || (l1[i] >= 'A' && l1[i] <= 'Z') || l1[i] == ' '))
      bad(1, "international designator", "'" + l1.substr(9, 8) + "' is not of the form YYNNNAAA");
  const int two_digit_year = static_cast<int>(value_of(checked({l1, 1, 18, "epoch year", "NN"})));
  const int year = two_digit_year < 57 ? two_digit_year + 2000 : two_digit_year + 1900;
  const int days_in_year = year % 4 == 0 ? 366 : 365;  // 1957-2056
  const Field day_field{l1, 1, 20, "epoch day", "NNN.NNNNNNNN"};
  const std::string day_text = checked(day_field);
  const double epochdays = value_of(day_text);
  if (!(epochdays >= 1.0 && epochdays < days_in_year + 1.0))
    bad(1, "epoch day", day_text + " outside [1, " + std::to_string(days_in_year + 1) + ") in " + std::to_string(year));
  const double ndot = value_of(checked({l1, 1, 33, "ndot", "S.NNNNNNNN"}));
  const double nddot = assumed_point({l1, 1, 44, "nddot", "SNNNNNEN"});
  const double bstar = assumed_point({l1, 1, 53, "bstar", "SNNNNNEN"});
  if (!(digit(l1[62]) || l1[62] == ' ')) bad(1, "ephemeris type", "'" + std::string(1, l1[62]) + "' is not a digit");
  checked({l1, 1, 64, "element set number", "NNNN"});

  if (parse_satellite_number(l2, 2) != p.satnum_) bad(2, "satellite number", "differs from line 1's");
  const double inclo = decimal({l2, 2, 8, "inclination", "NNN.NNNN"}, 0, 180);
  const double nodeo = decimal({l2, 2, 17, "right ascension of the node", "NNN.NNNN"}, 0, 360, true);
  std::string ecc_digits = checked({l2, 2, 26, "eccentricity", "NNNNNNN"});
  for (char& c : ecc_digits)
    if (c == ' ') c = '0';
  const double ecco = std::strtod(("0." + ecc_digits).c_str(), nullptr);
  const double argpo = decimal({l2, 2, 34, "argument of perigee", "NNN.NNNN"}, 0, 360, true);
  const double mo = decimal({l2, 2, 43, "mean anomaly", "NNN.NNNN"}, 0, 360, true);
  const double no_kozai = value_of(checked({l2, 2, 52, "mean motion", "NN.NNNNNNNN"}));
  if (!(no_kozai > 0.0)) bad(2, "mean motion", "must be positive (revolutions per day)");
  checked({l2, 2, 63, "revolution number", "NNNNN"});

  const double xpdotp = 1440.0 / (2.0 * pi);
  Satrec& s = p.s_;
  s.no_kozai = no_kozai / xpdotp;
  s.nddot = nddot / (xpdotp * 1440.0 * 1440);
  s.bstar = bstar;
  s.ndot = ndot / (xpdotp * 1440.0);
  s.inclo = inclo * deg2rad;
  s.nodeo = nodeo * deg2rad;
  s.argpo = argpo * deg2rad;
  s.mo = mo * deg2rad;
  s.ecco = ecco;
  int mon, day, hr, minute;
  double sec;
  days2mdhms(year, epochdays, mon, day, hr, minute, sec);
  const double jdsatepoch = jday(year, mon, day, hr, minute, sec);
  // The split Julian date of python-sgp4's Satrec (exact to the TLE's digits).
  const double days = std::floor(epochdays), fraction = epochdays - days;
  p.jd_epoch_ = year * 365.0 + std::floor((year - 1) / 4.0) + days + 1721044.5;
  p.jd_epoch_fraction_ = std::round(fraction * 1e8) / 1e8;
  p.init(jdsatepoch - 2433281.5);
  return p;
}

double Sgp4::perigee_radius_km() const { return (s_.altp + 1.0) * s_.radiusearthkm; }
double Sgp4::apogee_radius_km() const { return (s_.alta + 1.0) * s_.radiusearthkm; }

// ------------------------------------------------------- deep-space helpers
// dpper: deep-space long-period periodics (lunar-solar).
static void dpper(double e3, double ee2, double peo, double pgho, double pho, double pinco, double plo, double se2,
                  double se3, double sgh2, double sgh3, double sgh4, double sh2, double sh3, double si2, double si3,
                  double sl2, double sl3, double sl4, double t, double xgh2, double xgh3, double xgh4, double xh2,
                  double xh3, double xi2, double xi3, double xl2, double xl3, double xl4, double zmol, double zmos,
                  char init, double& ep, double& inclp, double& nodep, double& argpp, double& mp, char opsmode) {
  const double zns = 1.19459e-5, zes = 0.01675, znl = 1.5835218e-4, zel = 0.05490;
  double zm = zmos + zns * t;
  if (init == 'y') zm = zmos;
  double zf = zm + 2.0 * zes * std::sin(zm);
  double sinzf = std::sin(zf);
  double f2 = 0.5 * sinzf * sinzf - 0.25;
  double f3 = -0.5 * sinzf * std::cos(zf);
  const double ses = se2 * f2 + se3 * f3;
  const double sis = si2 * f2 + si3 * f3;
  const double sls = sl2 * f2 + sl3 * f3 + sl4 * sinzf;
  const double sghs = sgh2 * f2 + sgh3 * f3 + sgh4 * sinzf;
  const double shs = sh2 * f2 + sh3 * f3;
  zm = zmol + znl * t;
  if (init == 'y') zm = zmol;
  zf = zm + 2.0 * zel * std::sin(zm);
  sinzf = std::sin(zf);
  f2 = 0.5 * sinzf * sinzf - 0.25;
  f3 = -0.5 * sinzf * std::cos(zf);
  const double sel = ee2 * f2 + e3 * f3;
  const double sil = xi2 * f2 + xi3 * f3;
  const double sll = xl2 * f2 + xl3 * f3 + xl4 * sinzf;
  const double sghl = xgh2 * f2 + xgh3 * f3 + xgh4 * sinzf;
  const double shll = xh2 * f2 + xh3 * f3;
  double pe = ses + sel, pinc = sis + sil, pl = sls + sll, pgh = sghs + sghl, ph = shs + shll;
  if (init == 'n') {
    pe = pe - peo;
    pinc = pinc - pinco;
    pl = pl - plo;
    pgh = pgh - pgho;
    ph = ph - pho;
    inclp = inclp + pinc;
    ep = ep + pe;
    const double sinip = std::sin(inclp), cosip = std::cos(inclp);
    if (inclp >= 0.2) {
      ph /= sinip;
      pgh -= cosip * ph;
      argpp += pgh;
      nodep += ph;
      mp += pl;
    } else {
      // Lyddane modification for low inclinations.
      const double sinop = std::sin(nodep), cosop = std::cos(nodep);
      double alfdp = sinip * sinop, betdp = sinip * cosop;
      const double dalf = ph * cosop + pinc * cosip * sinop;
      const double dbet = -ph * sinop + pinc * cosip * cosop;
      alfdp = alfdp + dalf;
      betdp = betdp + dbet;
      nodep = cmod(nodep, twopi);
      if (nodep < 0.0 && opsmode == 'a') nodep = nodep + twopi;
      const double xls = mp + argpp + pl + pgh + (cosip - pinc * sinip) * nodep;
      const double xnoh = nodep;
      nodep = std::atan2(alfdp, betdp);
      if (nodep < 0.0 && opsmode == 'a') nodep = nodep + twopi;
      if (std::fabs(xnoh - nodep) > pi) {
        if (nodep < xnoh)
          nodep = nodep + twopi;
        else
          nodep = nodep - twopi;
      }
      mp += pl;
      argpp = xls - mp - cosip * nodep;
    }
  }
}

// ------------------------------------------------------------- sgp4init
void Sgp4::init(double epoch) {
  Satrec& s = s_;
  // WGS72 (Vallado's getgravconst("wgs72"); python-sgp4's default).
  s.mu = 398600.8;
  s.radiusearthkm = 6378.135;
  s.xke = 60.0 / std::sqrt(s.radiusearthkm * s.radiusearthkm * s.radiusearthkm / s.mu);
  s.tumin = 1.0 / s.xke;
  s.j2 = 0.001082616;
  s.j3 = -0.00000253881;
  s.j4 = -0.00000165597;
  s.j3oj2 = s.j3 / s.j2;
  s.operationmode = 'i';
  s.method = 'n';
  s.isimp = 0;
  s.init = 'y';
  s.t = 0.0;
  const double temp4 = 1.5e-12;
  const double ss = 78.0 / s.radiusearthkm + 1.0;
  const double qzms2ttemp = (120.0 - 78.0) / s.radiusearthkm;
  const double qzms2t = qzms2ttemp * qzms2ttemp * qzms2ttemp * qzms2ttemp;

  // initl
  const double eccsq = s.ecco * s.ecco;
  const double omeosq = 1.0 - eccsq;
  const double rteosq = std::sqrt(omeosq);
  const double cosio = std::cos(s.inclo);
  const double cosio2 = cosio * cosio;
  const double ak = std::pow(s.xke / s.no_kozai, x2o3);
  const double d1 = 0.75 * s.j2 * (3.0 * cosio2 - 1.0) / (rteosq * omeosq);
  double del = d1 / (ak * ak);
  const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
  del = d1 / (adel * adel);
  s.no_unkozai = s.no_kozai / (1.0 + del);
  const double ao = std::pow(s.xke / s.no_unkozai, x2o3);
  const double sinio = std::sin(s.inclo);
  const double po = ao * omeosq;
  const double con42 = 1.0 - 5.0 * cosio2;
  s.con41 = -con42 - cosio2 - cosio2;
  const double posq = po * po;
  const double rp = ao * (1.0 - s.ecco);
  s.gsto = gstime(epoch + 2433281.5);

  s.a = std::pow(s.no_unkozai * s.tumin, -2.0 / 3.0);
  s.alta = s.a * (1.0 + s.ecco) - 1.0;
  s.altp = s.a * (1.0 - s.ecco) - 1.0;

  if (omeosq >= 0.0 || s.no_unkozai >= 0.0) {
    s.isimp = 0;
    if (rp < 220.0 / s.radiusearthkm + 1.0) s.isimp = 1;
    double sfour = ss, qzms24 = qzms2t;
    const double perige = (rp - 1.0) * s.radiusearthkm;
    if (perige < 156.0) {
      sfour = perige - 78.0;
      if (perige < 98.0) sfour = 20.0;
      const double qzms24temp = (120.0 - sfour) / s.radiusearthkm;
      qzms24 = qzms24temp * qzms24temp * qzms24temp * qzms24temp;
      sfour = sfour / s.radiusearthkm + 1.0;
    }
    const double pinvsq = 1.0 / posq;
    const double tsi = 1.0 / (ao - sfour);
    s.eta = ao * s.ecco * tsi;
    const double etasq = s.eta * s.eta;
    const double eeta = s.ecco * s.eta;
    const double psisq = std::fabs(1.0 - etasq);
    const double coef = qzms24 * std::pow(tsi, 4.0);
    const double coef1 = coef / std::pow(psisq, 3.5);
    const double cc2 = coef1 * s.no_unkozai *
                       (ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                        0.375 * s.j2 * tsi / psisq * s.con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
    s.cc1 = s.bstar * cc2;
    double cc3 = 0.0;
    if (s.ecco > 1.0e-4) cc3 = -2.0 * coef * tsi * s.j3oj2 * s.no_unkozai * sinio / s.ecco;
    s.x1mth2 = 1.0 - cosio2;
    s.cc4 = 2.0 * s.no_unkozai * coef1 * ao * omeosq *
            (s.eta * (2.0 + 0.5 * etasq) + s.ecco * (0.5 + 2.0 * etasq) -
             s.j2 * tsi / (ao * psisq) *
                 (-3.0 * s.con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
                  0.75 * s.x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) * std::cos(2.0 * s.argpo)));
    s.cc5 = 2.0 * coef1 * ao * omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);
    const double cosio4 = cosio2 * cosio2;
    const double temp1 = 1.5 * s.j2 * pinvsq * s.no_unkozai;
    const double temp2 = 0.5 * temp1 * s.j2 * pinvsq;
    const double temp3 = -0.46875 * s.j4 * pinvsq * pinvsq * s.no_unkozai;
    s.mdot = s.no_unkozai + 0.5 * temp1 * rteosq * s.con41 +
             0.0625 * temp2 * rteosq * (13.0 - 78.0 * cosio2 + 137.0 * cosio4);
    s.argpdot = -0.5 * temp1 * con42 + 0.0625 * temp2 * (7.0 - 114.0 * cosio2 + 395.0 * cosio4) +
                temp3 * (3.0 - 36.0 * cosio2 + 49.0 * cosio4);
    const double xhdot1 = -temp1 * cosio;
    s.nodedot = xhdot1 + (0.5 * temp2 * (4.0 - 19.0 * cosio2) + 2.0 * temp3 * (3.0 - 7.0 * cosio2)) * cosio;
    const double xpidot = s.argpdot + s.nodedot;
    s.omgcof = s.bstar * cc3 * std::cos(s.argpo);
    s.xmcof = 0.0;
    if (s.ecco > 1.0e-4) s.xmcof = -x2o3 * coef * s.bstar / eeta;
    s.nodecf = 3.5 * omeosq * xhdot1 * s.cc1;
    s.t2cof = 1.5 * s.cc1;
    if (std::fabs(cosio + 1.0) > 1.5e-12)
      s.xlcof = -0.25 * s.j3oj2 * sinio * (3.0 + 5.0 * cosio) / (1.0 + cosio);
    else
      s.xlcof = -0.25 * s.j3oj2 * sinio * (3.0 + 5.0 * cosio) / temp4;
    s.aycof = -0.5 * s.j3oj2 * sinio;
    const double delmotemp = 1.0 + s.eta * std::cos(s.mo);
    s.delmo = delmotemp * delmotemp * delmotemp;
    s.sinmao = std::sin(s.mo);
    s.x7thm1 = 7.0 * cosio2 - 1.0;

    // Deep space (period >= 225 min).
    if (2 * pi / s.no_unkozai >= 225.0) {
      s.method = 'd';
      s.isimp = 1;
      const double tc = 0.0;
      double inclm = s.inclo;

      // ------------------------------------------------------------ dscom
      const double zes = 0.01675, zel = 0.05490, c1ss = 2.9864797e-6, c1l = 4.7968065e-7, zsinis = 0.39785416,
                   zcosis = 0.91744867, zcosgs = 0.1945905, zsings = -0.98088458;
      double nm = s.no_unkozai, em = s.ecco;
      const double snodm = std::sin(s.nodeo), cnodm = std::cos(s.nodeo);
      const double sinomm = std::sin(s.argpo), cosomm = std::cos(s.argpo);
      const double sinim = std::sin(s.inclo), cosim = std::cos(s.inclo);
      double emsq = em * em;
      const double betasq = 1.0 - emsq;
      const double rtemsq = std::sqrt(betasq);
      s.peo = s.pinco = s.plo = s.pgho = s.pho = 0.0;
      const double day = epoch + 18261.5 + tc / 1440.0;
      const double xnodce = pymod(4.5236020 - 9.2422029e-4 * day, twopi);
      const double stem = std::sin(xnodce), ctem = std::cos(xnodce);
      const double zcosil = 0.91375164 - 0.03568096 * ctem;
      const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
      const double zsinhl = 0.089683511 * stem / zsinil;
      const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
      const double gam = 5.8351514 + 0.0019443680 * day;
      double zx = 0.39785416 * stem / zsinil;
      const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
      zx = std::atan2(zx, zy);
      zx = gam + zx - xnodce;
      const double zcosgl = std::cos(zx), zsingl = std::sin(zx);
      double zcosg = zcosgs, zsing = zsings, zcosi = zcosis, zsini = zsinis, zcosh = cnodm, zsinh = snodm;
      double cc = c1ss;
      const double xnoi = 1.0 / nm;
      double s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
      double ss1 = 0, ss2 = 0, ss3 = 0, ss4 = 0, ss5 = 0, ss6 = 0, ss7 = 0;
      double z1 = 0, z2 = 0, z3 = 0, z11 = 0, z12 = 0, z13 = 0, z21 = 0, z22 = 0, z23 = 0, z31 = 0, z32 = 0, z33 = 0;
      double sz1 = 0, sz2 = 0, sz3 = 0, sz11 = 0, sz12 = 0, sz13 = 0, sz21 = 0, sz22 = 0, sz23 = 0, sz31 = 0,
             sz32 = 0, sz33 = 0;
      for (int lsflg = 1; lsflg <= 2; ++lsflg) {
        const double a1 = zcosg * zcosh + zsing * zcosi * zsinh;
        const double a3 = -zsing * zcosh + zcosg * zcosi * zsinh;
        const double a7 = -zcosg * zsinh + zsing * zcosi * zcosh;
        const double a8 = zsing * zsini;
        const double a9 = zsing * zsinh + zcosg * zcosi * zcosh;
        const double a10 = zcosg * zsini;
        const double a2 = cosim * a7 + sinim * a8;
        const double a4 = cosim * a9 + sinim * a10;
        const double a5 = -sinim * a7 + cosim * a8;
        const double a6 = -sinim * a9 + cosim * a10;
        const double x1 = a1 * cosomm + a2 * sinomm;
        const double x2 = a3 * cosomm + a4 * sinomm;
        const double x3 = -a1 * sinomm + a2 * cosomm;
        const double x4 = -a3 * sinomm + a4 * cosomm;
        const double x5 = a5 * sinomm;
        const double x6 = a6 * sinomm;
        const double x7 = a5 * cosomm;
        const double x8 = a6 * cosomm;
        z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
        z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
        z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
        z1 = 3.0 * (a1 * a1 + a2 * a2) + z31 * emsq;
        z2 = 6.0 * (a1 * a3 + a2 * a4) + z32 * emsq;
        z3 = 3.0 * (a3 * a3 + a4 * a4) + z33 * emsq;
        z11 = -6.0 * a1 * a5 + emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
        z12 = -6.0 * (a1 * a6 + a3 * a5) + emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
        z13 = -6.0 * a3 * a6 + emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
        z21 = 6.0 * a2 * a5 + emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
        z22 = 6.0 * (a4 * a5 + a2 * a6) + emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
        z23 = 6.0 * a4 * a6 + emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
        z1 = z1 + z1 + betasq * z31;
        z2 = z2 + z2 + betasq * z32;
        z3 = z3 + z3 + betasq * z33;
        s3 = cc * xnoi;
        s2 = -0.5 * s3 / rtemsq;
        s4 = s3 * rtemsq;
        s1 = -15.0 * em * s4;
        s5 = x1 * x3 + x2 * x4;
        s6 = x2 * x3 + x1 * x4;
        s7 = x2 * x4 - x1 * x3;
        if (lsflg == 1) {  // the solar terms; the lunar ones follow
          ss1 = s1; ss2 = s2; ss3 = s3; ss4 = s4; ss5 = s5; ss6 = s6; ss7 = s7;
          sz1 = z1; sz2 = z2; sz3 = z3; sz11 = z11; sz12 = z12; sz13 = z13;
          sz21 = z21; sz22 = z22; sz23 = z23; sz31 = z31; sz32 = z32; sz33 = z33;
          zcosg = zcosgl;
          zsing = zsingl;
          zcosi = zcosil;
          zsini = zsinil;
          zcosh = zcoshl * cnodm + zsinhl * snodm;
          zsinh = snodm * zcoshl - cnodm * zsinhl;
          cc = c1l;
        }
      }
      s.zmol = pymod(4.7199672 + 0.22997150 * day - gam, twopi);
      s.zmos = pymod(6.2565837 + 0.017201977 * day, twopi);
      s.se2 = 2.0 * ss1 * ss6;
      s.se3 = 2.0 * ss1 * ss7;
      s.si2 = 2.0 * ss2 * sz12;
      s.si3 = 2.0 * ss2 * (sz13 - sz11);
      s.sl2 = -2.0 * ss3 * sz2;
      s.sl3 = -2.0 * ss3 * (sz3 - sz1);
      s.sl4 = -2.0 * ss3 * (-21.0 - 9.0 * emsq) * zes;
      s.sgh2 = 2.0 * ss4 * sz32;
      s.sgh3 = 2.0 * ss4 * (sz33 - sz31);
      s.sgh4 = -18.0 * ss4 * zes;
      s.sh2 = -2.0 * ss2 * sz22;
      s.sh3 = -2.0 * ss2 * (sz23 - sz21);
      s.ee2 = 2.0 * s1 * s6;
      s.e3 = 2.0 * s1 * s7;
      s.xi2 = 2.0 * s2 * z12;
      s.xi3 = 2.0 * s2 * (z13 - z11);
      s.xl2 = -2.0 * s3 * z2;
      s.xl3 = -2.0 * s3 * (z3 - z1);
      s.xl4 = -2.0 * s3 * (-21.0 - 9.0 * emsq) * zel;
      s.xgh2 = 2.0 * s4 * z32;
      s.xgh3 = 2.0 * s4 * (z33 - z31);
      s.xgh4 = -18.0 * s4 * zel;
      s.xh2 = -2.0 * s2 * z22;
      s.xh3 = -2.0 * s2 * (z23 - z21);

      // dpper at initialisation leaves the elements as they are (init 'y').
      dpper(s.e3, s.ee2, s.peo, s.pgho, s.pho, s.pinco, s.plo, s.se2, s.se3, s.sgh2, s.sgh3, s.sgh4, s.sh2, s.sh3,
            s.si2, s.si3, s.sl2, s.sl3, s.sl4, s.t, s.xgh2, s.xgh3, s.xgh4, s.xh2, s.xh3, s.xi2, s.xi3, s.xl2, s.xl3,
            s.xl4, s.zmol, s.zmos, s.init, s.ecco, s.inclo, s.nodeo, s.argpo, s.mo, s.operationmode);

      // ----------------------------------------------------------- dsinit
      const double q22 = 1.7891679e-6, q31 = 2.1460748e-6, q33 = 2.2123015e-7, root22 = 1.7891679e-6,
                   root44 = 7.3636953e-9, root54 = 2.1765803e-9, rptim = 4.37526908801129966e-3,
                   root32 = 3.7393792e-7, root52 = 1.1428639e-7, znl = 1.5835218e-4, zns = 1.19459e-5;
      double argpm = 0.0, nodem = 0.0, mm = 0.0;
      s.irez = 0;
      if (0.0034906585 < nm && nm < 0.0052359877) s.irez = 1;
      if (0.00826 <= nm && nm <= 0.00924 && em >= 0.5) s.irez = 2;
      const double ses = ss1 * zns * ss5;
      const double sis = ss2 * zns * (sz11 + sz13);
      const double sls = -zns * ss3 * (sz1 + sz3 - 14.0 - 6.0 * emsq);
      const double sghs = ss4 * zns * (sz31 + sz33 - 6.0);
      double shs = -zns * ss2 * (sz21 + sz23);
      if (inclm < 5.2359877e-2 || inclm > pi - 5.2359877e-2) shs = 0.0;
      if (sinim != 0.0) shs = shs / sinim;
      const double sgs = sghs - cosim * shs;
      s.dedt = ses + s1 * znl * s5;
      s.didt = sis + s2 * znl * (z11 + z13);
      s.dmdt = sls - znl * s3 * (z1 + z3 - 14.0 - 6.0 * emsq);
      const double sghl = s4 * znl * (z31 + z33 - 6.0);
      double shll = -znl * s2 * (z21 + z23);
      if (inclm < 5.2359877e-2 || inclm > pi - 5.2359877e-2) shll = 0.0;
      s.domdt = sgs + sghl;
      s.dnodt = shs;
      if (sinim != 0.0) {
        s.domdt = s.domdt - cosim / sinim * shll;
        s.dnodt = s.dnodt + shll / sinim;
      }
      const double dndt = 0.0;
      const double theta = pymod(s.gsto + tc * rptim, twopi);
      em = em + s.dedt * s.t;
      inclm = inclm + s.didt * s.t;
      argpm = argpm + s.domdt * s.t;
      nodem = nodem + s.dnodt * s.t;
      mm = mm + s.dmdt * s.t;
      if (s.irez != 0) {
        const double aonv = std::pow(nm / s.xke, x2o3);
        if (s.irez == 2) {  // 12-hour resonance
          const double cosisq = cosim * cosim;
          const double emo = em;
          em = s.ecco;
          const double emsqo = emsq;
          emsq = eccsq;
          const double eoc = em * emsq;
          const double g201 = -0.306 - (em - 0.64) * 0.440;
          double g211, g310, g322, g410, g422, g520, g533, g521, g532;
          if (em <= 0.65) {
            g211 = 3.616 - 13.2470 * em + 16.2900 * emsq;
            g310 = -19.302 + 117.3900 * em - 228.4190 * emsq + 156.5910 * eoc;
            g322 = -18.9068 + 109.7927 * em - 214.6334 * emsq + 146.5816 * eoc;
            g410 = -41.122 + 242.6940 * em - 471.0940 * emsq + 313.9530 * eoc;
            g422 = -146.407 + 841.8800 * em - 1629.014 * emsq + 1083.4350 * eoc;
            g520 = -532.114 + 3017.977 * em - 5740.032 * emsq + 3708.2760 * eoc;
          } else {
            g211 = -72.099 + 331.819 * em - 508.738 * emsq + 266.724 * eoc;
            g310 = -346.844 + 1582.851 * em - 2415.925 * emsq + 1246.113 * eoc;
            g322 = -342.585 + 1554.908 * em - 2366.899 * emsq + 1215.972 * eoc;
            g410 = -1052.797 + 4758.686 * em - 7193.992 * emsq + 3651.957 * eoc;
            g422 = -3581.690 + 16178.110 * em - 24462.770 * emsq + 12422.520 * eoc;
            if (em > 0.715)
              g520 = -5149.66 + 29936.92 * em - 54087.36 * emsq + 31324.56 * eoc;
            else
              g520 = 1464.74 - 4664.75 * em + 3763.64 * emsq;
          }
          if (em < 0.7) {
            g533 = -919.22770 + 4988.6100 * em - 9064.7700 * emsq + 5542.21 * eoc;
            g521 = -822.71072 + 4568.6173 * em - 8491.4146 * emsq + 5337.524 * eoc;
            g532 = -853.66600 + 4690.2500 * em - 8624.7700 * emsq + 5341.4 * eoc;
          } else {
            g533 = -37995.780 + 161616.52 * em - 229838.20 * emsq + 109377.94 * eoc;
            g521 = -51752.104 + 218913.95 * em - 309468.16 * emsq + 146349.42 * eoc;
            g532 = -40023.880 + 170470.89 * em - 242699.48 * emsq + 115605.82 * eoc;
          }
          const double sini2 = sinim * sinim;
          const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
          const double f221 = 1.5 * sini2;
          const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
          const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
          const double f441 = 35.0 * sini2 * f220;
          const double f442 = 39.3750 * sini2 * sini2;
          const double f522 = 9.84375 * sinim *
                              (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                               0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
          const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                                       6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
          const double f542 = 29.53125 * sinim * (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
          const double f543 = 29.53125 * sinim * (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));
          const double xno2 = nm * nm;
          const double ainv2 = aonv * aonv;
          double tq1 = 3.0 * xno2 * ainv2;
          double tq = tq1 * root22;
          s.d2201 = tq * f220 * g201;
          s.d2211 = tq * f221 * g211;
          tq1 = tq1 * aonv;
          tq = tq1 * root32;
          s.d3210 = tq * f321 * g310;
          s.d3222 = tq * f322 * g322;
          tq1 = tq1 * aonv;
          tq = 2.0 * tq1 * root44;
          s.d4410 = tq * f441 * g410;
          s.d4422 = tq * f442 * g422;
          tq1 = tq1 * aonv;
          tq = tq1 * root52;
          s.d5220 = tq * f522 * g520;
          s.d5232 = tq * f523 * g532;
          tq = 2.0 * tq1 * root54;
          s.d5421 = tq * f542 * g521;
          s.d5433 = tq * f543 * g533;
          s.xlamo = pymod(s.mo + s.nodeo + s.nodeo - theta - theta, twopi);
          s.xfact = s.mdot + s.dmdt + 2.0 * (s.nodedot + s.dnodt - rptim) - s.no_unkozai;
          em = emo;
          emsq = emsqo;
        }
        if (s.irez == 1) {  // synchronous resonance
          const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
          const double g310 = 1.0 + 2.0 * emsq;
          const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
          const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
          const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
          double f330 = 1.0 + cosim;
          f330 = 1.875 * f330 * f330 * f330;
          s.del1 = 3.0 * nm * nm * aonv * aonv;
          s.del2 = 2.0 * s.del1 * f220 * g200 * q22;
          s.del3 = 3.0 * s.del1 * f330 * g300 * q33 * aonv;
          s.del1 = s.del1 * f311 * g310 * q31 * aonv;
          s.xlamo = pymod(s.mo + s.nodeo + s.argpo - theta, twopi);
          s.xfact = s.mdot + xpidot - rptim + s.dmdt + s.domdt + s.dnodt - s.no_unkozai;
        }
        s.xli = s.xlamo;
        s.xni = s.no_unkozai;
        s.atime = 0.0;
        nm = s.no_unkozai + dndt;
      }
      (void)argpm;
      (void)nodem;
      (void)mm;
      (void)nm;
    }

    if (s.isimp != 1) {
      const double cc1sq = s.cc1 * s.cc1;
      s.d2 = 4.0 * ao * tsi * cc1sq;
      const double temp = s.d2 * tsi * s.cc1 / 3.0;
      s.d3 = (17.0 * ao + sfour) * temp;
      s.d4 = 0.5 * temp * ao * tsi * (221.0 * ao + 31.0 * sfour) * s.cc1;
      s.t3cof = s.d2 + 2.0 * cc1sq;
      s.t4cof = 0.25 * (3.0 * s.d3 + s.cc1 * (12.0 * s.d2 + 10.0 * cc1sq));
      s.t5cof = 0.2 * (3.0 * s.d4 + 12.0 * s.cc1 * s.d3 + 6.0 * s.d2 * s.d2 + 15.0 * cc1sq * (2.0 * s.d2 + cc1sq));
    }
  }
  // The reference propagates to t = 0 once here (errors are reported by the
  // calls that follow), which also sets the deep-space coefficients that
  // propagate() recomputes each time.
  try {
    (void)propagate(s_, 0.0);
  } catch (const Sgp4Error&) {
  }
  s.init = 'n';
}

TemeState Sgp4::at_minutes(double minutes) const {
  if (!std::isfinite(minutes)) throw Sgp4Error(-1, "time since epoch is not finite");
  Satrec s = s_;  // propagate() updates a few coefficients as the reference does
  return propagate(s, minutes);
}

// ------------------------------------------------------------------ sgp4
TemeState Sgp4::propagate(Satrec& s, double tsince) const {
  const double temp4 = 1.5e-12;
  const double vkmpersec = s.radiusearthkm * s.xke / 60.0;
  s.t = tsince;
  const double xmdf = s.mo + s.mdot * s.t;
  const double argpdf = s.argpo + s.argpdot * s.t;
  const double nodedf = s.nodeo + s.nodedot * s.t;
  double argpm = argpdf, mm = xmdf;
  const double t2 = s.t * s.t;
  double nodem = nodedf + s.nodecf * t2;
  double tempa = 1.0 - s.cc1 * s.t;
  double tempe = s.bstar * s.cc4 * s.t;
  double templ = s.t2cof * t2;
  if (s.isimp != 1) {
    const double delomg = s.omgcof * s.t;
    const double delmtemp = 1.0 + s.eta * std::cos(xmdf);
    const double delm = s.xmcof * (delmtemp * delmtemp * delmtemp - s.delmo);
    const double temp = delomg + delm;
    mm = xmdf + temp;
    argpm = argpdf - temp;
    const double t3 = t2 * s.t, t4 = t3 * s.t;
    tempa = tempa - s.d2 * t2 - s.d3 * t3 - s.d4 * t4;
    tempe = tempe + s.bstar * s.cc5 * (std::sin(mm) - s.sinmao);
    templ = templ + s.t3cof * t3 + t4 * (s.t4cof + s.t * s.t5cof);
  }
  double nm = s.no_unkozai, em = s.ecco, inclm = s.inclo;
  if (s.method == 'd') {
    // ------------------------------------------------------------ dspace
    const double fasx2 = 0.13130908, fasx4 = 2.8843198, fasx6 = 0.37448087, g22 = 5.7686396, g32 = 0.95240898,
                 g44 = 1.8014998, g52 = 1.0508330, g54 = 4.4108898, rptim = 4.37526908801129966e-3, stepp = 720.0,
                 stepn = -720.0, step2 = 259200.0;
    const double tc = s.t;
    double dndt = 0.0;
    const double theta = pymod(s.gsto + tc * rptim, twopi);
    em = em + s.dedt * s.t;
    inclm = inclm + s.didt * s.t;
    argpm = argpm + s.domdt * s.t;
    nodem = nodem + s.dnodt * s.t;
    mm = mm + s.dmdt * s.t;
    double ft = 0.0;
    if (s.irez != 0) {
      // The integrator starts from the epoch (the reference keeps atime = 0
      // between calls too).
      double atime = s.atime, xli = s.xli, xni = s.xni;
      if (atime == 0.0 || s.t * atime <= 0.0 || std::fabs(s.t) < std::fabs(atime)) {
        atime = 0.0;
        xni = s.no_unkozai;
        xli = s.xlamo;
      }
      const double delt = s.t > 0.0 ? stepp : stepn;
      double xndt = 0, xldot = 0, xnddt = 0;
      for (;;) {
        if (s.irez != 2) {
          xndt = s.del1 * std::sin(xli - fasx2) + s.del2 * std::sin(2.0 * (xli - fasx4)) +
                 s.del3 * std::sin(3.0 * (xli - fasx6));
          xldot = xni + s.xfact;
          xnddt = s.del1 * std::cos(xli - fasx2) + 2.0 * s.del2 * std::cos(2.0 * (xli - fasx4)) +
                  3.0 * s.del3 * std::cos(3.0 * (xli - fasx6));
          xnddt = xnddt * xldot;
        } else {
          const double xomi = s.argpo + s.argpdot * atime;
          const double x2omi = xomi + xomi;
          const double x2li = xli + xli;
          xndt = s.d2201 * std::sin(x2omi + xli - g22) + s.d2211 * std::sin(xli - g22) +
                 s.d3210 * std::sin(xomi + xli - g32) + s.d3222 * std::sin(-xomi + xli - g32) +
                 s.d4410 * std::sin(x2omi + x2li - g44) + s.d4422 * std::sin(x2li - g44) +
                 s.d5220 * std::sin(xomi + xli - g52) + s.d5232 * std::sin(-xomi + xli - g52) +
                 s.d5421 * std::sin(xomi + x2li - g54) + s.d5433 * std::sin(-xomi + x2li - g54);
          xldot = xni + s.xfact;
          xnddt = s.d2201 * std::cos(x2omi + xli - g22) + s.d2211 * std::cos(xli - g22) +
                  s.d3210 * std::cos(xomi + xli - g32) + s.d3222 * std::cos(-xomi + xli - g32) +
                  s.d5220 * std::cos(xomi + xli - g52) + s.d5232 * std::cos(-xomi + xli - g52) +
                  2.0 * (s.d4410 * std::cos(x2omi + x2li - g44) + s.d4422 * std::cos(x2li - g44) +
                         s.d5421 * std::cos(xomi + x2li - g54) + s.d5433 * std::cos(-xomi + x2li - g54));
          xnddt = xnddt * xldot;
        }
        if (std::fabs(s.t - atime) >= stepp) {
          xli = xli + xldot * delt + xndt * step2;
          xni = xni + xndt * delt + xnddt * step2;
          atime = atime + delt;
        } else {
          ft = s.t - atime;
          break;
        }
      }
      nm = xni + xndt * ft + xnddt * ft * ft * 0.5;
      const double xl = xli + xldot * ft + xndt * ft * ft * 0.5;
      if (s.irez != 1) {
        mm = xl - 2.0 * nodem + 2.0 * theta;
        dndt = nm - s.no_unkozai;
      } else {
        mm = xl - nodem - argpm + theta;
        dndt = nm - s.no_unkozai;
      }
      nm = s.no_unkozai + dndt;
    }
  }
  char text[160];
  if (nm <= 0.0) {
    std::snprintf(text, sizeof text, "mean motion %f is less than zero", nm);
    throw Sgp4Error(2, text);
  }
  const double am = std::pow(s.xke / nm, x2o3) * tempa * tempa;
  nm = s.xke / std::pow(am, 1.5);
  em = em - tempe;
  if (em >= 1.0 || em < -0.001) {
    std::snprintf(text, sizeof text, "mean eccentricity %f not within range 0.0 <= e < 1.0", em);
    throw Sgp4Error(1, text);
  }
  if (em < 1.0e-6) em = 1.0e-6;
  mm = mm + s.no_unkozai * templ;
  double xlm = mm + argpm + nodem;
  nodem = cmod(nodem, twopi);
  argpm = pymod(argpm, twopi);
  xlm = pymod(xlm, twopi);
  mm = pymod(xlm - argpm - nodem, twopi);

  const double sinim = std::sin(inclm), cosim = std::cos(inclm);
  double ep = em, xincp = inclm, argpp = argpm, nodep = nodem, mp = mm, sinip = sinim, cosip = cosim;
  if (s.method == 'd') {
    dpper(s.e3, s.ee2, s.peo, s.pgho, s.pho, s.pinco, s.plo, s.se2, s.se3, s.sgh2, s.sgh3, s.sgh4, s.sh2, s.sh3,
          s.si2, s.si3, s.sl2, s.sl3, s.sl4, s.t, s.xgh2, s.xgh3, s.xgh4, s.xh2, s.xh3, s.xi2, s.xi3, s.xl2, s.xl3,
          s.xl4, s.zmol, s.zmos, 'n', ep, xincp, nodep, argpp, mp, s.operationmode);
    if (xincp < 0.0) {
      xincp = -xincp;
      nodep = nodep + pi;
      argpp = argpp - pi;
    }
    if (ep < 0.0 || ep > 1.0) {
      std::snprintf(text, sizeof text, "perturbed eccentricity %f not within range 0.0 <= e <= 1.0", ep);
      throw Sgp4Error(3, text);
    }
    sinip = std::sin(xincp);
    cosip = std::cos(xincp);
    s.aycof = -0.5 * s.j3oj2 * sinip;
    if (std::fabs(cosip + 1.0) > 1.5e-12)
      s.xlcof = -0.25 * s.j3oj2 * sinip * (3.0 + 5.0 * cosip) / (1.0 + cosip);
    else
      s.xlcof = -0.25 * s.j3oj2 * sinip * (3.0 + 5.0 * cosip) / temp4;
  }
  // Long-period periodics, then Kepler's equation in Lyddane's variables.
  const double axnl = ep * std::cos(argpp);
  double temp = 1.0 / (am * (1.0 - ep * ep));
  const double aynl = ep * std::sin(argpp) + temp * s.aycof;
  const double xl = mp + argpp + nodep + temp * s.xlcof * axnl;
  const double u = pymod(xl - nodep, twopi);
  double eo1 = u, tem5 = 9999.9, sineo1 = 0, coseo1 = 0;
  for (int ktr = 1; std::fabs(tem5) >= 1.0e-12 && ktr <= 10; ++ktr) {
    sineo1 = std::sin(eo1);
    coseo1 = std::cos(eo1);
    tem5 = 1.0 - coseo1 * axnl - sineo1 * aynl;
    tem5 = (u - aynl * coseo1 + axnl * sineo1 - eo1) / tem5;
    if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
    eo1 = eo1 + tem5;
  }
  const double ecose = axnl * coseo1 + aynl * sineo1;
  const double esine = axnl * sineo1 - aynl * coseo1;
  const double el2 = axnl * axnl + aynl * aynl;
  const double pl = am * (1.0 - el2);
  if (pl < 0.0) {
    std::snprintf(text, sizeof text, "semilatus rectum %f is less than zero", pl);
    throw Sgp4Error(4, text);
  }
  // Short-period periodics.
  const double rl = am * (1.0 - ecose);
  const double rdotl = std::sqrt(am) * esine / rl;
  const double rvdotl = std::sqrt(pl) / rl;
  const double betal = std::sqrt(1.0 - el2);
  temp = esine / (1.0 + betal);
  const double sinu = am / rl * (sineo1 - aynl - axnl * temp);
  const double cosu = am / rl * (coseo1 - axnl + aynl * temp);
  double su = std::atan2(sinu, cosu);
  const double sin2u = (cosu + cosu) * sinu;
  const double cos2u = 1.0 - 2.0 * sinu * sinu;
  temp = 1.0 / pl;
  const double temp1 = 0.5 * s.j2 * temp;
  const double temp2 = temp1 * temp;
  if (s.method == 'd') {
    const double cosisq = cosip * cosip;
    s.con41 = 3.0 * cosisq - 1.0;
    s.x1mth2 = 1.0 - cosisq;
    s.x7thm1 = 7.0 * cosisq - 1.0;
  }
  const double mrt = rl * (1.0 - 1.5 * temp2 * betal * s.con41) + 0.5 * temp1 * s.x1mth2 * cos2u;
  su = su - 0.25 * temp2 * s.x7thm1 * sin2u;
  const double xnode = nodep + 1.5 * temp2 * cosip * sin2u;
  const double xinc = xincp + 1.5 * temp2 * cosip * sinip * cos2u;
  const double mvt = rdotl - nm * temp1 * s.x1mth2 * sin2u / s.xke;
  const double rvdot = rvdotl + nm * temp1 * (s.x1mth2 * cos2u + 1.5 * s.con41) / s.xke;
  const double sinsu = std::sin(su), cossu = std::cos(su);
  const double snod = std::sin(xnode), cnod = std::cos(xnode);
  const double sini = std::sin(xinc), cosi = std::cos(xinc);
  const double xmx = -snod * cosi, xmy = cnod * cosi;
  const double ux = xmx * sinsu + cnod * cossu, uy = xmy * sinsu + snod * cossu, uz = sini * sinsu;
  const double vx = xmx * cossu - cnod * sinsu, vy = xmy * cossu - snod * sinsu, vz = sini * cossu;
  TemeState out;
  const double mr = mrt * s.radiusearthkm;
  out.r_km = {mr * ux, mr * uy, mr * uz};
  out.v_km_s = {(mvt * ux + rvdot * vx) * vkmpersec, (mvt * uy + rvdot * vy) * vkmpersec,
                (mvt * uz + rvdot * vz) * vkmpersec};
  if (mrt < 1.0) {
    std::snprintf(text, sizeof text, "mrt %f is less than 1.0 indicating the satellite has decayed", mrt);
    throw Sgp4Error(6, text);
  }
  return out;
}

// ------------------------------------------------------------ TEME -> J2000
std::array<double, 9> teme_to_j2000_matrix(double jd_utc1, double jd_utc2) {
  double tai1 = 0, tai2 = 0, tt1 = 0, tt2 = 0;
  if (eraUtctai(jd_utc1, jd_utc2, &tai1, &tai2) < 0 || eraTaitt(tai1, tai2, &tt1, &tt2) != 0)
    throw std::invalid_argument("TEME to J2000: the time is outside ERFA's range");
  // TEME -> true of date: TEME's x axis lies GMST (IAU 1982, the angle SGP4's
  // TEME is defined with) east of... that is, Greenwich is GMST82 from TEME's
  // x axis and GAST (IAU 2006/2000A) from the true equinox; the x axes are
  // GAST - GMST82 apart (the equation of the equinoxes, plus the small
  // difference of the GMST models). UT1 = UTC as in the engine (it cancels
  // to first order in the difference).
  double ee = eraAnpm(eraGst06a(jd_utc1, jd_utc2, tt1, tt2) - eraGmst82(jd_utc1, jd_utc2));
  double r3[3][3];
  eraIr(r3);
  eraRz(-ee, r3);  // v_tod = Rz(-ee) v_teme (an active rotation by +ee)
  // true of date -> GCRS: the transpose of the bias-precession-nutation matrix.
  double npb[3][3];
  eraPnm06a(tt1, tt2, npb);
  double m[3][3];
  double npbt[3][3];
  eraTr(npb, npbt);
  eraRxr(npbt, r3, m);
  return {m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
}

}  // namespace eoir::cli
