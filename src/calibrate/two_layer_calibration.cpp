#include "calibrate/two_layer_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <mutex>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "greens/causal_modulus.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
constexpr double pi = std::numbers::pi;

// Parameter order of TwoLayerCalibration::parameters().
enum Index : std::size_t {
  belt_youngs_modulus_x,
  belt_youngs_modulus_y,
  belt_youngs_modulus_z,
  belt_shear_modulus_xy,
  belt_shear_modulus_xz,
  belt_shear_modulus_yz,
  belt_density,
  belt_loss_factor,
  tread_youngs_modulus,
  tread_density,
  tread_loss_factor,
  tension_x,
  tension_y,
  foundation_stiffness,
  foundation_loss_factor,
  count
};

// Which part of the stack a parameter changes: a finite difference recomputes only that.
enum class Part { belt, tread, inner };

Part part_of(std::size_t k) {
  if (k <= belt_loss_factor) return Part::belt;
  if (k <= tread_loss_factor) return Part::tread;
  return Part::inner;
}

// Relative step of the central differences: it balances truncation (∝ h², which matters on
// sharp resonances) against the rounding of the layer solutions, amplified by the cancelling
// terms of the modal sum (∝ 1/h): 1e-4 and 1e-6 give errors of 3e-5 and 2e-5 of |α| where
// 1e-5 gives 3e-6 (tests/calibrate).
constexpr double relative_step = 1e-5;

// Chebyshev–Lobatto interpolation on [−1, 1] with n nodes x_j = cos(πj/(n − 1)): the
// barycentric basis values at t (they sum to 1).
class LobattoBasis {
 public:
  explicit LobattoBasis(int n) : x_(static_cast<std::size_t>(n)), w_(static_cast<std::size_t>(n)) {
    for (int j = 0; j < n; ++j) {
      x_[static_cast<std::size_t>(j)] = std::cos(pi * j / (n - 1));
      w_[static_cast<std::size_t>(j)] = (j % 2 == 0 ? 1.0 : -1.0) * (j == 0 || j == n - 1 ? 0.5 : 1.0);
    }
  }
  void operator()(double t, double* out) const {
    const std::size_t n = x_.size();
    double sum = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const double d = t - x_[j];
      if (std::abs(d) < 1e-15) {
        std::fill(out, out + n, 0.0);
        out[j] = 1.0;
        return;
      }
      out[j] = w_[j] / d;
      sum += out[j];
    }
    for (std::size_t j = 0; j < n; ++j) out[j] /= sum;
  }

 private:
  std::vector<double> x_, w_;
};

double sinc(double z) { return std::abs(z) < 1e-8 ? 1.0 - z * z / 6.0 : std::sin(z) / z; }

}  // namespace

// The wavenumbers at which the stack is solved: the kept modes, then the tail's interpolation
// nodes; and how the lattice is split between them.
struct TwoLayerCalibration::Nodes {
  static constexpr int radial_nodes = 12;
  static constexpr int angle_nodes = 5;

  std::vector<double> kx, ky;      // per node
  std::vector<int> last_kept_m;    // per lateral row from the first order: the last kept m (−1: none)
  std::vector<std::size_t> row_offset;  // index of the row's first kept mode
  std::size_t kept = 0;
  int lattice_m = 0, lattice_n = 0;  // the tail's last orders
  // The tail is interpolated in ln ρ, ρ = k/k_edge(θ), with k_edge(θ) where the estimated
  // resonance along the direction θ reaches twice the band's top: the kept modes then lie at
  // ρ < 1 in every direction, and the belt's resonances with them, while in ln k alone the
  // interpolation range of a direction of low tension (across) would reach into them.
  std::vector<double> edge;  // k_edge at u = cos 2θ = −1 + 2t/(edge.size() − 1)
  double log_rho_low = 0.0, log_rho_high = 0.0;

