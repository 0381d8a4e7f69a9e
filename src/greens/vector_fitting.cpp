#include "greens/vector_fitting.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace rollnoise {

namespace {

using cd = std::complex<double>;
constexpr cd kI(0.0, 1.0);

// The poles in the real formulation (GS99 appendix): real poles, and one pole (Im > 0) of each
// conjugate pair. The real basis is 1/(s − a) for a real pole and, for a pair a, ā,
//   φ' = 1/(s − a) + 1/(s − ā),  φ'' = i/(s − a) − i/(s − ā),
// so that c'φ' + c''φ'' = (c' + ic'')/(s − a) + (c' − ic'')/(s − ā): real coefficients give a real h.
struct PoleSet {
  std::vector<double> real;
  std::vector<cd> upper;
  int basis_size() const { return static_cast<int>(real.size() + 2 * upper.size()); }
};

// The samples, with what every step needs of them.
struct Samples {
  std::span<const double> omega;
  std::span<const cd> f;
  std::vector<double> weight;        // w_k of the least squares
  std::vector<double> error_scale;   // 1/|α_k| (1/RMS|α| where α_k = 0): the error measure
  bool has_static = false;           // ω_0 = 0: its imaginary row is left out (see put_column)
  int size() const { return static_cast<int>(omega.size()); }
  // Real equations: the real and imaginary parts of each sample.
  int rows() const { return 2 * size() - (has_static ? 1 : 0); }
};

// 1/z by conj(z)/|z|²: no overflow concerns here (|z| ≥ |Re a| > 0 and moderate), and much
// faster than the general complex division.
cd reciprocal(cd z) { return std::conj(z) / std::norm(z); }

// Φ (K × N, complex): the real basis at s_k = iω_k.
Eigen::MatrixXcd basis(const Samples& x, const PoleSet& poles) {
  const int n = poles.basis_size();
  Eigen::MatrixXcd phi(x.size(), n);
  for (int k = 0; k < x.size(); ++k) {
    const cd s = kI * x.omega[static_cast<std::size_t>(k)];
    int j = 0;
    for (double a : poles.real) phi(k, j++) = reciprocal(s - a);
    for (cd a : poles.upper) {
      const cd u = reciprocal(s - a), v = reciprocal(s - std::conj(a));
      phi(k, j++) = u + v;
      phi(k, j++) = kI * (u - v);
    }
  }
  return phi;
}

// Writes the real and imaginary parts of the complex column `values` (one per sample) into
// column `col` of the real system. The static sample's imaginary part is left out: the basis is
// real at s = 0, and a real h has a real static value.
template <class Values>
void put_column(const Samples& x, Eigen::MatrixXd& m, Eigen::Index col, Values&& values) {
  Eigen::Index row = 0;
  for (int k = 0; k < x.size(); ++k) {
    const cd v = values(k);
    m(row++, col) = v.real();
    if (!(x.has_static && k == 0)) m(row++, col) = v.imag();
  }
}

// Least squares min ‖Mx − b‖ with the columns scaled to unit norm first: the basis columns span
// orders of magnitude (1/(iω − a) over 1 Hz…50 kHz), and a pivoting QR on the scaled system
// keeps the small ones (as Gustavsen's vectfit does: columns scaled to unit length). A zero
// column gets a zero unknown.
Eigen::VectorXd solve_scaled(Eigen::MatrixXd& m, const Eigen::VectorXd& b) {
  Eigen::VectorXd scale(m.cols());
  for (Eigen::Index j = 0; j < m.cols(); ++j) {
    const double norm = m.col(j).norm();
    scale(j) = norm > 0.0 ? 1.0 / norm : 0.0;
    m.col(j) *= scale(j);
  }
  const Eigen::VectorXd x = m.colPivHouseholderQr().solve(b);
  return x.cwiseProduct(scale);
}

// GS99's pole flipping: an unstable pole is replaced by its mirror image; one on the
// imaginary axis (which the reflection leaves in place) is pushed into the left half-plane by a
// small fraction of its size (of the band's top for a pole at 0).
cd stabilise(cd p, double omega_high) {
  if (p.real() > 0.0) p = {-p.real(), p.imag()};
  if (p.real() == 0.0) p = {-1e-6 * (std::abs(p) > 0.0 ? std::abs(p) : omega_high), p.imag()};
  return p;
}

// The linear system of GS99's pole identification for the unknowns (c, d, c̃, d̃), weighted: at every sample
//   w_k (Σ c_j φ_j + d − α_k (Σ c̃_j φ_j + d̃)) = 0,
// relaxed (G06) with the extra row Re Σ_k σ(s_k) = K, weighted like vectfit3 so that it
// counts as much as an average equation (scale ‖w·α‖/K). Not relaxed, d̃ = 1 is fixed instead
// (GS99) and the system has no d̃ column, with right-hand side w·α.
struct LinearSystem {
  Eigen::MatrixXd m;
  Eigen::VectorXd b;
};

LinearSystem relocation_system(const Samples& x, const Eigen::MatrixXcd& phi, bool fit_direct, bool relaxed) {
  const int n = static_cast<int>(phi.cols());
  const int nd = fit_direct ? 1 : 0;
  const int cols = 2 * n + nd + (relaxed ? 1 : 0);
  const int rows = x.rows();
  const auto w = [&](int k) { return x.weight[static_cast<std::size_t>(k)]; };
  const auto f = [&](int k) { return x.f[static_cast<std::size_t>(k)]; };
  const int equations = rows + (relaxed ? 1 : 0);
  LinearSystem sys{Eigen::MatrixXd::Zero(equations, cols), Eigen::VectorXd::Zero(equations)};
  for (int j = 0; j < n; ++j) {
    put_column(x, sys.m, j, [&](int k) { return w(k) * phi(k, j); });
    put_column(x, sys.m, n + nd + j, [&](int k) { return -w(k) * f(k) * phi(k, j); });
  }
  if (fit_direct) put_column(x, sys.m, n, [&](int k) { return cd(w(k)); });
  if (relaxed) {
    double wf = 0.0;
    for (int k = 0; k < x.size(); ++k) wf += std::norm(w(k) * f(k));
    const double scale = std::sqrt(wf) / x.size();
    put_column(x, sys.m, cols - 1, [&](int k) { return -w(k) * f(k); });
    for (int j = 0; j < n; ++j) sys.m(rows, n + nd + j) = scale * phi.col(j).real().sum();
    sys.m(rows, cols - 1) = scale * x.size();
    sys.b(rows) = scale * x.size();
  } else {
    Eigen::MatrixXd rhs(rows, 1);
    put_column(x, rhs, 0, [&](int k) { return w(k) * f(k); });
    sys.b = rhs.col(0);
  }
  return sys;
}

// GS99 step 1 with G06's relaxation: the zeros of σ, i.e. the new poles. Returns false when the
// system is degenerate (non-finite result), leaving `poles` unchanged.
bool relocate(const Samples& x, PoleSet& poles, bool fit_direct, double omega_high) {
  const int n = poles.basis_size();
  const int nd = fit_direct ? 1 : 0;
  const Eigen::MatrixXcd phi = basis(x, poles);
  LinearSystem sys = relocation_system(x, phi, fit_direct, true);
  const Eigen::VectorXd sol = solve_scaled(sys.m, sys.b);
  Eigen::VectorXd c_tilde = sol.segment(n + nd, n);
  double d_tilde = sol(2 * n + nd);
  // G06: a vanishing d̃ makes A − bc̃ᵀ/d̃ meaningless; then fall back to GS99's d̃ = 1
  // (any fixed nonzero d̃ gives the same zeros).
  if (!(std::abs(d_tilde) > 1e-8)) {
    sys = relocation_system(x, phi, fit_direct, false);
    c_tilde = solve_scaled(sys.m, sys.b).segment(n + nd, n);
    d_tilde = 1.0;
  }
  if (!c_tilde.allFinite() || !std::isfinite(d_tilde)) return false;

  // GS99's appendix: σ's zeros are the eigenvalues of A − b c̃ᵀ/d̃, with A the real state matrix
  // of the poles (a 2×2 block [Re a, Im a; −Im a, Re a] per pair) and b = 1 per real pole,
  // (2, 0) per pair.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd bvec = Eigen::VectorXd::Zero(n);
  int j = 0;
  for (double p : poles.real) {
    a(j, j) = p;
    bvec(j++) = 1.0;
  }
  for (cd p : poles.upper) {
    a(j, j) = p.real();
    a(j, j + 1) = p.imag();
    a(j + 1, j) = -p.imag();
    a(j + 1, j + 1) = p.real();
    bvec(j) = 2.0;
    j += 2;
  }
  const Eigen::MatrixXd h = a - bvec * c_tilde.transpose() / d_tilde;
  if (!h.allFinite()) return false;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(h, false);
  if (eig.info() != Eigen::Success) return false;

  // The eigenvalues of a real matrix: real ones, and pairs that Eigen returns as exact
  // conjugates. Keep one of each pair (Im > 0), stabilised.
  PoleSet next;
  for (Eigen::Index i = 0; i < n; ++i) {
    cd p = eig.eigenvalues()(i);
    if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) return false;
    p = stabilise(p, omega_high);
    if (p.imag() == 0.0) {
      next.real.push_back(p.real());
    } else if (p.imag() > 0.0) {
      // A pair this close to the real axis would be taken for two real poles by validate();
      // keep it a pair, a little further from the axis (the next relocation moves it anyway).
      next.upper.push_back({p.real(), std::max(p.imag(), 1e-7 * std::abs(p))});
    }
  }
  if (next.basis_size() != n) return false;
  poles = std::move(next);
  return true;
}

