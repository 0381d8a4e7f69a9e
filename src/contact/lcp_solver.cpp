#include "contact/lcp_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>

namespace rollnoise {
namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
}

LcpSolver::LcpSolver(Eigen::MatrixXd matrix) : a_(std::move(matrix)) {
  const Eigen::Index n = a_.rows();
  if (a_.cols() != n) throw std::invalid_argument("LCP matrix must be square");
  if (!a_.allFinite()) throw NotPositiveDefiniteError("the contact matrix G[0] has non-finite entries");
  const double scale = a_.cwiseAbs().maxCoeff();
  const double asym = (a_ - a_.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-12 * scale) {
    throw NotPositiveDefiniteError("the contact matrix G[0] is not symmetric (asymmetry " +
                                   std::to_string(asym / scale) + " relative)");
  }
  Eigen::LLT<Eigen::MatrixXd> llt(a_);
  if (n > 0 && (llt.info() != Eigen::Success || !(scale > 0.0))) {
    throw NotPositiveDefiniteError("the contact matrix G[0] is not positive definite");
  }
  x_ = Eigen::VectorXd::Zero(n);
  w_ = Eigen::VectorXd::Zero(n);
  z_ = Eigen::VectorXd::Zero(n);
  rhs_ = Eigen::VectorXd::Zero(n);
  work_ = Eigen::VectorXd::Zero(n);
  l_ = Eigen::MatrixXd::Zero(n, n);
  is_active_.assign(static_cast<std::size_t>(n), 0);
  blocked_.assign(static_cast<std::size_t>(n), 0);
  active_.reserve(static_cast<std::size_t>(n));
}

void LcpSolver::reset() {
  active_.clear();
  std::fill(is_active_.begin(), is_active_.end(), 0);
  active_count_ = 0;
}

void LcpSolver::warm_start(const std::vector<char>& active) {
  if (static_cast<Eigen::Index>(active.size()) != a_.rows()) throw std::invalid_argument("warm start has the wrong size");
  reset();
  std::vector<Eigen::Index> indices;
  for (Eigen::Index i = 0; i < a_.rows(); ++i)
    if (active[static_cast<std::size_t>(i)]) indices.push_back(i);
  const auto p = static_cast<Eigen::Index>(indices.size());
  if (p == 0) return;
  Eigen::MatrixXd block(p, p);
  for (Eigen::Index b = 0; b < p; ++b)
    for (Eigen::Index a = 0; a < p; ++a) block(a, b) = a_(indices[a], indices[b]);
  const Eigen::LLT<Eigen::MatrixXd> llt(block);
  if (llt.info() != Eigen::Success) return;  // numerically singular: start from nothing instead
  l_.topLeftCorner(p, p) = llt.matrixL();
  for (Eigen::Index i = 0; i < p; ++i) {
    active_.push_back(indices[i]);
    is_active_[indices[i]] = 1;
  }
}

void LcpSolver::relabel_active_set(const std::vector<Eigen::Index>& new_index) {
  if (static_cast<Eigen::Index>(new_index.size()) != a_.rows()) throw std::invalid_argument("relabel has the wrong size");
  for (Eigen::Index position = static_cast<Eigen::Index>(active_.size()) - 1; position >= 0; --position) {
    if (new_index[static_cast<std::size_t>(active_[position])] < 0) remove_from_factor(position);
  }
  std::fill(is_active_.begin(), is_active_.end(), 0);
  for (Eigen::Index& index : active_) {
    index = new_index[static_cast<std::size_t>(index)];
    is_active_[index] = 1;
  }
}

