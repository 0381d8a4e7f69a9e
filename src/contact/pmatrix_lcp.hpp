#pragma once
// The LCP  z ≥ 0, w = M·z + q ≥ 0, zᵀw = 0  for a P-matrix M that need not be symmetric, such as
// the compliance of a rolling, damped tyre summed over all lags (the steady-rolling problem;
// damping makes it non-symmetric). Every P-matrix LCP has exactly one solution.
//
// Block principal pivoting (Júdice & Pires, Comput. Oper. Res. 21 (1994) 587–596): exchange all
// infeasible indices at once while their number falls, and fall back to Murty's single
// least-index pivot, which terminates finitely for P-matrices, when it does not. Each
// iteration solves the active block: solve_pmatrix_lcp with a dense LU (the reference), the
// PMatrixLcpSolver of a sequence of nearby problems with a factor kept across them.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "contact/bordered_lu.hpp"

namespace rollnoise {

struct PMatrixLcpResult {
  Eigen::VectorXd z;  // the solution
  Eigen::VectorXd w;  // M·z + q
  int iterations = 0;
  std::vector<char> basic;  // the final set of indices with z free (w = 0)
};

// `start`: a first guess of the basic set (for example the last solution's, for a nearby q);
// without one, the indices with q < 0.
PMatrixLcpResult solve_pmatrix_lcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                                   const std::vector<char>* start = nullptr);

// A sequence of LCPs with the same M and nearby q, such as the steps of a rolling contact: each
// solve is warm-started from the last one's basic set, and M's block on the basic set stays
// factorised across solves (BorderedLu), so that a set that moves by a few indices costs O(n²)
// per index instead of an O(n³) factorisation per pivoting iteration. Same pivoting, same
// answer as solve_pmatrix_lcp up to round-off. Nothing is allocated per solve.
class PMatrixLcpSolver {
 public:
  // `capacity`: the most indices by which the basic set may drift from the factorised one
  // before it is refactorised (bordered_lu.hpp).
  explicit PMatrixLcpSolver(Eigen::MatrixXd m, Eigen::Index capacity = 128);

  const PMatrixLcpResult& solve(const Eigen::VectorXd& q);
  const PMatrixLcpResult& result() const noexcept { return result_; }

  // The next solve's first guess of the basic set.
  void warm_start(const std::vector<char>& basic);
  // Moves the warm start to other indices: index i becomes new_index[i] (or leaves, < 0). With
  // `matrix_unchanged` (M(new_index[a], new_index[b]) = M(a, b), a contact matrix shifted along
  // a translation-invariant direction) the factor moves with it; otherwise it is redone.
  void relabel(const std::vector<Eigen::Index>& new_index, bool matrix_unchanged);

  // Factorisations of the basic block so far (the rest were bordered updates).
  long factorisations() const noexcept { return factor_.factorisations(); }
  const Eigen::MatrixXd& matrix() const noexcept { return *m_; }

 private:
  std::shared_ptr<const Eigen::MatrixXd> m_;
  BorderedLu factor_;
  PMatrixLcpResult result_;
  std::vector<char> shifted_;
  std::vector<Eigen::Index> active_;
};

// Whether M(new_index[a], new_index[b]) = M(a, b) for every pair that stays, to `tolerance`
// relative to max |M|: the condition for moving a factor with relabel().
bool matrix_unchanged_by(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& new_index,
                         double tolerance = 1e-12);

}  // namespace rollnoise