// A fit of one order, with what the driver needs to raise the order.
struct OrderFit {
  VectorFittingResult result;
  PoleSet poles;
  std::vector<double> errors;  // e_k, the relative error at each sample
};

// GS99's residue identification: c and d with the poles fixed, then the errors on the samples.
OrderFit identify_residues(const Samples& x, const PoleSet& poles, const VectorFittingOptions& options) {
  const int n = poles.basis_size();
  const int nd = options.fit_direct ? 1 : 0;
  const Eigen::MatrixXcd phi = basis(x, poles);
  const auto w = [&](int k) { return x.weight[static_cast<std::size_t>(k)]; };
  Eigen::MatrixXd m(x.rows(), n + nd);
  for (int j = 0; j < n; ++j) put_column(x, m, j, [&](int k) { return w(k) * phi(k, j); });
  if (nd) put_column(x, m, n, [&](int k) { return cd(w(k)); });
  Eigen::MatrixXd rhs(x.rows(), 1);
  put_column(x, rhs, 0, [&](int k) { return w(k) * x.f[static_cast<std::size_t>(k)]; });
  const Eigen::VectorXd c = solve_scaled(m, rhs.col(0));

  OrderFit order{{}, poles, std::vector<double>(static_cast<std::size_t>(x.size()))};
  VectorFittingResult& out = order.result;
  const double d = nd ? c(n) : 0.0;
  const Eigen::VectorXcd fit = (phi * c.head(n).cast<cd>()).array() + d;
  double sum = 0.0, worst = 0.0;
  for (int k = 0; k < x.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const double e = std::abs(fit(k) - x.f[i]) * x.error_scale[i];
    order.errors[i] = e;
    sum += e * e;
    worst = std::max(worst, e);
  }
  out.rms_error = std::sqrt(sum / x.size());
  out.max_error = worst;
  if (!std::isfinite(out.rms_error)) out.rms_error = out.max_error = std::numeric_limits<double>::infinity();
  out.converged = out.rms_error <= options.target_rms_error && out.max_error <= options.target_max_error;

  // Back to poles and complex residues: pairs (a, ā) with ρ = c' ± ic'', then the real poles.
  PoleResidueResponse& r = out.response;
  r.direct = d;
  int j = static_cast<int>(poles.real.size());
  for (cd a : poles.upper) {
    const cd rho(c(j), c(j + 1));
    r.poles.push_back(a);
    r.residues.push_back(rho);
    r.poles.push_back(std::conj(a));
    r.residues.push_back(std::conj(rho));
    j += 2;
  }
  for (std::size_t i = 0; i < poles.real.size(); ++i) {
    r.poles.emplace_back(poles.real[i], 0.0);
    r.residues.emplace_back(c(static_cast<Eigen::Index>(i)), 0.0);
  }
  return order;
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("vector fitting: " + what); }