// Appends `index` to the factor: solve L·l = A[P, j], then d = A[j, j] − l·l. Returns false
// (and leaves the factor alone) if the pivot is not safely positive.
bool LcpSolver::add_to_factor(Eigen::Index index) {
  const Eigen::Index p = static_cast<Eigen::Index>(active_.size());
  for (Eigen::Index i = 0; i < p; ++i) rhs_(i) = a_(active_[i], index);
  auto row = l_.row(p).head(p);
  if (p > 0) {
    row.transpose() = l_.topLeftCorner(p, p).triangularView<Eigen::Lower>().solve(rhs_.head(p));
  }
  const double d = a_(index, index) - (p > 0 ? row.squaredNorm() : 0.0);
  if (!(d > 1e-13 * a_(index, index))) return false;
  l_(p, p) = std::sqrt(d);
  active_.push_back(index);
  is_active_[index] = 1;
  return true;
}

// Deletes the factor row of active position `position` and restores the triangle with
// Givens rotations on neighbouring columns (they leave L·Lᵀ unchanged).
void LcpSolver::remove_from_factor(Eigen::Index position) {
  const Eigen::Index p = static_cast<Eigen::Index>(active_.size());
  is_active_[active_[position]] = 0;
  active_.erase(active_.begin() + position);
  for (Eigen::Index i = position; i + 1 < p; ++i) l_.row(i).head(i + 2) = l_.row(i + 1).head(i + 2);
  for (Eigen::Index c = position; c + 1 < p; ++c) {
    const double a = l_(c, c);
    const double b = l_(c, c + 1);
    const double r = std::hypot(a, b);
    const double cs = a / r;
    const double sn = b / r;
    for (Eigen::Index i = c; i + 1 < p; ++i) {
      const double u = l_(i, c);
      const double v = l_(i, c + 1);
      l_(i, c) = cs * u + sn * v;
      l_(i, c + 1) = -sn * u + cs * v;
    }
    l_(c, c + 1) = 0.0;
  }
  l_.row(p - 1).setZero();
  l_.col(p - 1).setZero();
}

// z_P = −A_PP⁻¹ q_P from the factor. (Round-off of the updated factor is removed once, at
// the end of solve(), by a refinement step.)
void LcpSolver::solve_on_active(const Eigen::Ref<const Eigen::VectorXd>& q) {
  const Eigen::Index p = static_cast<Eigen::Index>(active_.size());
  if (p == 0) return;
  const auto lower = l_.topLeftCorner(p, p).triangularView<Eigen::Lower>();
  for (Eigen::Index i = 0; i < p; ++i) rhs_(i) = -q(active_[i]);
  auto z = z_.head(p);
  z = lower.solve(rhs_.head(p));
  lower.transpose().solveInPlace(z);
}

// From a feasible x (x ≥ 0, x = 0 off the active set), moves towards the unconstrained
// minimiser on the active set and drops the indices that would go negative, until that
// minimiser is strictly positive.
void LcpSolver::feasibility_loop(const Eigen::Ref<const Eigen::VectorXd>& q) {
  while (!active_.empty()) {
    solve_on_active(q);
    const Eigen::Index p = static_cast<Eigen::Index>(active_.size());
    double alpha = 1.0;
    for (Eigen::Index i = 0; i < p; ++i) {
      if (z_(i) <= 0.0) {
        const double xi = x_(active_[i]);
        alpha = std::min(alpha, xi > 0.0 ? xi / (xi - z_(i)) : 0.0);
      }
    }
    if (alpha >= 1.0) {
      for (Eigen::Index i = 0; i < p; ++i) x_(active_[i]) = z_(i);
      return;
    }
    // Step to the boundary; the indices that reach it leave the active set.
    for (Eigen::Index i = 0; i < p; ++i) {
      const Eigen::Index j = active_[i];
      x_(j) += alpha * (z_(i) - x_(j));
    }
    for (Eigen::Index i = p - 1; i >= 0; --i) {
      const Eigen::Index j = active_[i];
      if (z_(i) <= 0.0 && x_(j) <= 1e-14 * std::abs(z_(i)) + std::numeric_limits<double>::min()) {
        x_(j) = 0.0;
        remove_from_factor(i);
        ++iterations_;
      }
    }
    // Guard: at least the index that set alpha has left (it met the test above), so the
    // active set shrinks and the loop ends.
  }
}

