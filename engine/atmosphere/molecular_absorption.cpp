#include "atmosphere/molecular_absorption.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "atmosphere/data_table.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {

// LOWTRAN 7's reference state of the scaled amounts (STDMDL): P0, T0.
constexpr double kP0_Pa = 101325.0, kT0_K = 273.15;
constexpr double kLoschmidt_cm3 = kLoschmidt_m3 * 1e-6;

// A function of wavenumber, linear between strictly increasing points, 0
// outside them.
struct Table {
  std::vector<double> v, y;
  void add(double x, double value, const std::string& where) {
    if (!v.empty() && !(x > v.back())) throw Error(Status::corrupt_file, where + ": wavenumbers must increase");
    v.push_back(x);
    y.push_back(value);
  }
  double operator()(double x) const {
    if (v.empty() || x < v.front() || x > v.back()) return 0.0;
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(v.begin(), v.end(), x) - v.begin());
    if (i >= v.size()) return y.back();
    const double f = (x - v[i - 1]) / (v[i] - v[i - 1]);
    return y[i - 1] + f * (y[i] - y[i - 1]);
  }
};

// Which amount of a path an absorber of the band models counts.
enum class Amount { h2o, o3, mixed };

struct Region {
  double from_cm1, to_cm1;
  int band;  // the amount's scaling (n, m) index
  double a;
  Table log10_c;
};

struct Absorber {
  std::string name;
  Amount amount = Amount::mixed;
  std::size_t mixed = 0;  // MixedGas index
  std::vector<Region> regions;
};

// tau = -ln(exp(-(C W)^a)) with LOWTRAN's cut-offs (FUNCTION DBLTX).
double band_depth(double log10_c, double log10_w, double a) {
  const double x = a * (log10_c + log10_w);
  if (x <= -6.0) return 0.0;
  if (x >= 2.0) return 100.0;
  return std::pow(10.0, x);
}

// R(v, T) = v tanh(hcv / 2kT): the continuum's radiation term (cm^-1).
double radiation_term(double v, double T) { return v * std::tanh(v / (2.0 * 0.6952 * T)); }

// LOWTRAN 7's far-wing addition to the foreign continuum (SUBROUTINE FUDGE).
double far_wing(double v) {
  return 1.0 / (1.0 / (1.025 * 3.159e-8 * std::exp(-2.75e-4 * v)) + 1.0 / (8.97e-6 * std::exp(-1.3e-3 * v)));
}

class LowtranBandModel final : public MolecularAbsorption {
 public:
  explicit LowtranBandModel(const std::string& dir) {
    load_bands(dir);
    load_continua(dir);
  }

  void optical_depths(const PathColumns& path, const std::vector<double>& wavelength_um,
                      std::vector<double>& tau) const override {
    tau.assign(wavelength_um.size(), 0.0);
    if (!path.crosses) return;
    if (path.segments.empty())
      throw Error(Status::internal, "molecular absorption: the path's segments were not kept");
    const Amounts w = amounts(path);
    for (std::size_t k = 0; k < wavelength_um.size(); ++k) {
      const double v = 1e4 / wavelength_um[k];
      double t = 0;
      for (const Absorber& a : absorbers_) {
        const auto r = std::find_if(a.regions.begin(), a.regions.end(),
                                    [v](const Region& g) { return v >= g.from_cm1 && v <= g.to_cm1; });
        if (r == a.regions.end()) continue;
        const auto found = w.scaled.find(r->band);
        if (found == w.scaled.end() || !(found->second > 1e-20)) continue;
        t += band_depth(r->log10_c(v), std::log10(found->second), r->a);
      }
      // H2O continuum (self at 296 K and 260 K, foreign; radiation term).
      if (v < h2o_self_296_.v.back()) {
        const double x = 1.0 - 0.2333 * (200.0 * 200.0 / ((v - 1050.0) * (v - 1050.0) + 200.0 * 200.0));
        const double s0 = h2o_self_296_(v) * x * radiation_term(v, 296.0);
        const double s1 = h2o_self_260_(v) * x * radiation_term(v, 260.0);
        const double f = (h2o_foreign_(v) + far_wing(v)) * radiation_term(v, 296.0);
        t += 1e-20 * (s0 * w.self + (s1 - s0) * w.self_cold + f * w.foreign);
      }
      // Ozone: Chappuis (13000-24200 cm^-1), Hartley-Huggins (27370-40800).
      if (v >= 13000.0 && v <= 24200.0) t += chappuis_(v) * w.o3_atm_cm;
      if (v >= hartley_c0_.v.front() && v < 40800.0) {
        const std::size_t i = static_cast<std::size_t>(
            std::upper_bound(hartley_c0_.v.begin(), hartley_c0_.v.end(), v) - hartley_c0_.v.begin() - 1);
        t += hartley_c0_(v) * (0.269 * w.o3_atm_cm + hartley_c1_[i] * w.o3_t1 + hartley_c2_[i] * w.o3_t2);
      }
      // N2 (4.3 um) and O2 (6.4 um) collision-induced continua.
      t += n2_(v) * w.n2_km;
      if (v >= o2_s0_.v.front() && v <= o2_s0_.v.back()) {
        const double A = o2_a_(v), B = 0.5 * A * A + o2_b_(v);
        t += o2_s0_(v) / 0.20946 * (w.o2 + A * w.o2_t1 + B * w.o2_t2);
      }
      tau[k] = t;
    }
  }

 private:
  // A path's amounts in LOWTRAN's units, from its layer-by-layer segments.
  struct Amounts {
    std::map<int, double> scaled;  // per band scaling index: sum of u (P/P0)^n (T0/T)^m
    double self = 0, self_cold = 0, foreign = 0;  // H2O continuum (molecules cm^-2 amagat)
    double o3_atm_cm = 0, o3_t1 = 0, o3_t2 = 0;
    double n2_km = 0;
    double o2 = 0, o2_t1 = 0, o2_t2 = 0;
  };

  Amounts amounts(const PathColumns& path) const {
    Amounts w;
    for (const auto& [band, nm] : scaling_) w.scaled[band] = 0.0;
    for (const PathSegment& s : path.segments) {
      if (!(s.length_m > 0) || !(s.air_m2 > 0)) continue;
      // (temperatures held at 1 K or more: the scalings divide by them)
      const double temperature_K = std::max(s.temperature_K, 1.0);
      const double pss = s.pressure_Pa / kP0_Pa, tss = kT0_K / temperature_K;
      const double lp = std::log(pss), lt = std::log(tss);
      const double h2o_g_cm2 = precipitable_water_g_cm2(s.h2o_m2);
      const double o3_atm_cm = atm_cm(s.o3_m2);
      std::array<double, kMixedGases> mixed_atm_cm{};
      for (std::size_t g = 0; g < kMixedGases; ++g) mixed_atm_cm[g] = atm_cm(s.mixed_m2[g]);
      for (const auto& [band, nm] : scaling_) {
        const double u = nm.amount == Amount::h2o ? h2o_g_cm2 : nm.amount == Amount::o3 ? o3_atm_cm : mixed_atm_cm[nm.mixed];
        w.scaled[band] += u * std::exp(nm.n * lp + nm.m * lt);
      }
      // Mean densities of the segment in amagat.
      const double w_amagat = s.h2o_m2 / s.length_m / kLoschmidt_m3, air_amagat = s.air_m2 / s.length_m / kLoschmidt_m3;
      const double h2o_cm2 = s.h2o_m2 * 1e-4, r0 = kT0_K / 296.0;
      const double self = h2o_cm2 * w_amagat / r0;
      w.self += self;
      w.self_cold += std::clamp((296.0 - temperature_K) / 36.0, 0.0, 1.0) * self;
      w.foreign += h2o_cm2 * (air_amagat - w_amagat) / r0;
      const double dt = temperature_K - kT0_K;
      w.o3_atm_cm += o3_atm_cm;
      w.o3_t1 += 0.269 * o3_atm_cm * dt;
      w.o3_t2 += 0.269 * o3_atm_cm * dt * dt;
      w.n2_km += 0.781 * pss * pss * std::pow(tss, 1.5) * s.length_m * 1e-3;
      const double o2 = mixed_atm_cm[static_cast<std::size_t>(MixedGas::o2)] * pss, d220 = temperature_K - 220.0;
      w.o2 += o2;
      w.o2_t1 += o2 * d220;
      w.o2_t2 += o2 * d220 * d220;
    }
    return w;
  }

  void load_bands(const std::string& dir) {
    const std::string ppath = dir + "/atmosphere/band_model_parameters_lowtran7.csv";
    const DataTable p = read_data_table(ppath);
    const std::size_t from = p.column("from_cm1"), to = p.column("to_cm1");
    const std::size_t band = p.column("band_index"), a = p.column("a");
    const std::size_t n = p.column("n"), m = p.column("m");
    const std::map<std::string, std::pair<Amount, std::size_t>> known{
        {"H2O", {Amount::h2o, 0}},
        {"O3", {Amount::o3, 0}},
        {"CO2", {Amount::mixed, static_cast<std::size_t>(MixedGas::co2)}},
        {"N2O", {Amount::mixed, static_cast<std::size_t>(MixedGas::n2o)}},
        {"CO", {Amount::mixed, static_cast<std::size_t>(MixedGas::co)}},
        {"CH4", {Amount::mixed, static_cast<std::size_t>(MixedGas::ch4)}},
        {"O2", {Amount::mixed, static_cast<std::size_t>(MixedGas::o2)}}};
    // Only the gases the profiles carry (NO, SO2, NO2, NH3 have no amounts).
    for (std::size_t r = 0; r < p.rows.size(); ++r) {
      const auto k = known.find(p.key[r]);
      if (k == known.end()) continue;
      auto it = std::find_if(absorbers_.begin(), absorbers_.end(), [&](const Absorber& x) { return x.name == p.key[r]; });
      if (it == absorbers_.end()) {
        absorbers_.push_back(Absorber{p.key[r], k->second.first, k->second.second, {}});
        it = absorbers_.end() - 1;
      }
      const int b = static_cast<int>(p.rows[r][band]);
      it->regions.push_back(Region{p.rows[r][from], p.rows[r][to], b, p.rows[r][a], {}});
      scaling_[b] = Scaling{k->second.first, k->second.second, p.rows[r][n], p.rows[r][m]};
    }
    const std::string cpath = dir + "/atmosphere/band_model_lowtran7.csv";
    const DataTable c = read_data_table(cpath);
    const std::size_t v = c.column("wavenumber_cm1"), coefficient = c.column("coefficient");
    for (std::size_t r = 0; r < c.rows.size(); ++r) {
      auto it = std::find_if(absorbers_.begin(), absorbers_.end(), [&](const Absorber& x) { return x.name == c.key[r]; });
      if (it == absorbers_.end()) continue;
      const double x = c.rows[r][v];
      auto g = std::find_if(it->regions.begin(), it->regions.end(),
                            [x](const Region& reg) { return x >= reg.from_cm1 && x <= reg.to_cm1; });
      if (g == it->regions.end())
        throw Error(Status::corrupt_file, cpath + ": " + c.key[r] + " at " + std::to_string(x) + " cm-1 lies in no band region");
      g->log10_c.add(x, c.rows[r][coefficient], cpath + ": " + c.key[r]);
    }
    for (const Absorber& absorber : absorbers_)
      for (const Region& g : absorber.regions)
        if (g.log10_c.v.size() < 2)
          throw Error(Status::corrupt_file, cpath + ": " + absorber.name + ": a band region has fewer than two points");
  }

