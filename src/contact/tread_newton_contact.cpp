#include "contact/tread_newton_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact/block_pivoting_exchange.hpp"

namespace rollnoise {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// The stopping test, relative to ‖q‖∞: as the linear tread's LCP (pmatrix_lcp.cpp).
constexpr double kTolerance = 1e-13;
// Newton on one contact set takes a handful of iterations from the last step's compressions
// and a few dozen from a cold start; this many means it stalls, which is reported.
constexpr int kMaxIterations = 100;
// After this many Newton iterations on a set, a residual within kStallFactor of the tolerance
// that stops falling is accepted (solve_contact_set).
constexpr int kStallIterations = 8;
constexpr double kStallFactor = 16.0;
constexpr int kMaxCgIterations = 1000;
// The inexact Newton forcing term: (3) is solved to min(kForcing, ‖gap_S‖∞/‖q‖∞) of its right
// side, which keeps Newton's quadratic rate (Eisenstat & Walker's choice 2 with exponent 2).
constexpr double kForcing = 0.1;
// Points whose δ_p is set outside Newton (leaving the contact set, or joining it) correct the gap
// by A's column each, up to this many; more, and one product for the whole gap is cheaper. A
// column streams P values from memory; the dense product costs P columns, the window's FFT
// product about 6–10 (perf on plate_rough_80kmh's 2060 points: 0.08 and 0.013 samples each).
constexpr std::size_t kColumnUpdates = 32;
constexpr std::size_t kColumnUpdatesFft = 8;
// A point whose spring is this soft against its own structural compliance (dF/dδ·A_pp) carries
// no force in the linearisation: a point entering the contact at δ = 0 for n > 1 (dF/dδ = 0).
constexpr double kNegligibleSlope = 1e-14;
// A point's violation of its sign beyond this many times the residual of Newton on the contact
// set ends Newton on the set, and the points beyond it are exchanged (solve_contact_set). At 100
// (a violation no remaining iteration could undo) the texture laws on plate_rough_80kmh took
// three rounds and 4.0 Newton iterations a step: the patch's edge was released a row at a time
// over two rounds. At 1, 3.05 iterations a step, and the same forces to 6e-14.
constexpr double kEarlyExchange = 1.0;
// The line search gives up below this step (after about 40 halvings).
constexpr double kSmallestStep = 1e-12;

// For messages: lengths of 1e-15 m must not print as 0.000000.
std::string sci(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  return text;
}

}  // namespace

TreadNewtonContact::TreadNewtonContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                                       std::optional<ContactWindow> window, bool require_symmetric)
    : TreadNewtonContact(std::move(structural), std::make_shared<const PowerLawSprings>(std::move(stiffness), exponent),
                         window, require_symmetric) {}