void require(bool ok, const char* what) {
  if (!ok) fail(what);
}

Samples prepare(std::span<const double> omega, std::span<const cd> response, const VectorFittingOptions& options) {
  // (The messages are built only on failure: this runs once per fit, of which there are many.)
  if (omega.size() != response.size())
    fail("omega and response differ in size (" + std::to_string(omega.size()) + " and " +
         std::to_string(response.size()) + ")");
  if (omega.size() < 3) fail("need at least 3 samples (got " + std::to_string(omega.size()) + ")");
  for (std::size_t k = 0; k < omega.size(); ++k) {
    if (!std::isfinite(omega[k])) fail("omega[" + std::to_string(k) + "] is not finite");
    if (omega[k] < 0.0) fail("omega[" + std::to_string(k) + "] = " + std::to_string(omega[k]) + " is negative");
    if (k > 0 && !(omega[k] > omega[k - 1]))
      fail("omega must be strictly increasing (omega[" + std::to_string(k) + "] = " + std::to_string(omega[k]) +
           " follows " + std::to_string(omega[k - 1]) + ")");
    if (!std::isfinite(response[k].real()) || !std::isfinite(response[k].imag()))
      fail("response[" + std::to_string(k) + "] is not finite");
  }
  require(options.starting_pole_pairs >= 0 && options.real_poles >= 0,
          "starting_pole_pairs and real_poles must be >= 0");
  require(options.starting_pole_pairs + options.real_poles >= 1, "need at least one starting pole");
  require(options.maximum_pole_pairs >= options.starting_pole_pairs,
          "maximum_pole_pairs must be >= starting_pole_pairs");
  require(options.iterations >= 1, "iterations must be >= 1");
  require(options.target_rms_error > 0.0 && options.target_max_error > 0.0, "the target errors must be > 0");

  Samples x{omega, response, {}, {}, omega[0] == 0.0};
  double mean_square = 0.0;
  for (cd v : response) mean_square += std::norm(v);
  const double rms = std::sqrt(mean_square / static_cast<double>(response.size()));
  require(rms > 0.0, "the response is identically zero");
  x.weight.resize(omega.size());
  x.error_scale.resize(omega.size());
  for (std::size_t k = 0; k < omega.size(); ++k) {
    const double magnitude = std::abs(response[k]);
    if (options.weighting == FitWeighting::relative) {
      if (!(magnitude > 0.0))
        fail("relative weighting needs a nonzero response (response[" + std::to_string(k) +
             "] = 0); use FitWeighting::uniform");
      x.weight[k] = 1.0 / magnitude;
    } else {
      x.weight[k] = 1.0;
    }
    x.error_scale[k] = 1.0 / (magnitude > 0.0 ? magnitude : rms);
  }
  return x;
}