  double edge_at(double u) const {
    const double where = 0.5 * (std::clamp(u, -1.0, 1.0) + 1.0) * static_cast<double>(edge.size() - 1);
    const std::size_t t = std::min(static_cast<std::size_t>(where), edge.size() - 2);
    const double f = where - static_cast<double>(t);
    return (1.0 - f) * edge[t] + f * edge[t + 1];
  }
  // The interpolation coordinate in [−1, 1] of the wavenumber (k_x, k_y).
  double coordinate(double k, double u) const {
    const double s = 2.0 * (std::log(k / edge_at(u)) - log_rho_low) / (log_rho_high - log_rho_low) - 1.0;
    return std::clamp(s, -1.0, 1.0);
  }

  bool is_kept(int m, int row) const {
    return row < static_cast<int>(last_kept_m.size()) && m <= last_kept_m[static_cast<std::size_t>(row)];
  }
};

// Node values of Ĝ_zz (and of its derivatives) per parameter set and frequency.
struct TwoLayerCalibration::Cache {
  struct Entry {
    std::vector<cd> g;
    std::map<std::size_t, std::vector<cd>> dg;  // by parameter index
  };
  using Key = std::pair<double, std::vector<double>>;  // ω, the parameter values
  static constexpr std::size_t capacity = 1024;  // entries (about 30 kB each): two evaluations of 500 lines

  std::mutex mutex;
  std::map<Key, Entry> entries;
  std::deque<Key> order;  // oldest first
};

namespace {

// The tyre with `v` (one per parameter, in Index order) in place of its own.
TwoLayerParameters apply_values(TwoLayerParameters p, std::span<const double> v) {
  p.belt.youngs_x = v[belt_youngs_modulus_x];
  p.belt.youngs_y = v[belt_youngs_modulus_y];
  p.belt.youngs_z = v[belt_youngs_modulus_z];
  p.belt.shear_xy = v[belt_shear_modulus_xy];
  p.belt.shear_xz = v[belt_shear_modulus_xz];
  p.belt.shear_yz = v[belt_shear_modulus_yz];
  p.belt_density = v[belt_density];
  p.belt_loss_factor = v[belt_loss_factor];
  p.tread_youngs_modulus = v[tread_youngs_modulus];
  p.tread_density = v[tread_density];
  p.tread_loss_factor = v[tread_loss_factor];
  p.tension_x = v[tension_x];
  p.tension_y = v[tension_y];
  p.foundation_stiffness = v[foundation_stiffness];
  p.foundation_loss_factor = v[foundation_loss_factor];
  return p;
}

// Ĝ_zz at every node for `values`, and the layers' stiffnesses when `belt`/`tread` are given.
void node_values(const TwoLayerCalibration::Nodes& nodes, const TwoLayerStack& stack, cd omega, std::vector<cd>& g,
                 std::vector<LayerStiffness>* belt, std::vector<LayerStiffness>* tread) {
  const std::size_t count = nodes.kx.size();
  g.resize(count);
  if (belt) belt->resize(count);
  if (tread) tread->resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    const LayerStiffness b = stack.belt_stiffness(nodes.kx[j], nodes.ky[j], omega);
    const LayerStiffness t = stack.tread_stiffness(nodes.kx[j], nodes.ky[j], omega);
    g[j] = stack.surface_compliance(b, t, nodes.kx[j], nodes.ky[j], omega)(2, 2);
    if (belt) (*belt)[j] = b;
    if (tread) (*tread)[j] = t;
  }
}

class TwoLayerReceptance : public ReceptanceFunction {
 public:
  TwoLayerReceptance(const TwoLayerParameters& tyre, std::shared_ptr<const TwoLayerCalibration::Nodes> nodes,
                     std::shared_ptr<TwoLayerCalibration::Cache> cache, std::vector<double> weights)
      : tyre_(tyre), nodes_(std::move(nodes)), cache_(std::move(cache)), weights_(std::move(weights)) {}