TreadNewtonContact::TreadNewtonContact(Eigen::MatrixXd structural, std::shared_ptr<const PointSprings> springs,
                                       std::optional<ContactWindow> window, bool require_symmetric)
    : a_(std::move(structural)), springs_(std::move(springs)) {
  const Eigen::Index size = a_.rows();
  if (a_.cols() != size)
    throw std::invalid_argument("TreadNewtonContact: the structural compliance A must be square (got " +
                                std::to_string(a_.rows()) + " × " + std::to_string(a_.cols()) + ")");
  if (!a_.allFinite()) throw std::invalid_argument("TreadNewtonContact: the structural compliance A has non-finite entries");
  if (!springs_ || springs_->size() != size)
    throw std::invalid_argument("TreadNewtonContact: one spring per contact point expected (" + std::to_string(size) +
                                ")");
  if (size > 0) {
    // Conjugate gradients need A + C symmetric positive definite: A symmetric with a positive
    // diagonal is checked here, a non-positive curvature in the iterations is reported there.
    const double a_max = a_.cwiseAbs().maxCoeff();
    symmetric_ = (a_ - a_.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * a_max;
    if (require_symmetric && !symmetric_)
      throw std::invalid_argument("TreadNewtonContact: the structural compliance A is not symmetric");
    if (!(a_.diagonal().minCoeff() > 0.0))
      throw std::invalid_argument("TreadNewtonContact: the structural compliance A has a diagonal entry ≤ 0");
  }
  if (window) {
    if (Eigen::Index{window->window} * window->lateral != size)
      throw std::invalid_argument("TreadNewtonContact: the window's " + std::to_string(window->window) + " × " +
                                  std::to_string(window->lateral) + " points differ from A's size " +
                                  std::to_string(size));
    product_ = std::make_unique<WindowConvolution>(a_, window->window, window->lateral);
  }
  a_diagonal_ = a_.diagonal();
  delta_ = force_ = slope_ = gap_ = Eigen::VectorXd::Zero(size);
  compliance_ = mask_ = inverse_diagonal_ = x_ = ax_ = r_ = z_ = p_ = ap_ = mp_ = shifted_ = delta_;
  step_ = coordinate_ = previous_ = shadow_ = s_ = hat_s_ = at_ = t_ = delta_;
  active_.assign(static_cast<std::size_t>(size), 0);
  in_contact_.assign(static_cast<std::size_t>(size), 0);
  moved_.reserve(static_cast<std::size_t>(size));
}

TreadNewtonContact::~TreadNewtonContact() = default;

void TreadNewtonContact::multiply(const Eigen::VectorXd& z, Eigen::VectorXd& out) {
  if (product_) product_->apply(z, out);
  else out.noalias() = a_ * z;
}

void TreadNewtonContact::evaluate_gap(const Eigen::VectorXd& q) {
  multiply(force_, gap_);
  gap_ += q + delta_;
}

double TreadNewtonContact::merit(const Eigen::VectorXd& q) const {
  if (!symmetric_) return set_residual();
  // E = ½FᵀAF + qᵀF + Σ ∫₀^F δ with A·F = gap − q − δ and ∫₀^F δ = F·δ − ∫₀^δ F: no product
  // beyond the gap's.
  double complementary = 0.0;
  for (Eigen::Index p = 0; p < q.size(); ++p)
    if (force_(p) != 0.0) complementary += force_(p) * delta_(p) - springs_->stored_energy(p, delta_(p));
  return 0.5 * force_.dot(gap_ + q - delta_) + complementary;
}

double TreadNewtonContact::merit_noise(const Eigen::VectorXd& q) const {
  // The round-off of merit(): eps times its terms' magnitudes, with margin.
  if (!symmetric_) {
    double largest = 0.0;
    for (Eigen::Index p = 0; p < q.size(); ++p)
      largest = std::max(largest, std::abs(gap_(p)) + std::abs(q(p)) + std::abs(delta_(p)));
    return 64.0 * kEps * largest;
  }
  double sum = 0.0;
  for (Eigen::Index p = 0; p < q.size(); ++p)
    sum += std::abs(force_(p)) * (std::abs(gap_(p)) + std::abs(q(p)) + std::abs(delta_(p)));
  return 64.0 * kEps * sum;
}

double TreadNewtonContact::set_residual() const {
  double residual = 0.0;
  for (Eigen::Index p = 0; p < gap_.size(); ++p)
    if (active_[static_cast<std::size_t>(p)]) residual = std::max(residual, std::abs(gap_(p)));
  return residual;
}

double TreadNewtonContact::merit_before_step(const Eigen::VectorXd& q) {
  // Back to the compressions before the step (previous_ on the contact set), then the merit.
  for (Eigen::Index p = 0; p < q.size(); ++p) {
    if (!active_[static_cast<std::size_t>(p)]) continue;
    delta_(p) = previous_(p);
    evaluate_spring(p);
  }
  evaluate_gap(q);
  return merit(q);
}

std::size_t TreadNewtonContact::column_updates() const noexcept { return product_ ? kColumnUpdatesFft : kColumnUpdates; }

void TreadNewtonContact::release(Eigen::Index p) {
  gap_.noalias() -= a_.col(p) * force_(p);
  gap_(p) -= delta_(p);
  delta_(p) = force_(p) = slope_(p) = 0.0;
}

void TreadNewtonContact::newton_system(double tolerance) {
  const Eigen::Index size = a_.rows();
  // (3) on the contact points that carry force in the linearisation; Jacobi-preconditioned.
  for (Eigen::Index p = 0; p < size; ++p) {
    const bool solved = active_[static_cast<std::size_t>(p)] && slope_(p) * a_diagonal_(p) > kNegligibleSlope;
    mask_(p) = solved ? 1.0 : 0.0;
    compliance_(p) = solved ? 1.0 / slope_(p) : 0.0;
    inverse_diagonal_(p) = solved ? 1.0 / (a_diagonal_(p) + compliance_(p)) : 0.0;
    r_(p) = solved ? -gap_(p) : 0.0;
  }
  x_.setZero();
  ax_.setZero();
  if (r_.cwiseAbs().maxCoeff() <= tolerance) return;
  if (symmetric_) conjugate_gradients(tolerance);
  else bicgstab(tolerance);
}

void TreadNewtonContact::conjugate_gradients(double tolerance) {
  z_ = r_.cwiseProduct(inverse_diagonal_);
  p_ = z_;
  double rz = r_.dot(z_);
  for (int iteration = 0; iteration < kMaxCgIterations; ++iteration) {
    multiply(p_, ap_);  // A·p at every point: the points left out of (3) need A·x too
    mp_ = (ap_ + compliance_.cwiseProduct(p_)).cwiseProduct(mask_);
    const double curvature = p_.dot(mp_);
    if (!(curvature > 0.0))
      throw std::runtime_error("TreadNewtonContact: A + C is not positive definite on the contact set (curvature " +
                               sci(curvature) + " in conjugate-gradient iteration " +
                               std::to_string(iteration) + "): is A positive definite?");
    const double alpha = rz / curvature;
    x_.noalias() += alpha * p_;
    ax_.noalias() += alpha * ap_;
    r_.noalias() -= alpha * mp_;
    ++cg_iterations_;
    if (r_.cwiseAbs().maxCoeff() <= tolerance) return;
    z_ = r_.cwiseProduct(inverse_diagonal_);
    const double next = r_.dot(z_);
    p_ = z_ + (next / rz) * p_;
    rz = next;
  }
  throw std::runtime_error("TreadNewtonContact: conjugate gradients did not reach " + sci(tolerance) +
                           " m in " + std::to_string(kMaxCgIterations) + " iterations (residual " +
                           sci(r_.cwiseAbs().maxCoeff()) + " m)");
}

void TreadNewtonContact::bicgstab(double tolerance) {
  // Right-preconditioned by K = diag(A + C) (K⁻¹ = inverse_diagonal_, zero off the mask), from
  // x = 0; r_ holds −gap on the mask. A·K⁻¹p and A·K⁻¹s at every point accumulate A·x.
  shadow_ = r_;
  p_.setZero();
  mp_.setZero();  // v = (A + C)·K⁻¹p
  double rho_old = 1.0, alpha = 1.0, omega = 1.0;
  const auto breakdown = [&](const char* what, int iteration) {
    return std::runtime_error(std::string("TreadNewtonContact: BiCGSTAB broke down (") + what + " in iteration " +
                              std::to_string(iteration) + ", residual " + sci(r_.cwiseAbs().maxCoeff()) + " m)");
  };
  for (int iteration = 0; iteration < kMaxCgIterations; ++iteration) {
    const double rho = shadow_.dot(r_);
    if (!(std::abs(rho) > 0.0)) throw breakdown("ρ = 0", iteration);
    const double beta = (rho / rho_old) * (alpha / omega);
    p_ = r_ + beta * (p_ - omega * mp_);
    z_ = p_.cwiseProduct(inverse_diagonal_);
    multiply(z_, ap_);
    mp_ = (ap_ + compliance_.cwiseProduct(z_)).cwiseProduct(mask_);
    const double projection = shadow_.dot(mp_);
    if (!(std::abs(projection) > 0.0)) throw breakdown("r̂₀·v = 0", iteration);
    alpha = rho / projection;
    x_.noalias() += alpha * z_;
    ax_.noalias() += alpha * ap_;
    s_ = r_ - alpha * mp_;
    ++cg_iterations_;
    if (s_.cwiseAbs().maxCoeff() <= tolerance) {
      r_ = s_;
      return;
    }
    hat_s_ = s_.cwiseProduct(inverse_diagonal_);
    multiply(hat_s_, at_);
    t_ = (at_ + compliance_.cwiseProduct(hat_s_)).cwiseProduct(mask_);
    const double tt = t_.squaredNorm();
    if (!(tt > 0.0)) throw breakdown("t = 0", iteration);
    omega = t_.dot(s_) / tt;
    if (!(std::abs(omega) > 0.0)) throw breakdown("ω = 0", iteration);
    x_.noalias() += omega * hat_s_;
    ax_.noalias() += omega * at_;
    r_ = s_ - omega * t_;
    if (r_.cwiseAbs().maxCoeff() <= tolerance) return;
    rho_old = rho;
  }
  throw std::runtime_error("TreadNewtonContact: BiCGSTAB did not reach " + sci(tolerance) + " m in " +
                           std::to_string(kMaxCgIterations) + " iterations (residual " + sci(r_.cwiseAbs().maxCoeff()) +
                           " m)");
}

const Eigen::VectorXd& TreadNewtonContact::solve(const Eigen::VectorXd& q) {
  const Eigen::Index size = a_.rows();
  if (q.size() != size)
    throw std::invalid_argument("TreadNewtonContact::solve: q has " + std::to_string(q.size()) + " entries, expected " +
                                std::to_string(size));
  if (!q.allFinite()) throw std::invalid_argument("TreadNewtonContact::solve: q has non-finite entries");
  iterations_ = 0;
  const double scale = size > 0 ? q.cwiseAbs().maxCoeff() : 0.0;
  if (scale == 0.0) {
    // q = 0: δ = 0 gives gap = 0, complementary (and the solution is unique).
    delta_.setZero();
    force_.setZero();
    gap_ = q;
    std::fill(in_contact_.begin(), in_contact_.end(), 0);
    return force_;
  }
  const double tolerance = kTolerance * scale;
  // The first contact set: the warm start's points in contact and those that penetrate under
  // its forces (δ_p > gap_p, the semismooth Newton choice on min(δ, gap)).
  for (Eigen::Index p = 0; p < size; ++p) evaluate_spring(p);
  evaluate_gap(q);
  for (Eigen::Index p = 0; p < size; ++p)
    active_[static_cast<std::size_t>(p)] = delta_(p) > 0.0 || gap_(p) < 0.0 ? 1 : 0;
  // Block principal pivoting over contact sets, as for the linear tread (pmatrix_lcp.cpp; Júdice
  // & Pires 1994): exchange all infeasible points at once while their number falls (with ten
  // tries more), else one, the last (Murty's rule).
  BlockPivotingExchange exchange(size);
  const Eigen::Index max_rounds = 10 * size + 100;
  for (Eigen::Index round = 0; round < max_rounds; ++round) {
    // δ = 0 off the contact set, exactly.
    moved_.clear();
    for (Eigen::Index p = 0; p < size; ++p)
      if (!active_[static_cast<std::size_t>(p)] && delta_(p) != 0.0) moved_.push_back(p);
    if (moved_.size() <= column_updates()) {
      for (const Eigen::Index p : moved_) release(p);
    } else {
      for (const Eigen::Index p : moved_) delta_(p) = force_(p) = slope_(p) = 0.0;
      evaluate_gap(q);
    }
    seed_joining_points(q);
    const double residual = solve_contact_set(q, tolerance);
    // Infeasible: a point of the set pulled into tension (δ < 0), or one off it penetrating. Left
    // early (see solve_contact_set), only the points violated beyond the residual's reach.
    const double threshold = residual <= tolerance ? tolerance : kEarlyExchange * residual;
    Eigen::Index infeasible = 0, last = -1;
    for (Eigen::Index p = 0; p < size; ++p) {
      if (active_[static_cast<std::size_t>(p)] ? pull(p) < -threshold : gap_(p) < -threshold) {
        ++infeasible;
        last = p;
      }
    }
    // (Left early, solve_contact_set found a violation beyond this same threshold: at least one
    // point is infeasible, so no infeasible point means Newton converged on the set.)
    if (infeasible == 0) {
      // A δ_p at −round-off is a point out of contact.
      for (Eigen::Index p = 0; p < size; ++p)
        if (delta_(p) < 0.0) release(p);
      for (Eigen::Index p = 0; p < size; ++p) in_contact_[static_cast<std::size_t>(p)] = force_(p) > 0.0 ? 1 : 0;
      return force_;
    }
    exchange.exchange(active_, infeasible, last, [&](Eigen::Index p) {
      return active_[static_cast<std::size_t>(p)] ? pull(p) < -threshold : gap_(p) < -threshold;
    });
  }
  throw std::runtime_error("TreadNewtonContact: the contact set did not settle in " + std::to_string(max_rounds) +
                           " exchanges (P = " + std::to_string(size) + ")");
}

void TreadNewtonContact::seed_joining_points(const Eigen::VectorXd& q) {
  // A point joining the set (δ_p = 0, gap_p < 0) has no force in Newton's first linearisation
  // for n > 1 (dF/dδ = 0 at δ = 0), so the others would not see it until the second iteration.
  // It starts instead at its own compression under the others' forces, δ + A_pp·F(δ) = −gap_p
  // (the minimum of (2) along F_p alone): Newton then starts with every contact force coupled.
  // On plate_rough_80kmh (n = 1.5) this took the Newton iterations from 5.6 to 4.1 a step.
  const Eigen::Index size = a_.rows();
  moved_.clear();
  for (Eigen::Index p = 0; p < size; ++p)
    if (active_[static_cast<std::size_t>(p)] && delta_(p) == 0.0 && gap_(p) < 0.0) moved_.push_back(p);
  for (const Eigen::Index p : moved_) {  // all from the same gaps, then the gaps updated
    springs_->compress(p, -gap_(p), a_diagonal_(p), 0.0, delta_(p), force_(p), slope_(p));
  }
  if (moved_.size() > column_updates()) {
    evaluate_gap(q);
  } else {
    for (const Eigen::Index p : moved_) {
      gap_.noalias() += a_.col(p) * force_(p);
      gap_(p) += delta_(p);
    }
  }
}

double TreadNewtonContact::solve_contact_set(const Eigen::VectorXd& q, double tolerance) {
  const Eigen::Index size = a_.rows();
  const double scale = q.cwiseAbs().maxCoeff();
  double last_residual = std::numeric_limits<double>::infinity();
  for (int iteration = 0;; ++iteration) {
    double residual = 0.0, violation = 0.0;
    for (Eigen::Index p = 0; p < size; ++p) {
      if (active_[static_cast<std::size_t>(p)]) {
        residual = std::max(residual, std::abs(gap_(p)));
        violation = std::max(violation, -pull(p));
      } else {
        violation = std::max(violation, -gap_(p));
      }
    }
    if (residual <= tolerance) return residual;
    // Round-off: a residual that no longer halves within a few times the tolerance is the floor
    // of the gaps' products (FFT), not a set that Newton cannot solve. Seen with the tabulated
    // texture laws, whose slopes come from float nodes: stalled at 1.2× the tolerance.
    if (iteration >= kStallIterations && residual <= kStallFactor * tolerance && residual > 0.5 * last_residual)
      return residual;
    last_residual = residual;
    // A point whose violation exceeds what the rest of the Newton iterations are likely to change
    // (the residual's effect on δ and the other gaps, through (A + C)⁻¹ and A, is of its order)
    // leaves or joins the set: exchange now rather than converge a set that is most likely wrong
    // (a semismooth Newton step; a wrong exchange is undone in the next round).
    if (violation > kEarlyExchange * residual) return residual;
    if (iteration == kMaxIterations)
      throw std::runtime_error("TreadNewtonContact: Newton did not converge in " + std::to_string(kMaxIterations) +
                               " iterations on a contact set (max |gap| = " + sci(residual) + " m, tolerance " +
                               sci(tolerance) + " m)");
    ++iterations_;
    // The merit before the step: without (2) max_S |gap|, the residual; with it computed only if
    // the full step does not settle it (below).
    std::optional<double> start;
    if (!symmetric_) start = residual;
    // Inexact Newton: (3) to a fraction of the residual that falls with it (quadratic rate).
    newton_system(std::max(0.5 * tolerance, residual * std::min(kForcing, residual / scale)));
    // The step in y = δ + A_pp·F(δ): Δy = Δδ + A_pp·x with Δδ = C·x on the points of (3), and
    // Δδ = −gap − (A·x) from its own row, with no force change, for a point left out.
    for (Eigen::Index p = 0; p < size; ++p) {
      if (!active_[static_cast<std::size_t>(p)]) continue;
      step_(p) = mask_(p) != 0.0 ? (compliance_(p) + a_diagonal_(p)) * x_(p) : -gap_(p) - ax_(p);
      coordinate_(p) = delta_(p) + a_diagonal_(p) * force_(p);
      previous_(p) = delta_(p);
    }
    // On a fixed set, with F's odd extension, (2) is strictly convex and smooth in F, and the
    // Newton step a descent direction: it must not increase (beyond its round-off), else the
    // step is halved along the path y + α·Δy. Without (2) (A not symmetric) max_S |gap| must
    // fall, by the Armijo fraction 1e-4·α. Near the solution the full step is taken; far from
    // it (a cold start, where the entering points take their own compressions and together
    // overshoot) this keeps Newton from wandering. A full step that halves max_S |gap| is taken
    // without the merit: the residual then falls geometrically, which is all the line search
    // guards, and the energy's per-point integrals are the dearest part of a trial.
    const auto take_step = [&](double alpha) {
      for (Eigen::Index p = 0; p < size; ++p) {
        if (!active_[static_cast<std::size_t>(p)]) continue;
        // Newton's own prediction of δ (Δδ = C·x, or the whole step for a point left out of
        // (3)) starts the scalar root search a second-order distance from its root.
        const double predicted = previous_(p) + alpha * (mask_(p) != 0.0 ? compliance_(p) * x_(p) : step_(p));
        springs_->compress(p, coordinate_(p) + alpha * step_(p), a_diagonal_(p), predicted, delta_(p), force_(p),
                           slope_(p));
      }
      evaluate_gap(q);
    };
    for (double alpha = 1.0;; alpha *= 0.5) {
      take_step(alpha);
      if (alpha == 1.0 && set_residual() <= 0.5 * residual) break;
      if (!start) {
        start = merit_before_step(q);
        take_step(alpha);
      }
      if (merit(q) <= (symmetric_ ? *start : (1.0 - 1e-4 * alpha) * *start) + merit_noise(q)) break;
      if (alpha < kSmallestStep)
        throw std::runtime_error("TreadNewtonContact: no decrease of the merit along the Newton step (max |gap| = " +
                                 sci(residual) + " m, tolerance " + sci(tolerance) + " m)");
    }
  }
}

void TreadNewtonContact::warm_start(const Eigen::Ref<const Eigen::VectorXd>& force) {
  if (force.size() != a_.rows() || !force.allFinite())
    throw std::invalid_argument("TreadNewtonContact::warm_start: " + std::to_string(a_.rows()) + " finite forces expected");
  for (Eigen::Index p = 0; p < force.size(); ++p)
    delta_(p) = force(p) > 0.0 ? springs_->compression_at(p, force(p)) : 0.0;
  for (Eigen::Index p = 0; p < delta_.size(); ++p) in_contact_[static_cast<std::size_t>(p)] = delta_(p) > 0.0 ? 1 : 0;
}

void TreadNewtonContact::relabel(const std::vector<Eigen::Index>& new_index) {
  if (static_cast<Eigen::Index>(new_index.size()) != a_.rows())
    throw std::invalid_argument("TreadNewtonContact::relabel: one new index per point expected");
  shifted_.setZero();
  for (std::size_t i = 0; i < new_index.size(); ++i)
    if (const Eigen::Index to = new_index[i]; to >= 0) shifted_(to) = delta_(static_cast<Eigen::Index>(i));
  std::swap(shifted_, delta_);
  for (Eigen::Index p = 0; p < delta_.size(); ++p) in_contact_[static_cast<std::size_t>(p)] = delta_(p) > 0.0 ? 1 : 0;
}

}  // namespace rollnoise
