#include "road/texture_band_psd.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

TextureBandPsd::TextureBandPsd(std::span<const double> centres_m, std::span<const double> levels_db) {
  if (centres_m.empty() || centres_m.size() != levels_db.size()) {
    throw std::invalid_argument("TextureBandPsd: needs as many levels as bands, at least one");
  }
  constexpr double a_ref = 1e-6;  // m (ISO 13473-4 reference of L_tx)
  const double half_band = std::pow(10.0, 1.0 / 20.0);
  // The density on each band, keyed by its edges in wavenumber; adjacent bands share an edge.
  std::map<double, double> change;  // edge wavenumber -> dG there
  for (std::size_t b = 0; b < centres_m.size(); ++b) {
    if (!(centres_m[b] > 0.0) || !std::isfinite(levels_db[b]) ||
        (b > 0 && !(centres_m[b] > centres_m[b - 1] * 1.2))) {
      throw std::invalid_argument("TextureBandPsd: band centres must be increasing third octaves, levels finite");
    }
    const double n_low = 1.0 / (centres_m[b] * half_band);
    const double n_high = half_band / centres_m[b];
    const double power = a_ref * a_ref * std::pow(10.0, levels_db[b] / 10.0);
    const double g = power / (n_high - n_low);
    variance_ += power;
    // Edges of adjacent bands agree to rounding: merge them within a relative 1e-9.
    const auto add = [&](double n, double dg) {
      auto it = change.lower_bound(n * (1.0 - 1e-9));
      if (it != change.end() && it->first <= n * (1.0 + 1e-9)) {
        it->second += dg;
      } else {
        change.emplace(n, dg);
      }
    };
    add(n_low, g);
    add(n_high, -g);
  }
  double g = 0.0;
  for (const auto& [n, dg] : change) {
    g += dg;
    edge_n_.push_back(n);
    step_.push_back(dg);
    density_above_.push_back(std::abs(g) < 1e-300 ? 0.0 : g);
  }
  density_above_.back() = 0.0;
  for (std::size_t k = 0; k < step_.size(); ++k)
    if (step_[k] > 0.0) highest_rising_edge_ = edge_n_[k];
}

double TextureBandPsd::line_density(double n) const {
  n = std::abs(n);
  // The last edge at or below n.
  const auto it = std::upper_bound(edge_n_.begin(), edge_n_.end(), n);
  if (it == edge_n_.begin()) return 0.0;
  return std::max(0.0, density_above_[static_cast<std::size_t>(it - edge_n_.begin()) - 1]);
}

double TextureBandPsd::isotropic_density(double q_low, double q_high) const {
  if (!(q_low >= 0.0) || !(q_high > q_low)) throw std::invalid_argument("TextureBandPsd: bad radial interval");
  // Mean over [q_low, q_high] of -(1/(2 pi)) Σ_e dG_e / sqrt(e^2 - q^2) (zero for q >= e).
  double sum = 0.0;
  for (std::size_t k = 0; k < edge_n_.size(); ++k) {
    const double e = edge_n_[k];
    if (e <= q_low) continue;
    const double integral = std::asin(std::min(q_high, e) / e) - std::asin(q_low / e);
    sum += step_[k] * integral;
  }
  const double s = -sum / (2.0 * std::numbers::pi * (q_high - q_low));
  return std::max(0.0, s);
}

double TextureBandPsd::isotropic_line_cumulative(double nx, double ny) const {
  nx = std::abs(nx);
  const double t = std::abs(ny);
  double sum = 0.0;
  for (std::size_t k = edge_n_.size(); k-- > 0;) {
    const double e = edge_n_[k];
    if (e <= nx) break;  // edges are increasing: none above nx remains
    const double b = std::sqrt((e - nx) * (e + nx));
    sum += step_[k] * (t >= b ? std::numbers::pi / 2.0 : std::asin(t / b));
  }
  const double value = -sum / (2.0 * std::numbers::pi);
  return ny < 0.0 ? -value : value;
}

double TextureBandPsd::isotropic_line_cells(double nx, std::vector<double>& bound, std::vector<double>& cumulative,
                                            std::vector<double>& weight) const {
  nx = std::abs(nx);
  bound.assign(1, 0.0);
  for (double e : edge_n_)
    if (e > nx) bound.push_back(std::sqrt((e - nx) * (e + nx)));
  cumulative.resize(bound.size());
  weight.resize(bound.size() - 1);
  for (std::size_t c = 0; c < bound.size(); ++c) cumulative[c] = isotropic_line_cumulative(nx, bound[c]);
  double total = 0.0;
  for (std::size_t c = 0; c + 1 < bound.size(); ++c) {
    weight[c] = std::max(0.0, cumulative[c + 1] - cumulative[c]);
    total += weight[c];
  }
  return total;
}

double TextureBandPsd::realisable_line_density(double n) const {
  // Above every edge where G rises with n, S >= 0 for all q >= n: nothing is clipped.
  if (std::abs(n) >= highest_rising_edge_) return line_density(n);
  std::vector<double> bound, cumulative, weight;
  return 4.0 * isotropic_line_cells(n, bound, cumulative, weight);  // k >= 0 holds a quarter
}

}  // namespace rollnoise
