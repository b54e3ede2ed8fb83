#include "radiometry/band_planck_table.hpp"

#include <cmath>
#include <limits>

#include "radiometry/planck.hpp"

namespace eoir::radiometry {

BandPlanckTable::BandPlanckTable(const SpectralBand& band, std::vector<double> sample_wavelengths_um,
                                 std::vector<double> weights)
    : band_(band), wavelengths_um_(std::move(sample_wavelengths_um)), weights_(std::move(weights)) {
  u_min_ = 1.0 / max_temperature_K;
  const auto intervals = static_cast<std::size_t>(std::ceil((1.0 / min_temperature_K - u_min_) / node_spacing_per_K));
  block_count_ = (intervals + nodes_per_block - 1) / nodes_per_block;
  blocks_ = std::make_unique<std::atomic<const Node*>[]>(block_count_);
  for (std::size_t b = 0; b < block_count_; ++b) blocks_[b].store(nullptr, std::memory_order_relaxed);
}

BandPlanckTable::~BandPlanckTable() {
  for (std::size_t b = 0; b < block_count_; ++b) delete[] blocks_[b].load(std::memory_order_relaxed);
}

double BandPlanckTable::direct(double temperature_K) const {
  double sum = 0;
  for (std::size_t i = 0; i < weights_.size(); ++i) sum += weights_[i] * planck_radiance(wavelengths_um_[i], temperature_K);
  return sum * band_.interval_um();
}

BandPlanckTable::Node BandPlanckTable::node(double u) const {
  // B = c1 lambda^-5 / (e^x - 1), x = c2 u / lambda: dB/du = -B (c2 / lambda) e^x / (e^x - 1).
  double f = 0, df = 0;
  for (std::size_t i = 0; i < weights_.size(); ++i) {
    const double x = c2_um_K * u / wavelengths_um_[i];
    const double B = planck_radiance(wavelengths_um_[i], 1.0 / u);
    f += weights_[i] * B;
    df -= weights_[i] * B * (c2_um_K / wavelengths_um_[i]) * (1.0 + 1.0 / std::expm1(x));
  }
  if (!(f >= std::numeric_limits<double>::min()) || !std::isfinite(df))
    return Node{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
  return Node{f * band_.interval_um(), df / f * node_spacing_per_K, 0.0};
}

const BandPlanckTable::Node* BandPlanckTable::block(std::size_t b) const {
  if (const Node* ready = blocks_[b].load(std::memory_order_acquire)) return ready;
  std::lock_guard<std::mutex> lock(fill_mutex_);
  if (const Node* ready = blocks_[b].load(std::memory_order_acquire)) return ready;
  auto nodes = std::make_unique<Node[]>(nodes_per_block + 1);
  for (int k = 0; k <= nodes_per_block; ++k)
    nodes[static_cast<std::size_t>(k)] =
        node(u_min_ + static_cast<double>(b * nodes_per_block + static_cast<std::size_t>(k)) * node_spacing_per_K);
  for (std::size_t k = 0; k < nodes_per_block; ++k) nodes[k].log_ratio = std::log(nodes[k + 1].f / nodes[k].f);
  blocks_[b].store(nodes.get(), std::memory_order_release);
  return nodes.release();
}

// The node below T and the offset t in [0, 1) past it; null off the table.
const BandPlanckTable::Node* BandPlanckTable::node_below(double temperature_K, double& t) const {
  if (!(temperature_K > min_temperature_K && temperature_K < max_temperature_K)) return nullptr;
  const double s = (1.0 / temperature_K - u_min_) / node_spacing_per_K;
  const auto k = static_cast<std::size_t>(s);
  const std::size_t b = k / nodes_per_block;
  if (b >= block_count_) return nullptr;
  t = s - static_cast<double>(k);
  return block(b) + (k - b * nodes_per_block);
}

// ln(f(T) / f at the node below): cubic Hermite on [0, 1] (h00 + h01 = 1).
double BandPlanckTable::log_ratio_at(const Node* nodes, double t) {
  const double t2 = t * t, t3 = t2 * t;
  return (3 * t2 - 2 * t3) * nodes[0].log_ratio + (t3 - 2 * t2 + t) * nodes[0].slope_per_node +
         (t3 - t2) * nodes[1].slope_per_node;
}

double BandPlanckTable::blend(double wa, const BandPlanckTable& a, double wb, const BandPlanckTable& b,
                              double temperature_K) {
  const auto separately = [&] { return wa * a.radiance(temperature_K) + wb * b.radiance(temperature_K); };
  double t = 0;
  const Node* na = a.node_below(temperature_K, t);
  if (!na) return separately();
  const Node* nb = b.node_below(temperature_K, t);  // (the same nodes: one u grid for every table)
  const double delta_a = log_ratio_at(na, t), x = log_ratio_at(nb, t) - delta_a;
  const double ratio =
      std::fabs(x) < 1e-3 ? 1.0 + x * (1.0 + 0.5 * x * (1.0 + x / 3.0 * (1.0 + 0.25 * x))) : std::exp(x);
  const double f = std::exp(delta_a) * (wa * na[0].f + wb * nb[0].f * ratio);
  return std::isfinite(f) ? f : separately();  // (a node where f underflows: NaN)
}

double BandPlanckTable::radiance(double temperature_K) const {
  double t = 0;
  const Node* nodes = node_below(temperature_K, t);
  if (!nodes) return direct(temperature_K);
  const double f = nodes[0].f * std::exp(log_ratio_at(nodes, t));
  if (std::isnan(f)) return direct(temperature_K);  // a node where f underflows
  return f;
}

}  // namespace eoir::radiometry
