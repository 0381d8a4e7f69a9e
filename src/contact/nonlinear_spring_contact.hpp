#pragma once
// The per-step contact problem with nonlinear contact springs for small-scale roughness
// (Andersson & Kropp 2008; MODEL.md §4): each contact point p has a local spring
// F_p = k_p·δ_p^n (δ_p ≥ 0 its compression) in series with the linear structure, whose
// instantaneous compliance is A = G_s[0] (structural part only; symmetric positive
// semi-definite). With the known part q = h − d + u⁰ − r the gap is
//   gap(δ) = q + A·(k ∘ δⁿ) + δ
// and the problem is the nonlinear complementarity problem δ ≥ 0, gap ≥ 0, δ·gap = 0 (F > 0
// exactly where δ > 0). KINSOL (Newton with line search, dense Jacobian) solves its
// Fischer–Burmeister reformulation φ(y_p/s, gap_p/s) = 0 in the rescaled compression
// y_p = δ_p + A_pp·F_p(δ_p), which has the sign of δ_p and keeps Newton well conditioned from soft
// to very stiff springs (in δ itself it stalls when the springs are much stiffer than the
// structure); s = ‖q‖∞. For n = 1 the problem is the linear LCP with compliance A + diag(1/k).
#include <memory>

#include <Eigen/Core>

namespace rollnoise {

class NonlinearSpringContact {
 public:
  // structural: A (P × P, symmetric PSD); stiffness: k_p > 0 (N/m^n); exponent: n ≥ 1.
  // require_symmetric = false admits a non-symmetric A with a positive-definite symmetric part
  // (the compliance of steady rolling): I + A·diag(D) is then still non-singular.
  NonlinearSpringContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                         bool require_symmetric = true);
  ~NonlinearSpringContact();
  NonlinearSpringContact(const NonlinearSpringContact&) = delete;
  NonlinearSpringContact& operator=(const NonlinearSpringContact&) = delete;

  // The next solve starts from these compressions δ ≥ 0 (m) instead of the previous solution's:
  // the last step's, for a solver made for this step's points.
  void warm_start(const Eigen::Ref<const Eigen::VectorXd>& compression);

  // Solves for q (m), warm-started from the previous solution. Returns the forces F (N).
  // Throws std::runtime_error if KINSOL fails to converge.
  const Eigen::VectorXd& solve(const Eigen::Ref<const Eigen::VectorXd>& q);

  const Eigen::VectorXd& force() const noexcept;        // F = k ∘ δⁿ
  const Eigen::VectorXd& compression() const noexcept;  // δ
  const Eigen::VectorXd& gap() const noexcept;          // gap(δ) ≥ 0
  int iterations() const noexcept;                      // Newton iterations of the last solve

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollnoise
