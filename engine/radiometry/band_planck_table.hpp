// The band radiance of a body at temperature T on the view's grid (eq. 48 of
// eq. 4's self-emission): f(T) = integral of w(lambda) B_lambda(T), with
// w the emissivity at the grid's wavelengths, tabulated so that a sample
// costs one exp instead of one Planck term per wavelength.
//
// ln f is smooth in u = 1/T (in the Wien regime each term is exp(-c2 u /
// lambda)). Cubic Hermite interpolation of ln f between nodes 1e-6 K^-1
// apart in u, with the exact derivative d ln f / du at each node, done
// relative to the node below (f = f_k exp(delta), delta interpolating
// ln(f / f_k), so a large |ln f| costs no precision), is within 3e-13 of f
// for bands from 0.3 to 14 um over 30-1200 K (band_planck_table_test checks
// 1e-12 at 20,000 temperatures; at 30 K in a visible band 1e-13 is the direct
// sum's own rounding, x eps with x = c2 / lambda T ~ 1000). Above 1200 K the
// spacing would have to shrink as 1/T^2 for the same error. Nodes are made on
// first use, 64 at a time, so a frame pays only for the temperatures it
// holds. Outside the table (below 10 K, above 1200 K) and where f underflows,
// f is the direct sum.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "radiometry/band_integral.hpp"

namespace eoir::radiometry {

class BandPlanckTable {
 public:
  // weights: w at the sample wavelengths (one per interval).
  BandPlanckTable(const SpectralBand& band, std::vector<double> sample_wavelengths_um, std::vector<double> weights);
  ~BandPlanckTable();
  BandPlanckTable(const BandPlanckTable&) = delete;
  BandPlanckTable& operator=(const BandPlanckTable&) = delete;

  // f(T), W cm^-2 sr^-1.
  double radiance(double temperature_K) const;
  // f(T) summed term by term (the table's nodes, and the value off it).
  double direct(double temperature_K) const;
  // wa f_a(T) + wb f_b(T) of two tables (the same nodes) with one exp:
  // f_b / f_a over a node interval is exp of a small difference (|x| < 1e-3:
  // four terms of its series, below 1e-17), so a blend of two emissivities
  // costs one look-up. Within a few ulp of the two look-ups' sum.
  static double blend(double wa, const BandPlanckTable& a, double wb, const BandPlanckTable& b, double temperature_K);

  static constexpr double node_spacing_per_K = 1e-6;  // in u = 1/T
  static constexpr double min_temperature_K = 10.0, max_temperature_K = 1200.0;
  static constexpr int nodes_per_block = 64;

 private:
  struct Node {
    double f;               // f at the node (NaN where it is not a positive normal number)
    double slope_per_node;  // d ln f / du times the node spacing
    double log_ratio;       // ln(f at the next node / f)
  };
  Node node(double u) const;
  const Node* block(std::size_t b) const;
  const Node* node_below(double temperature_K, double& t) const;
  static double log_ratio_at(const Node* nodes, double t);

  SpectralBand band_;
  std::vector<double> wavelengths_um_, weights_;
  double u_min_ = 0;
  // Block b holds nodes [64 b, 64 b + 64], the last shared with block b + 1.
  std::unique_ptr<std::atomic<const Node*>[]> blocks_;
  std::size_t block_count_ = 0;
  mutable std::mutex fill_mutex_;
};

}  // namespace eoir::radiometry