  std::complex<double> evaluate(std::span<const double> values, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    const std::lock_guard<std::mutex> lock(cache_->mutex);
    const TwoLayerCalibration::Cache::Entry* entry = nullptr;
    try {
      entry = &update(values, omega, gradient != nullptr ? wanted : std::span<const std::size_t>());
    } catch (const std::invalid_argument&) {
      // Values outside the physical range (a compliance that is not positive definite, a loss
      // factor the causal band cannot carry): no response, and the fit steps back.
      const double nan = std::numeric_limits<double>::quiet_NaN();
      if (gradient)
        for (std::size_t k : wanted) gradient[k] = nan;
      return nan;
    }
    const auto dot = [&](const std::vector<cd>& v) {
      cd sum = 0.0;
      for (std::size_t j = 0; j < v.size(); ++j) sum += weights_[j] * v[j];
      return sum;
    };
    if (gradient)
      for (std::size_t k : wanted) gradient[k] = dot(entry->dg.at(k));
    return dot(entry->g);
  }

 private:
  // The cache's entry for (ω, values) with the derivatives `wanted`, computed as needed.
  const TwoLayerCalibration::Cache::Entry& update(std::span<const double> values, double omega,
                                                  std::span<const std::size_t> wanted) const {
    TwoLayerCalibration::Cache& cache = *cache_;
    TwoLayerCalibration::Cache::Key key{omega, std::vector<double>(values.begin(), values.end())};
    auto found = cache.entries.find(key);
    if (found == cache.entries.end()) {
      if (cache.entries.size() >= TwoLayerCalibration::Cache::capacity) {
        cache.entries.erase(cache.order.front());
        cache.order.pop_front();
      }
      TwoLayerCalibration::Cache::Entry entry;
      node_values(*nodes_, stack_of(values), omega, entry.g, nullptr, nullptr);
      found = cache.entries.emplace(key, std::move(entry)).first;
      cache.order.push_back(std::move(key));
    }
    TwoLayerCalibration::Cache::Entry& entry = found->second;
    std::vector<std::size_t> missing;
    for (std::size_t k : wanted)
      if (!entry.dg.contains(k)) missing.push_back(k);
    if (missing.empty()) return entry;
    // The layers at the values themselves, reused by the steps that leave them unchanged.
    std::vector<cd> g;
    std::vector<LayerStiffness> belt, tread;
    node_values(*nodes_, stack_of(values), omega, g, &belt, &tread);
    const Nodes& nodes = *nodes_;
    std::vector<double> shifted(values.begin(), values.end());
    std::vector<cd> up(nodes.kx.size()), down(nodes.kx.size());
    for (std::size_t k : missing) {
      const double h = relative_step * values[k];
      const Part part = part_of(k);
      for (const double sign : {1.0, -1.0}) {
        shifted[k] = values[k] + sign * h;
        const TwoLayerStack stack = stack_of(shifted);
        std::vector<cd>& out = sign > 0.0 ? up : down;
        for (std::size_t j = 0; j < nodes.kx.size(); ++j) {
          const double kx = nodes.kx[j], ky = nodes.ky[j];
          const LayerStiffness b = part == Part::belt ? stack.belt_stiffness(kx, ky, omega) : belt[j];
          const LayerStiffness t = part == Part::tread ? stack.tread_stiffness(kx, ky, omega) : tread[j];
          out[j] = stack.surface_compliance(b, t, kx, ky, omega)(2, 2);
        }
      }
      shifted[k] = values[k];
      std::vector<cd>& d = entry.dg[k];
      d.resize(up.size());
      for (std::size_t j = 0; j < up.size(); ++j) d[j] = (up[j] - down[j]) / (2.0 * h);
    }
    return entry;
  }

  using Nodes = TwoLayerCalibration::Nodes;
  // The parameters as a stack (std::invalid_argument when they are not physical).
  TwoLayerStack stack_of(std::span<const double> values) const { return make_two_layer_stack(apply_values(tyre_, values)); }

  TwoLayerParameters tyre_;
  std::shared_ptr<const Nodes> nodes_;
  std::shared_ptr<TwoLayerCalibration::Cache> cache_;
  std::vector<double> weights_;  // per node: α = Σ weights·Ĝ_zz(node)
};