const Eigen::VectorXd& LcpSolver::solve(const Eigen::Ref<const Eigen::VectorXd>& q) {
  const Eigen::Index n = a_.rows();
  if (q.size() != n) throw std::invalid_argument("LCP vector has the wrong size");
  iterations_ = 0;
  // Warm start: x = 0 is feasible for any active set; the loop keeps what still fits. With
  // no previous set, the points that penetrate at x = 0 (q < 0) are the first guess, which
  // saves one pivot per contact point against starting from nothing.
  if (active_.empty()) {
    for (Eigen::Index j = 0; j < n; ++j)
      if (q(j) < 0.0 && add_to_factor(j)) ++iterations_;
  }
  x_.setZero();
  feasibility_loop(q);
  const double q_scale = q.cwiseAbs().maxCoeff();
  const double a_scale = a_.cwiseAbs().rowwise().sum().maxCoeff();
  const int max_changes = static_cast<int>(20 * n + 100);
  std::fill(blocked_.begin(), blocked_.end(), 0);
  bool refined = false;
  // Block additions: every index with w_j < 0 enters at once, then the feasibility loop drops
  // what does not fit. Each round still lowers the QP objective (the segment towards the
  // minimiser on the larger set descends), and it saves most of the O(n·p) slack updates when
  // many contacts change in one step (a rough road). After a bounded number of rounds the
  // classic single-index rule takes over, whose termination is guaranteed.
  int block_rounds = 0;
  constexpr int max_block_rounds = 25;
  while (true) {
    // w = q + A·x, summed over the active columns only (x is 0 elsewhere).
    w_ = q;
    for (const Eigen::Index j : active_) w_.noalias() += a_.col(j) * x_(j);
    const double tolerance = 64.0 * kEps * (a_scale * x_.cwiseAbs().maxCoeff() + q_scale);
    Eigen::Index entering = -1;
    double most_negative = -tolerance;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!is_active_[j] && !blocked_[j] && w_(j) < most_negative) {
        most_negative = w_(j);
        entering = j;
      }
    }
    if (entering < 0) {
      if (refined) break;
      // One step of iterative refinement on the final active set: x_P += A_PP⁻¹·(−w_P). It
      // removes the round-off that the row updates of the factor have gathered.
      refined = true;
      const Eigen::Index p = static_cast<Eigen::Index>(active_.size());
      if (p == 0) break;
      const auto lower = l_.topLeftCorner(p, p).triangularView<Eigen::Lower>();
      for (Eigen::Index i = 0; i < p; ++i) work_(i) = -w_(active_[i]);
      auto dx = work_.head(p);
      dx = lower.solve(dx.eval());
      lower.transpose().solveInPlace(dx);
      bool stays_positive = true;
      for (Eigen::Index i = 0; i < p; ++i) stays_positive = stays_positive && x_(active_[i]) + dx(i) > 0.0;
      if (!stays_positive) break;  // at a degenerate boundary: keep the unrefined, feasible x
      for (Eigen::Index i = 0; i < p; ++i) x_(active_[i]) += dx(i);
      continue;  // recompute w and recheck optimality
    }
    if (block_rounds < max_block_rounds) {
      ++block_rounds;
      int added = 0;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (!is_active_[j] && !blocked_[j] && w_(j) < -tolerance) {
          if (add_to_factor(j)) ++added;
          else blocked_[j] = 1;  // numerically singular with the active points: x_j = 0 fits
        }
      }
      iterations_ += added;
      if (added == 0) continue;
    } else {
      if (!add_to_factor(entering)) {
        // A_PP ∪ {j} is numerically singular (j duplicates active points): x_j = 0 is optimal.
        blocked_[entering] = 1;
        continue;
      }
      ++iterations_;
    }
    if (iterations_ > max_changes) {
      throw std::runtime_error("LCP solver did not terminate after " + std::to_string(max_changes) +
                               " active-set changes (n = " + std::to_string(n) + ")");
    }
    feasibility_loop(q);
  }
  active_count_ = static_cast<Eigen::Index>(active_.size());
  return x_;
}

}  // namespace rollnoise
