#include "universe/central_bodies.hpp"

#include <erfa.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "core/constants.hpp"
#include "universe/vsop87.hpp"

namespace eoir::universe {

const std::vector<CentralBodyInfo>& central_bodies() {
  static const std::vector<CentralBodyInfo> table = {
      {CentralBody::sun, "Sun", 695700.0e3, 695700.0e3, 0, BodyAxes::iau, 25.38 * 86400.0},
      {CentralBody::mercury, "Mercury", 2440.53e3, 2438.26e3, 1, BodyAxes::iau, 4222.6 * 3600.0},
      {CentralBody::venus, "Venus", 6051.8e3, 6051.8e3, 2, BodyAxes::iau, 2802.0 * 3600.0},
      {CentralBody::earth, "Earth", 6378137.0, 6356752.314245, 0, BodyAxes::earth_fixed, 86400.0},
      {CentralBody::mars, "Mars", 3396.19e3, 3376.20e3, 4, BodyAxes::iau, 88775.244},
      {CentralBody::jupiter, "Jupiter", 71492.0e3, 66854.0e3, 5, BodyAxes::iau, 9.9259 * 3600.0},
      {CentralBody::saturn, "Saturn", 60268.0e3, 54364.0e3, 6, BodyAxes::iau, 10.656 * 3600.0},
      {CentralBody::uranus, "Uranus", 25559.0e3, 24973.0e3, 7, BodyAxes::iau, 17.24 * 3600.0},
      {CentralBody::neptune, "Neptune", 24764.0e3, 24341.0e3, 8, BodyAxes::iau, 16.11 * 3600.0},
      {CentralBody::moon, "Moon", 1737.4e3, 1737.4e3, 0, BodyAxes::iau, 29.530589 * 86400.0},
  };
  return table;
}

// Defaults of the surfaces, so that each body is seen as bright as it is.
// Planets: gray bodies of SRF = 1.5 p (their disc's p is 2/3 SRF in eq. 7,
// radiometry/disk_photometry.hpp), p the geometric albedo that Mallama &
// Hilton's (2018) V(1, 0) gives for the volumetric mean radius (IAU 2015) and
// the engine's solar V of -26.762 (E-490 through Bessell's V):
// p = 10^(-0.4 (V(1,0) + 26.762)) (1 au / R)^2: Mercury -0.613 -> 0.1305,
// Venus -4.384 -> 0.684 (SRF capped at 1: 0.03 mag faint), Mars -1.601 ->
// 0.168, Jupiter -9.395 -> 0.5175, Saturn (globe) -8.95 -> 0.495, Uranus
// -7.110 -> 0.479, Neptune -7.00 -> 0.4595. Temperatures: effective
// (thermal-emission) temperatures of the NASA NSSDC planetary fact sheets
// (Mercury's surface 100-700 K, Venus' cloud tops ~230 K, Mars 210 K mean,
// Jupiter 124.4 K, Saturn 95 K, Uranus 59.1 K, Neptune 59.3 K). Mars is gray
// too: the laboratory analogue of its dust (material mars_surface, JSC
// Mars-1) reflects 0.10 in V, and the disc would be 0.8 mag fainter than Mars
// is. The Earth: its Bond albedo 0.306 as a gray SRF of 0.3 and the
// climatology thermal model (spec 4.3.1.3); the Moon its data-folder material
// (Apollo 62231 regolith at the lunar geometric albedo 0.12, with the lunar
// Lommel-Seeliger law) with the subsolar model (390 K, 95 K at night: spec
// 4.3.1.3), its albedo map on the same law.
const CentralBodySurface& central_body_surface(CentralBody id) {
  static const CentralBodySurface table[] = {
      {"gray_body", 0.0, 5772.0, 0.0, false},        // Sun (its E-490 spectrum replaces eps B(T))
      {"gray_body", 0.196, 700.0, 100.0, false},     // Mercury: subsolar
      {"gray_body", 1.0, 230.0, 0.0, false},         // Venus
      {"gray_body", 0.3, 288.0, 0.0, true},          // Earth: climatology
      {"gray_body", 0.252, 210.0, 0.0, false},       // Mars
      {"gray_body", 0.776, 124.4, 0.0, false},       // Jupiter
      {"gray_body", 0.743, 95.0, 0.0, false},        // Saturn
      {"gray_body", 0.719, 59.1, 0.0, false},        // Uranus
      {"gray_body", 0.689, 59.3, 0.0, false},        // Neptune
      {"lunar_regolith", 0.0, 390.0, 95.0, false, "lunar_gray_body"},  // Moon: subsolar
  };
  return table[static_cast<std::size_t>(id)];
}

const CentralBodyInfo& central_body_info(CentralBody id) { return central_bodies()[static_cast<std::size_t>(id)]; }

const CentralBodyInfo* find_central_body(const std::string& name) {
  for (const auto& b : central_bodies())
    if (name == b.name) return &b;
  return nullptr;
}

namespace {

// The ephemeris at one instant (geocentric J2000, m and m/s).
void erfa_state_j2000(const CentralBodyInfo& body, const EngineTime& t, frames::Vec3& r_m, frames::Vec3& v_m_s) {
  const JulianDate tdb = t.to(TimeScale::tdb);
  constexpr double au = constants::au_m;
  constexpr double au_per_day = constants::au_m / constants::seconds_per_day;
  double pv[2][3];
  if (body.id == CentralBody::moon) {
    eraMoon98(tdb.jd1, tdb.jd2, pv);
    r_m = frames::Vec3(pv[0][0], pv[0][1], pv[0][2]) * au;
    v_m_s = frames::Vec3(pv[1][0], pv[1][1], pv[1][2]) * au_per_day;
    return;
  }
  double earth_h[2][3], earth_b[2][3];
  eraEpv00(tdb.jd1, tdb.jd2, earth_h, earth_b);
  frames::Vec3 rh(0, 0, 0), vh(0, 0, 0);  // heliocentric body (Sun: zero)
  if (body.erfa_planet > 0) {  // VSOP87B (issue 21: eraPlan94 is 20" off for Mars and Jupiter)
    vsop87::heliocentric_state(body.erfa_planet, tdb.jd1, tdb.jd2, pv[0], pv[1]);
    rh = frames::Vec3(pv[0][0], pv[0][1], pv[0][2]);
    vh = frames::Vec3(pv[1][0], pv[1][1], pv[1][2]);
  }
  r_m = (rh - frames::Vec3(earth_h[0][0], earth_h[0][1], earth_h[0][2])) * au;
  v_m_s = (vh - frames::Vec3(earth_h[1][0], earth_h[1][1], earth_h[1][2])) * au_per_day;
}

struct NodeState {
  frames::Vec3 r, v;
};

constexpr double kNodesPerDay = constants::seconds_per_day / kEphemerisGridStep_s;

// The ephemeris' state at grid node k_in_day of TT day `day` (whole days since
// J2000), computed once per thread and kept (a bounded table).
const NodeState& node_state(const CentralBodyInfo& body, double day, std::int64_t k_in_day) {
  thread_local std::unordered_map<std::uint64_t, NodeState> nodes;
  const auto per_day = static_cast<std::int64_t>(kNodesPerDay);
  const std::int64_t k = static_cast<std::int64_t>(day) * per_day + k_in_day;
  const std::uint64_t key = (static_cast<std::uint64_t>(k) << 4) | static_cast<std::uint64_t>(body.id);
  auto it = nodes.find(key);
  if (it != nodes.end()) return it->second;
  if (nodes.size() > 4096) nodes.clear();
  NodeState n;
  erfa_state_j2000(body, EngineTime::from_tt_days(day, static_cast<double>(k_in_day) / kNodesPerDay), n.r, n.v);
  return nodes.emplace(key, n).first->second;
}

}  // namespace

void central_body_state_j2000(const CentralBodyInfo& body, const EngineTime& t, frames::Vec3& r_m,
                              frames::Vec3& v_m_s) {
  r_m.setZero();
  v_m_s.setZero();
  if (body.id == CentralBody::earth) return;
  // Cubic Lagrange through the four grid nodes around t (the series'
  // positions and, separately, their velocities there: a series' velocity
  // is not the derivative of its position to better than ~1 m/s, so a
  // Hermite blend of the two would move positions by ~100 m). The series run
  // once per node instead of at every time a frame asks for (light-time
  // iterations, integration start and end).
  const double x = t.fraction() * kNodesPerDay;
  const double k = std::floor(x), u = x - k;
  const auto k0 = static_cast<std::int64_t>(k);
  const double w[4] = {-u * (u - 1) * (u - 2) / 6, (u + 1) * (u - 1) * (u - 2) / 2, -(u + 1) * u * (u - 2) / 2,
                       (u + 1) * u * (u - 1) / 6};
  for (int i = 0; i < 4; ++i) {
    const NodeState n = node_state(body, t.days(), k0 - 1 + i);  // a copy: a lookup may clear the table
    r_m += w[i] * n.r;
    v_m_s += w[i] * n.v;
  }
}
}  // namespace eoir::universe