// The lowest resonance (Hz) of the mode (k_x, k_y), estimated from below as the belt
// laminate's: bending and transverse shear in series (the belt's shear modulus is that of the
// rubber between the cords, so it shears as well as bends at short wavelengths), plus tension
// and foundation, on the mass of belt and tread; the tread's stiffness is left out.
double estimated_resonance_hz(const TwoLayerParameters& p, const OrthotropicStiffness& c, double kx, double ky) {
  const double h = p.belt_thickness;
  const double bending = h * h * h / 12.0;
  // Plane-stress reduced stiffnesses (σ_zz = 0).
  const double q11 = c.c11 - c.c13 * c.c13 / c.c33;
  const double q22 = c.c22 - c.c23 * c.c23 / c.c33;
  const double q12 = c.c12 - c.c13 * c.c23 / c.c33;
  const double kx2 = kx * kx, ky2 = ky * ky;
  double belt = 0.0;
  if (kx2 + ky2 > 0.0) {
    const double bend = bending * (q11 * kx2 * kx2 + 2.0 * (q12 + 2.0 * c.c66) * kx2 * ky2 + q22 * ky2 * ky2);
    const double shear = h * (c.c55 * kx2 + c.c44 * ky2);
    belt = bend * shear / (bend + shear);
  }
  const double stiffness = belt + p.tension_x * kx2 + p.tension_y * ky2 + p.foundation_stiffness;
  const double mass = p.belt_density * p.belt_thickness + p.tread_density * p.tread_thickness;
  return std::sqrt(stiffness / mass) / (2.0 * pi);
}

}  // namespace

