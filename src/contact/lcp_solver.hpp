#pragma once
// The per-step contact problem (MODEL.md §2): the linear complementarity problem
//   x ≥ 0,  w = A·x + q ≥ 0,  xᵀw = 0
// with A symmetric positive definite, i.e. the convex QP min ½xᵀAx + qᵀx subject to x ≥ 0.
//
// Solved by a primal active-set method (Lawson & Hanson's NNLS, generalised to a QP): it
// terminates after finitely many set changes with the exact solution up to round-off, unlike
// the paper's "guess the contact points and repeat". A Cholesky factor of A on the active set
// is updated by one row at a time (O(p²) per change), and the active set of the previous solve
// is the warm start, so a rolling run that changes a few contacts per step costs a few
// updates per step.
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

// A is not symmetric positive definite: the contact problem has no unique solution.
class NotPositiveDefiniteError : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

class LcpSolver {
 public:
  // Checks that A is symmetric (to 1e-12 relative) and positive definite.
  explicit LcpSolver(Eigen::MatrixXd matrix);

  // Solves for q, warm-started from the previous solve's active set. Returns x.
  const Eigen::VectorXd& solve(const Eigen::Ref<const Eigen::VectorXd>& q);

  const Eigen::VectorXd& solution() const noexcept { return x_; }
  // w = A·x + q of the last solve (the gaps, for a contact problem).
  const Eigen::VectorXd& slack() const noexcept { return w_; }
  // Active-set changes (additions plus removals) in the last solve: 0 when the warm start was
  // already the answer.
  int iterations() const noexcept { return iterations_; }
  Eigen::Index active_count() const noexcept { return active_count_; }
  Eigen::Index size() const noexcept { return a_.rows(); }
  // Forget the warm start (the next solve starts from an empty active set).
  void reset();
  // Use `active` (one flag per index) as the next warm start, refactoring A on it (O(p³)):
  // worth it when the caller knows a better guess than the last active set, such as the last
  // set shifted with a rolling road.
  void warm_start(const std::vector<char>& active);
  // Moves the warm start to other indices without refactoring: active index a becomes
  // new_index[a], or leaves the set where new_index[a] < 0. Valid when A is the same on the new
  // indices as on the old, A(new_index[a], new_index[b]) = A(a, b) (e.g. a translation-invariant
  // contact matrix with a set shifted along it); the factor is then unchanged but for the rows
  // that leave (O(p²) each).
  void relabel_active_set(const std::vector<Eigen::Index>& new_index);
  // The active set of the last solve, one flag per index.
  const std::vector<char>& active_flags() const noexcept { return is_active_; }

 private:
  bool add_to_factor(Eigen::Index index);
  void remove_from_factor(Eigen::Index position);
  void solve_on_active(const Eigen::Ref<const Eigen::VectorXd>& q);
  void feasibility_loop(const Eigen::Ref<const Eigen::VectorXd>& q);

  Eigen::MatrixXd a_;
  Eigen::VectorXd x_, w_;
  // Active indices in factor order, their Cholesky factor (top-left p×p of l_), and scratch.
  std::vector<Eigen::Index> active_;
  std::vector<char> is_active_;
  // Indices that would make the active matrix singular, skipped for the rest of a solve.
  std::vector<char> blocked_;
  Eigen::MatrixXd l_;
  Eigen::VectorXd z_, rhs_, work_;
  Eigen::Index active_count_ = 0;
  int iterations_ = 0;
};

}  // namespace rollnoise