PoleSet split(std::span<const cd> poles) {
  PoleSet set;
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const cd p = poles[i];
    if (!(std::isfinite(p.real()) && std::isfinite(p.imag()) && p.real() < 0.0))
      fail("initial pole " + std::to_string(i) + " is not finite and stable (Re p < 0)");
    if (p.imag() == 0.0) {
      set.real.push_back(p.real());
    } else {
      if (!(p.imag() > 0.0 && i + 1 < poles.size() && poles[i + 1] == std::conj(p)))
        fail("initial pole " + std::to_string(i) + ": complex poles must come as p, conj(p) with Im p > 0");
      set.upper.push_back(p);
      ++i;
    }
  }
  require(!poles.empty(), "need at least one initial pole");
  return set;
}

// The number of unknowns of the relocation must not exceed its equations.
void require_enough_samples(const Samples& x, int basis_size, bool fit_direct) {
  const int unknowns = 2 * basis_size + (fit_direct ? 1 : 0) + 1;
  if (unknowns > x.rows() + 1)
    fail(std::to_string(basis_size) + " poles need at least " + std::to_string(unknowns - 1) +
         " real equations; the " + std::to_string(x.size()) + " samples give " + std::to_string(x.rows()));
}

// Up to options.iterations relocations from `poles`, each followed by the residues; the best
// iteration (smallest RMS error) is kept, and the loop stops as soon as the targets are met or
// the error stops improving.
OrderFit fit_order(const Samples& x, PoleSet poles, const VectorFittingOptions& options) {
  const double omega_high = x.omega.back();
  OrderFit best;
  bool have = false;
  for (int it = 0; it < options.iterations; ++it) {
    if (!relocate(x, poles, options.fit_direct, omega_high)) break;
    OrderFit r = identify_residues(x, poles, options);
    const bool done = r.result.converged;
    // Stagnation: once the poles have settled (an iteration that gains less than 10 % on the best
    // so far, after the first), further relocations at this order only cost time.
    const bool settled = have && !(r.result.rms_error < 0.9 * best.result.rms_error);
    if (!have || r.result.rms_error < best.result.rms_error) {
      best = std::move(r);
      have = true;
    }
    if (done || settled) break;
  }
  if (!have) best = identify_residues(x, poles, options);  // no relocation succeeded
  return best;
}

}  // namespace

std::vector<cd> starting_poles(double omega_low, double omega_high, int pairs, int real, StartingPoleSpacing spacing) {
  require(std::isfinite(omega_low) && std::isfinite(omega_high) && omega_low > 0.0 && omega_high >= omega_low,
          "starting poles need 0 < omega_low <= omega_high");
  require(pairs >= 0 && real >= 0, "the numbers of starting poles must be >= 0");
  const auto spread = [&](int count, int i) {
    if (count == 1) {
      return spacing == StartingPoleSpacing::logarithmic ? std::sqrt(omega_low * omega_high)
                                                         : 0.5 * (omega_low + omega_high);
    }
    const double t = static_cast<double>(i) / (count - 1);
    return spacing == StartingPoleSpacing::logarithmic ? omega_low * std::pow(omega_high / omega_low, t)
                                                       : omega_low + t * (omega_high - omega_low);
  };
  std::vector<cd> poles;
  // GS99: complex starting poles with a small real part, −β/100 ± iβ, over the band.
  for (int i = 0; i < pairs; ++i) {
    const double beta = spread(pairs, i);
    poles.emplace_back(-beta / 100.0, beta);
    poles.emplace_back(-beta / 100.0, -beta);
  }
  for (int i = 0; i < real; ++i) poles.emplace_back(-spread(real, i), 0.0);
  return poles;
}

VectorFittingResult vector_fit(std::span<const double> omega, std::span<const cd> response,
                               std::span<const cd> initial_poles, const VectorFittingOptions& options) {
  const Samples x = prepare(omega, response, options);
  const PoleSet poles = split(initial_poles);
  require_enough_samples(x, poles.basis_size(), options.fit_direct);
  return fit_order(x, poles, options).result;
}

namespace {

// The driver's loop, from the given poles.
VectorFittingResult raise_order(const Samples& x, PoleSet poles, const VectorFittingOptions& options) {
  const double low = x.has_static ? x.omega[1] : x.omega[0];
  const int nd = options.fit_direct ? 1 : 0;
  require_enough_samples(x, poles.basis_size(), options.fit_direct);
  // The cap counts poles, not pairs: the relocation may turn a pair into two real poles.
  const int most = 2 * options.maximum_pole_pairs + options.real_poles;
  OrderFit best;
  bool have = false;
  for (;;) {
    OrderFit r = fit_order(x, poles, options);
    if (r.result.converged) return std::move(r.result);
    if (!have || r.result.rms_error < best.result.rms_error) {
      best = r;
      have = true;
    }
    // The next order: this order's poles plus lightly damped pairs (GS99's −β/100 ± iβ) where
    // the error peaks, so that the relocation starts from a fit that is already close instead of
    // from scratch (the "adding" strategy of Grivet-Talocia & Bandinu, IEEE Trans. EMC 48(1)
    // 2006 104–120). A quarter more poles at a time (at least one pair) keeps the number of
    // orders tried small when many poles are needed.
    const int size = r.poles.basis_size();
    const int room = (x.rows() - nd - 2 * size) / 4;  // pairs the relocation's equations still carry
    const int add = std::min({std::max(1, size / 8), (most - size) / 2, room});
    if (add <= 0) break;
    std::vector<int> peaks;  // local maxima of the error, largest first
    const std::vector<double>& e = r.errors;
    for (int k = 0; k < x.size(); ++k) {
      const std::size_t i = static_cast<std::size_t>(k);
      if ((k == 0 || e[i] >= e[i - 1]) && (k + 1 == x.size() || e[i] >= e[i + 1])) peaks.push_back(k);
    }
    std::stable_sort(peaks.begin(), peaks.end(),
                     [&](int a, int b) { return e[static_cast<std::size_t>(a)] > e[static_cast<std::size_t>(b)]; });
    poles = std::move(r.poles);
    for (int i = 0; i < add; ++i) {
      // More new pairs than peaks (rare): the extra ones 1 % apart, never on top of each other.
      const std::size_t peak = static_cast<std::size_t>(i) % peaks.size();
      const double beta = std::max(x.omega[static_cast<std::size_t>(peaks[peak])], low) *
                          (1.0 + 0.01 * static_cast<double>(static_cast<std::size_t>(i) / peaks.size()));
      poles.upper.emplace_back(-beta / 100.0, beta);
    }
  }
  return std::move(best.result);
}

}  // namespace

VectorFittingResult fit_pole_residue(std::span<const double> omega, std::span<const cd> response,
                                     const VectorFittingOptions& options) {
  const Samples x = prepare(omega, response, options);
  const double low = x.has_static ? omega[1] : omega[0];
  return raise_order(
      x, split(starting_poles(low, omega.back(), options.starting_pole_pairs, options.real_poles, options.spacing)),
      options);
}


}  // namespace rollnoise