  void load_continua(const std::string& dir) {
    const std::string hpath = dir + "/atmosphere/h2o_continuum_lowtran7.csv";
    const DataTable h = read_data_table(hpath);
    const std::size_t s296 = h.column("self_296K"), s260 = h.column("self_260K");
    const std::size_t f296 = h.column("foreign_296K");
    for (std::size_t r = 0; r < h.rows.size(); ++r) {
      const double v = std::strtod(h.key[r].c_str(), nullptr);
      h2o_self_296_.add(v, h.rows[r][s296], hpath);
      h2o_self_260_.add(v, h.rows[r][s260], hpath);
      h2o_foreign_.add(v, h.rows[r][f296], hpath);
    }
    const std::string opath = dir + "/atmosphere/o3_uv_visible_lowtran7.csv";
    const DataTable o = read_data_table(opath);
    const std::size_t ov = o.column("wavenumber_cm1"), c0 = o.column("c0", true);
    const std::size_t c1 = o.column("c1", true), c2 = o.column("c2", true);
    for (std::size_t r = 0; r < o.rows.size(); ++r) {
      if (o.key[r] == "chappuis_c8") chappuis_.add(o.rows[r][ov], o.rows[r][c0], opath + ": chappuis_c8");
      if (o.key[r] == "hartley_huggins" && !std::isnan(o.rows[r][c0])) {  // (the last c1, c2 rows have no c0)
        hartley_c0_.add(o.rows[r][ov], o.rows[r][c0], opath + ": hartley_huggins");
        hartley_c1_.push_back(std::isnan(o.rows[r][c1]) ? 0.0 : o.rows[r][c1]);
        hartley_c2_.push_back(std::isnan(o.rows[r][c2]) ? 0.0 : o.rows[r][c2]);
      }
    }
    const std::string kpath = dir + "/atmosphere/continua_lowtran7.csv";
    const DataTable k = read_data_table(kpath);
    const std::size_t kv = k.column("wavenumber_cm1"), value = k.column("value");
    const std::size_t alpha = k.column("alpha", true), beta = k.column("beta", true);
    for (std::size_t r = 0; r < k.rows.size(); ++r) {
      if (k.key[r] == "n2") n2_.add(k.rows[r][kv], k.rows[r][value], kpath + ": n2");
      if (k.key[r].rfind("o2", 0) == 0) {
        o2_s0_.add(k.rows[r][kv], k.rows[r][value], kpath + ": o2");
        o2_a_.add(k.rows[r][kv], k.rows[r][alpha], kpath + ": o2");
        o2_b_.add(k.rows[r][kv], k.rows[r][beta], kpath + ": o2");
      }
    }
    if (h2o_self_296_.v.size() < 2 || chappuis_.v.size() < 2 || hartley_c0_.v.size() < 2 || n2_.v.size() < 2 ||
        o2_s0_.v.size() < 2)
      throw Error(Status::corrupt_file, dir + "/atmosphere: a continuum table is missing");
  }

  struct Scaling {
    Amount amount = Amount::mixed;
    std::size_t mixed = 0;
    double n = 0, m = 0;
  };
  std::vector<Absorber> absorbers_;
  std::map<int, Scaling> scaling_;
  Table h2o_self_296_, h2o_self_260_, h2o_foreign_;
  Table chappuis_, hartley_c0_;
  std::vector<double> hartley_c1_, hartley_c2_;
  Table n2_, o2_s0_, o2_a_, o2_b_;
};
}  // namespace

std::unique_ptr<const MolecularAbsorption> MolecularAbsorption::load(const std::string& data_dir) {
  return std::make_unique<const LowtranBandModel>(data_dir);
}

}  // namespace eoir::atmosphere
