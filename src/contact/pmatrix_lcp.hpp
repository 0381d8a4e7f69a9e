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
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "contact/bordered_lu.hpp"
#include "contact/window_convolution.hpp"

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
//
// A contact matrix that depends on x_p − x_q only (a translation-invariant tyre on its window,
// `window` given) is also multiplied by FFT (window_convolution.hpp). If it is moreover
// symmetric and, scaled by its diagonal, diagonally dominant enough that its condition number is
// at most 25 by Gershgorin's bound (the plate with its Winkler tread: a point's own compliance is
// 4–5 times its coupling to the whole patch), each basic block is solved by preconditioned
// conjugate gradients instead, started from the straight line through the last two solutions
// (moved with the road by relabel): about eleven FFT products a step, no factorisation.
// The factor stays the fallback. A pivoting iteration's conjugate gradients stop as soon as
// every sign test of the exchange is decided beyond a bound on their error (the exchange is then
// the exact solve's), or at a residual of 1e-13 of max |q|; the last iteration's, once all signs
// are decided feasible, at 1e-11 of it: KKT conditions to about 1e-11, scaled.
// (ContactWindow: window_convolution.hpp.)
class PMatrixLcpSolver {
 public:
  // `capacity`: the most indices by which the basic set may drift from the factorised one
  // before it is refactorised (bordered_lu.hpp). `window`: M depends on x_p − x_q only on this
  // window (point p = i + W·j), as matrix_unchanged_by checks.
  explicit PMatrixLcpSolver(Eigen::MatrixXd m, Eigen::Index capacity = 128, std::optional<ContactWindow> window = {});
  ~PMatrixLcpSolver();

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
  // Whether the conjugate gradients of a pivoting iteration may stop as soon as the iteration's
  // exchange is decided (the default; it is the same exchange), the last one's once all signs
  // are decided feasible and the residual is 1e-11 of max |q|, and the next iteration start
  // from the last M·z; off, each block is solved afresh to 1e-13 from the warm set as it is (the
  // solver as it was, kept as the tests' reference, without correct_warm_start either).
  void decide_early(bool on) noexcept { decide_early_ = on; }
  // Whether the warm start's set is corrected by the warm forces' gaps before the first solve
  // (the default, with decide_early and conjugate gradients): a point off it that penetrates
  // under them enters, one on it whose force a Jacobi step makes negative leaves.
  void correct_warm_start(bool on) noexcept { correct_start_ = on; }
  // Whether basic blocks are solved by conjugate gradients; their iterations so far.
  bool iterative() const noexcept { return iterative_; }
  long cg_iterations() const noexcept { return cg_iterations_; }
  const Eigen::MatrixXd& matrix() const noexcept { return *m_; }
  // Whether the conjugate gradients' pass over the window takes four values at a time (AVX,
  // where the processor has it: the default) or one; both give the same bits. Returns whether
  // AVX is now used.
  bool use_avx(bool on) noexcept;

 private:
  enum class Cg { converged, decided, failed };
  // M_AA z_A = −q_A from z's values on A: converged; or stopped early with every sign test of the
  // pivoting (z_i < −tolerance on A, w_i < −tolerance off it) decided as for the exact solution
  // and some index infeasible, w = M·z + q then set off A (decided); or failed (z is then
  // unusable).
  Cg conjugate_gradients(const std::vector<char>& basic, const Eigen::VectorXd& q, Eigen::VectorXd& z, Eigen::VectorXd& w,
                         double tolerance);
  // The warm start's basic set, corrected by the gaps and forces of z = last_z_.
  void correct_start(const Eigen::VectorXd& q);

  std::shared_ptr<const Eigen::MatrixXd> m_;
  BorderedLu factor_;
  std::unique_ptr<WindowConvolution> product_;
  bool iterative_ = false;
  bool decide_early_ = true;
  bool correct_start_ = true;
  bool avx_ = false;
  long cg_iterations_ = 0;
  PMatrixLcpResult result_;
  std::vector<char> shifted_;
  std::vector<Eigen::Index> active_, leaving_;
  // The last two solutions (the next warm start), and the conjugate gradients' vectors (mz_ = M·z).
  long solves_ = 0;  // since the last warm_start
  std::vector<double> on_bits_;  // the basic set as a mask for the AVX pass: all bits set on it
  Eigen::VectorXd last_z_, older_z_, shifted_z_, inverse_diagonal_, r_, s_, p_, mp_, mz_;
  // Bounds on any basic block: ‖z's error‖₂ per ‖D^{-1/2}·residual‖₂, ‖z's error‖∞ per
  // ‖residual‖∞, and the largest 2-norm and 1-norm of M's rows without their diagonal.
  // Whether mz_ = M·z for the z of the last pivoting iteration; up to how many indices leaving
  // the block it is updated by columns of M rather than by a product.
  bool mz_valid_ = false;
  static constexpr Eigen::Index kLeavingColumns = 32;
  double error_per_residual_ = 0.0, error_per_max_residual_ = INFINITY, coupling_row_norm_ = 0.0, coupling_row_sum_ = 0.0;
};

// Whether M(new_index[a], new_index[b]) = M(a, b) for every pair that stays, to `tolerance`
// relative to max |M|: the condition for moving a factor with relabel().
bool matrix_unchanged_by(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& new_index,
                         double tolerance = 1e-12);

}  // namespace rollnoise
