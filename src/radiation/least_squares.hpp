#pragma once
// The regularised least-squares problem of one equivalent-source solve,
//   min ‖A q − b‖² + λ²‖q‖²,   A: m × n complex (m ≥ n),
// factorised once and applied to any number of right-hand sides or receivers, with the dense
// kernels of an optimised BLAS/LAPACK (OpenBLAS, whose SIMD kernels are chosen at run time for
// the processor; Eigen's own kernels are compiled for the baseline instruction set and ran this
// complex QR 6–7× slower).
//
// Method. The normal equations (AᴴA + λ²I) q = Aᴴb, by a Hermitian rank-k update (zherk) and
// a Cholesky factorisation (zpotrf): for m = 2n a third of the flops of the Householder QR of
// [A; λI], in faster kernels. They square the condition number, so they are kept only when the
// condition estimate of AᴴA + λ²I (zpocon) is at most 1e11 (errors ≲ 1e-5 relative in q along
// its weakest directions, far less in the field q makes; the tyre's meshes are at 1e6–1e9);
// otherwise the Householder QR of [A; λI] (zgeqrf) is used, as before.
//
// Determinism: the BLAS runs single-threaded (core/blas_threads.hpp; the radiation stage runs
// its anchors on threads of its own), so results do not depend on the number of threads.
#include <complex>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

// automatic: the normal equations when well conditioned, else the QR; qr: always the QR (the
// reference, for tests and benchmarks); normal_equations: always them (unless the Cholesky fails).
// a·b by the BLAS (zgemm, single-threaded): the radiation applies its cached power operators
// this way (tyre_radiation.cpp), 4-5× faster than Eigen's product compiled for the baseline
// instruction set (issue 12: it was half of a warm run's radiation). Its sums run in the
// kernel's order, not Eigen's: the products differ from Eigen's in the last bits (1e-16
// relative), the same on every run on one processor.
Eigen::MatrixXcd blas_product(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b);

enum class LeastSquaresMethod { automatic, qr, normal_equations };

class RegularisedLeastSquares {
 public:
  // Forms AᴴA. A (m × n, m, n ≥ 1) is kept: the normal equations apply Aᴴ and A.
  explicit RegularisedLeastSquares(Eigen::MatrixXcd a, LeastSquaresMethod method = LeastSquaresMethod::automatic);

  // σ_max(A)², by 30 steps of power iteration on AᴴA from `start` (n): to set λ relative to it.
  double largest_singular_value_squared(Eigen::VectorXcd start) const;
  // Factorises for the given λ ≥ 0 (once, before solve / apply_pseudo_inverse_right).
  void factorise(double lambda);

  // q for right-hand sides b (m × K): n × K.
  Eigen::MatrixXcd solve(const Eigen::MatrixXcd& b) const;
  // X A⁺ for X (K × n): K × m, with A⁺ = (AᴴA + λ²I)⁻¹Aᴴ the regularised pseudo-inverse.
  Eigen::MatrixXcd apply_pseudo_inverse_right(const Eigen::MatrixXcd& x) const;
  // The columns `keep` of X A⁺ only (K × keep.size(), in that order). The normal equations form
  // just those columns, (A_keep G⁻¹Xᴴ)ᴴ with A_keep the rows `keep` of A: the power operator keeps
  // the tread's coordinates, 2/5 of the split mesh's points, and forming the others was 60 % of
  // its largest product. Each kept entry is the same sum over the same n terms as in the full
  // product. The QR forms all columns and picks them.
  Eigen::MatrixXcd apply_pseudo_inverse_right(const Eigen::MatrixXcd& x, const std::vector<Eigen::Index>& keep) const;

  Eigen::Index rows() const noexcept { return a_.rows(); }
  Eigen::Index columns() const noexcept { return a_.cols(); }
  // Whether the normal equations were kept (else the QR).
  bool normal_equations() const noexcept { return normal_; }
  // The reciprocal condition estimate of AᴴA + λ²I (zpocon; 0 if the Cholesky failed).
  double reciprocal_condition() const noexcept { return rcond_; }

 private:
  Eigen::MatrixXcd a_;       // A
  Eigen::MatrixXcd factor_;  // AᴴA, then its Cholesky factor L (lower); or zgeqrf's output for [A; λI]
  std::vector<std::complex<double>> tau_;  // QR: the reflectors' scalars
  LeastSquaresMethod method_;
  bool factorised_ = false;
  bool normal_ = true;
  double rcond_ = 0.0;
};

}  // namespace rollnoise