TwoLayerCalibration::TwoLayerCalibration(const TwoLayerParameters& parameters, double band_top_hz,
                                         double tail_factor)
    : tyre_(parameters),
      band_top_hz_(std::isfinite(band_top_hz) ? std::min(band_top_hz, largest_band_top_hz) : default_band_top_hz),
      cache_(std::make_shared<Cache>()) {
  if (!(band_top_hz_ > 0.0)) throw std::invalid_argument("two_layer calibration: the band's top must be > 0 Hz");
  if (!(tail_factor >= 1.0 && std::isfinite(tail_factor)))
    throw std::invalid_argument("two_layer calibration: the tail factor must be >= 1");
  const TwoLayerTyre tyre(tyre_);  // validates the parameters
  const double largest_eta = 0.95 * CausalModulus::largest_loss_factor();
  const auto& b = tyre_.belt;
  parameters_ = {
      log_parameter("belt_youngs_modulus_x", "Pa", b.youngs_x),
      log_parameter("belt_youngs_modulus_y", "Pa", b.youngs_y),
      log_parameter("belt_youngs_modulus_z", "Pa", b.youngs_z),
      log_parameter("belt_shear_modulus_xy", "Pa", b.shear_xy),
      log_parameter("belt_shear_modulus_xz", "Pa", b.shear_xz),
      log_parameter("belt_shear_modulus_yz", "Pa", b.shear_yz),
      log_parameter("belt_density", "kg/m^3", tyre_.belt_density),
      log_parameter("belt_loss_factor", "1", tyre_.belt_loss_factor, 0.0, largest_eta),
      log_parameter("tread_youngs_modulus", "Pa", tyre_.tread_youngs_modulus),
      log_parameter("tread_density", "kg/m^3", tyre_.tread_density),
      log_parameter("tread_loss_factor", "1", tyre_.tread_loss_factor, 0.0, largest_eta),
      log_parameter("tension_x", "N/m", tyre_.tension_x),
      log_parameter("tension_y", "N/m", tyre_.tension_y),
      log_parameter("foundation_stiffness", "N/m^3", tyre_.foundation_stiffness),
      log_parameter("foundation_loss_factor", "1", tyre_.foundation_loss_factor, 0.0, largest_eta),
  };

  // Kept: the modes whose estimated resonance lies below twice the band's top (rows of
  // increasing n; the estimate grows with k_x and k_y, so each row is m = 0 … its last).
  auto nodes = std::make_shared<Nodes>();
  const OrthotropicStiffness belt = orthotropic_stiffness(tyre_.belt);
  const double limit = 2.0 * band_top_hz_;
  const int first = tyre.first_lateral_order();
  lowest_resonance_hz_ = estimated_resonance_hz(tyre_, belt, 0.0, tyre.wavenumber_y(first));
  for (int n = first;; ++n) {
    int last = -1;
    while (estimated_resonance_hz(tyre_, belt, tyre.wavenumber_x(last + 1), tyre.wavenumber_y(n)) < limit) ++last;
    // The lowest mode is always kept: the tail's interpolation in ln ρ needs k > 0.
    if (n == first) last = std::max(last, 0);
    if (last < 0) break;
    nodes->last_kept_m.push_back(last);
    nodes->row_offset.push_back(nodes->kx.size());
    for (int m = 0; m <= last; ++m) {
      nodes->kx.push_back(tyre.wavenumber_x(m));
      nodes->ky.push_back(tyre.wavenumber_y(n));
    }
  }
  nodes->kept = nodes->kx.size();
  // The tail: the lattice beyond, to where the cells' sinc² factors are below 1/(8π)².
  const double length = tyre.circumference();
  nodes->lattice_m = static_cast<int>(std::ceil(tail_factor * length / (2.0 * transducer_size)));
  nodes->lattice_n = static_cast<int>(std::ceil(tail_factor * tyre_.width / transducer_size));
  // k_edge(θ) by bisection along each direction (the estimate grows along every ray).
  const double floor = 0.5 * tyre.wavenumber_x(1);
  constexpr int directions = 65;
  for (int t = 0; t < directions; ++t) {
    const double u = -1.0 + 2.0 * t / (directions - 1);
    const double cx = std::sqrt(0.5 * (1.0 + u)), cy = std::sqrt(0.5 * (1.0 - u));
    const auto above = [&](double k) { return estimated_resonance_hz(tyre_, belt, k * cx, k * cy) >= limit; };
    double lo = 0.0, hi = floor;
    while (!above(hi)) {
      lo = hi;
      hi *= 2.0;
    }
    for (int i = 0; i < 60; ++i) (above(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
    nodes->edge.push_back(std::max(hi, floor));
  }
  // The range of ln ρ over the tail's lattice.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (int n = first; n <= nodes->lattice_n; ++n)
    for (int m = 0; m <= nodes->lattice_m; ++m) {
      if (nodes->is_kept(m, n - first)) continue;
      const double kx = tyre.wavenumber_x(m), ky = tyre.wavenumber_y(n);
      const double k2 = kx * kx + ky * ky;
      const double log_rho = 0.5 * std::log(k2) - std::log(nodes->edge_at((kx * kx - ky * ky) / k2));
      low = std::min(low, log_rho);
      high = std::max(high, log_rho);
    }
  nodes->log_rho_low = low;
  nodes->log_rho_high = std::max(high, low + 1e-6);
  for (int i = 0; i < Nodes::radial_nodes; ++i) {
    const double s = std::cos(pi * i / (Nodes::radial_nodes - 1));
    const double log_rho = nodes->log_rho_low + 0.5 * (s + 1.0) * (nodes->log_rho_high - nodes->log_rho_low);
    for (int a = 0; a < Nodes::angle_nodes; ++a) {
      const double u = std::cos(pi * a / (Nodes::angle_nodes - 1));  // cos 2θ
      const double k = std::exp(log_rho) * nodes->edge_at(u);
      nodes->kx.push_back(k * std::sqrt(std::max(0.0, 0.5 * (1.0 + u))));
      nodes->ky.push_back(k * std::sqrt(std::max(0.0, 0.5 * (1.0 - u))));
    }
  }
  nodes_ = std::move(nodes);
}

std::vector<std::string> TwoLayerCalibration::default_free_parameters() const {
  std::vector<std::string> names;
  for (const std::size_t k : {belt_youngs_modulus_x, belt_youngs_modulus_y, tension_x, tension_y,
                              foundation_stiffness, tread_youngs_modulus, belt_loss_factor, tread_loss_factor,
                              foundation_loss_factor})
    if (parameters_[k].value > 0.0) names.push_back(parameters_[k].name);
  return names;
}

TwoLayerParameters TwoLayerCalibration::with_values(std::span<const double> v) const {
  return apply_values(tyre_, v);
}

std::size_t TwoLayerCalibration::kept_modes() const { return nodes_->kept; }

std::size_t TwoLayerCalibration::tail_nodes() const { return nodes_->kx.size() - nodes_->kept; }

int TwoLayerCalibration::last_circumferential_order() const { return nodes_->lattice_m; }

int TwoLayerCalibration::last_lateral_order() const { return nodes_->lattice_n; }

std::unique_ptr<ReceptanceFunction> TwoLayerCalibration::receptance(const FrfPoints& points) const {
  const double half = 0.5 * transducer_size;
  for (const auto& [p, what] : {std::pair{points.response, "response"}, {points.excitation, "excitation"}}) {
    if (!(p.y >= half - 1e-12 && p.y <= tyre_.width - half + 1e-12) || !std::isfinite(p.x)) {
      std::ostringstream problem;
      problem << "the " << what << " position y = " << p.y << " m: the " << transducer_size * 1e3
              << " mm transducer cell centred there must lie on the belt, y from " << half << " to "
              << tyre_.width - half << " m";
      throw InputError("", "", problem.str());
    }
  }
  const TwoLayerTyre tyre(tyre_);
  const Nodes& nodes = *nodes_;
  const double length = tyre.circumference();
  // Reduce to one turn first, so that cos(k_m·Δx) keeps its digits.
  const double dx = std::remainder(points.response.x - points.excitation.x, length);
  const double ell = transducer_size;
  std::vector<double> circumferential(static_cast<std::size_t>(nodes.lattice_m) + 1);
  for (int m = 0; m <= nodes.lattice_m; ++m) {
    const double k = tyre.wavenumber_x(m);
    const double c = sinc(0.5 * k * ell);
    circumferential[static_cast<std::size_t>(m)] = (m == 0 ? 1.0 : 2.0) * std::cos(k * dx) * c * c;
  }
  std::vector<double> weights(nodes.kx.size(), 0.0);
  // The tail's node weights before the factor k_node (the nodes interpolate k·Ĝ).
  constexpr int S = Nodes::radial_nodes, A = Nodes::angle_nodes;
  double* tail = weights.data() + nodes.kept;
  double bs[S], ba[A];
  const LobattoBasis radial_basis(S), angle_basis(A);
  const int first = tyre.first_lateral_order();
  for (int n = first; n <= nodes.lattice_n; ++n) {
    const double ky = tyre.wavenumber_y(n);
    const double cn = sinc(0.5 * ky * ell);
    const double lateral = tyre.lateral_shape(SurfaceDirection::z, n, points.response.y) *
                           tyre.lateral_shape(SurfaceDirection::z, n, points.excitation.y) * cn * cn /
                           tyre.modal_norm(n);
    if (lateral == 0.0) continue;  // a node line of the row: it adds nothing
    const int row = n - first;
    for (int m = 0; m <= nodes.lattice_m; ++m) {
      const double w = lateral * circumferential[static_cast<std::size_t>(m)];
      if (nodes.is_kept(m, row)) {
        weights[nodes.row_offset[static_cast<std::size_t>(row)] + static_cast<std::size_t>(m)] += w;
        continue;
      }
      const double kx = tyre.wavenumber_x(m);
      const double k2 = kx * kx + ky * ky;
      const double k = std::sqrt(k2);
      const double u = (kx * kx - ky * ky) / k2;
      radial_basis(nodes.coordinate(k, u), bs);
      angle_basis(u, ba);
      const double wk = w / k;
      for (int i = 0; i < S; ++i) {
        const double wi = wk * bs[i];
        for (int a = 0; a < A; ++a) tail[i * A + a] += wi * ba[a];
      }
    }
  }
  for (std::size_t j = nodes.kept; j < weights.size(); ++j) weights[j] *= std::hypot(nodes.kx[j], nodes.ky[j]);
  return std::make_unique<TwoLayerReceptance>(tyre_, nodes_, cache_, std::move(weights));
}

}  // namespace rollnoise
