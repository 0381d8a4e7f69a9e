#pragma once
// The per-step contact of a rolling tyre with nonlinear springs in series with the structure,
// solved fast enough for long runs: the nonlinear tread F_p = k_p·δ_p^n (docs/physics/contact.md,
// "The rolling tyre") or any increasing F_p = f_p(δ_p) (point_springs.hpp; the per-cell contact
// laws of the road's fine texture). Written below for the power law; for a general law replace
// k_p^{−1/n}·F^{1+1/n}/(1 + 1/n) by ∫₀^F f_p⁻¹ and n·k_p·δ^{n−1} by f_p'(δ).
//
// The problem (the same as NonlinearTreadContact's, which solves it with KINSOL and stays the
// reference): with the structure's instantaneous compliance A (P × P) and the known part q,
//   (1)  gap = q + A·F + δ,   δ_p ≥ 0,   gap_p ≥ 0,   δ_p·gap_p = 0,   F_p = k_p·δ_p^n.
// For a symmetric positive definite A (a time step) it is the optimality system of the
// strictly convex problem
//   (2)  min_{F ≥ 0} E(F) = ½FᵀAF + qᵀF + Σ_p k_p^{−1/n}·F_p^{1+1/n}/(1 + 1/n),
// whose gradient is A·F + q + δ(F): its solution exists and is unique. For steady rolling A is
// not symmetric (damping) but its symmetric part is positive definite, and (1) is still a
// uniquely solvable complementarity problem (a uniform P-function).
//
// Method. Block principal pivoting over contact sets S, as the linear tread's LCP
// (pmatrix_lcp.cpp; Júdice & Pires 1994): on S, δ = 0 off it exactly and Newton solves gap_S = 0;
// then the points of S pulled into tension (δ_p < 0) leave it and those off it that penetrate
// (gap_p < 0) join it, all at once while their number falls, else one (Murty's rule). Each
// Newton step solves
//   (3)  (A + C)_SS·x_S = −gap_S,   C = diag(dδ_p/dF_p) = diag(1/(n·k_p·δ_p^{n−1})),
// x the linearised force change (Δδ_p = C_p·x_p). A + C is, like the Winkler tread's
// A + diag(1/k), well conditioned by its diagonal: (3) is solved by Jacobi-preconditioned
// conjugate gradients (symmetric A) or BiCGSTAB (van der Vorst, SIAM J. Sci. Stat. Comput. 13
// (1992) 631–644; steady rolling), with the products A·x by FFT on the window
// (window_convolution.hpp) as for the linear tread. Inexactly while the residual is large (the
// forcing term of inexact Newton, Eisenstat & Walker, SIAM J. Sci. Comput. 17 (1996) 16–32),
// to the final tolerance at the end. A point whose sign is violated by more than the residual
// is exchanged without converging the set first (a semismooth Newton step on min(δ, gap), the
// primal–dual active set strategy of Hintermüller, Ito & Kunisch, SIAM J. Optim. 13 (2002)
// 865–888): an exchange that proves wrong is undone in a later round, and only a converged set
// passes the stopping test.
//
// dδ/dF = ∞ at F = 0 for n > 1: a point that enters the contact (δ_p = 0) has no force in the
// linearisation (dF/dδ = 0), so it is left out of (3) and its step follows from its own row,
// Δδ_p = −gap_p − (A·x)_p. The step is applied in the coordinate y_p = δ_p + A_pp·F_p(δ_p)
// (the displacement of point p under its own force; NonlinearSpringContact's coordinate), with
// Δy_p = Δδ_p + A_pp·x_p, and δ_p = δ(y_p) by a scalar inversion: an isolated point is linear in
// y, so Newton does not creep onto stiff springs from above as it does in δ, and an entering
// point lands on its own exact compression. Better still, a point joining S starts there, at
// δ + A_pp·F(δ) = −gap_p, so that Newton's first linearisation couples its force too. On S
// (δ may go negative there, with the odd extension F(−δ) = −F(δ)) a step that raises E
// (symmetric A) or max_S |gap| (otherwise) beyond round-off is halved along y + α·Δy: from a
// cold start the entering points, each at its own compression, together overshoot, and Newton
// would otherwise wander. A full step that halves max_S |gap| is taken without evaluating E
// (Newton's usual case near the solution, and E's per-point integrals are a trial's dearest
// part); the scalar inversions start from Newton's own prediction of each δ.
//
// Each solve starts from the last one's compressions (or those that warm_start() or relabel()
// set), S from the points in contact there and those that penetrate under their forces: between
// time steps the contact set moves by a few points, and Newton then takes a few iterations.
// n = 1 is the linear LCP with compliance A + diag(1/k) (the Winkler tread): Newton is exact on
// each contact set, up to the tolerance of (3).
//
// Stopping test: max_S |gap| ≤ 1e-13·‖q‖∞ and no point off S below −1e-13·‖q‖∞ nor on S with
// δ + A_pp·F below it (the gap its release would open: for a stiff spring a δ of round-off size
// is a large force; the linear tread's LCP stops at the same level), then δ = max(δ, 0). Nothing is
// allocated per solve.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "contact/point_springs.hpp"
#include "contact/window_convolution.hpp"

namespace rollnoise {

class TreadNewtonContact {
 public:
  // structural: A (P × P, symmetric positive definite, or with require_symmetric = false any A
  // with a positive-definite symmetric part); stiffness: k_p > 0 (N/m^n); exponent: n ≥ 1.
  // window: A depends on x_p − x_q only on this window (matrix_unchanged_by checks it), and its
  // products are done by FFT; without it, dense.
  TreadNewtonContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                     std::optional<ContactWindow> window = {}, bool require_symmetric = true);
  // Any springs (point_springs.hpp), one per point; the caller may change what they say between
  // solves (the per-cell contact laws follow the road), keeping them alive while this lives.
  TreadNewtonContact(Eigen::MatrixXd structural, std::shared_ptr<const PointSprings> springs,
                     std::optional<ContactWindow> window = {}, bool require_symmetric = true);
  ~TreadNewtonContact();
  TreadNewtonContact(const TreadNewtonContact&) = delete;
  TreadNewtonContact& operator=(const TreadNewtonContact&) = delete;

  // F ≥ 0 with (1) for this q (m). Throws std::runtime_error if Newton does not converge.
  const Eigen::VectorXd& solve(const Eigen::VectorXd& q);

  // The next solve starts from the compressions of these forces, δ = (F/k)^{1/n}.
  void warm_start(const Eigen::Ref<const Eigen::VectorXd>& force);
  // Moves the warm start: point i's compression goes to new_index[i] (or leaves, < 0); points
  // that receive none start at δ = 0. For a contact set that moves with the road.
  void relabel(const std::vector<Eigen::Index>& new_index);

  const Eigen::VectorXd& force() const noexcept { return force_; }        // F = f(δ), N
  const Eigen::VectorXd& compression() const noexcept { return delta_; }  // δ, m
  const Eigen::VectorXd& gap() const noexcept { return gap_; }            // q + A·F + δ, m
  // The points with F > 0 after the last solve (or δ > 0 of the warm start, once set or moved).
  const std::vector<char>& in_contact() const noexcept { return in_contact_; }
  int iterations() const noexcept { return iterations_; }  // Newton iterations of the last solve
  long cg_iterations() const noexcept { return cg_iterations_; }  // CG/BiCGSTAB, all solves so far

 private:
  // out = A·z (by FFT when the window is known).
  void multiply(const Eigen::VectorXd& z, Eigen::VectorXd& out);
  // force_ and slope_ (dF/dδ) from delta_ at point p, with the odd extension F(−δ) = −F(δ)
  // that Newton may visit.
  void evaluate_spring(Eigen::Index p) { springs_->evaluate(p, delta_(p), force_(p), slope_(p)); }
  // gap_ = q + A·force_ + delta_.
  void evaluate_gap(const Eigen::VectorXd& q);
  // How far a point of the contact set is pulled into tension: y_p = δ_p + A_pp·F_p, the gap it
  // would open if released (δ_p alone understates it for a stiff spring, whose small negative δ
  // is a large tensile force).
  double pull(Eigen::Index p) const { return delta_(p) + a_diagonal_(p) * force_(p); }
  // How many points' columns are cheaper than one product A·F for the whole gap.
  std::size_t column_updates() const noexcept;
  // Sets δ_p = 0 (and F_p = 0) at point p, keeping gap_ = q + A·F + δ.
  void release(Eigen::Index p);
  // What the line search must not raise: the energy (2) at the current forces (from the gap)
  // for a symmetric A, else max_S |gap|; and its round-off level.
  double merit(const Eigen::VectorXd& q) const;
  double merit_noise(const Eigen::VectorXd& q) const;
  // max_S |gap|.
  double set_residual() const;
  // The merit at the compressions before the Newton step (previous_), which it restores.
  double merit_before_step(const Eigen::VectorXd& q);
  // Points that join the contact set start at their own compression (keeping gap_).
  void seed_joining_points(const Eigen::VectorXd& q);
  // Newton on the contact set active_ (gap = 0 there, δ = 0 elsewhere) to `tolerance` (m), or
  // until a point's violation of its sign is certain; returns the residual max_S |gap|.
  double solve_contact_set(const Eigen::VectorXd& q, double tolerance);
  // Solves (3) to `tolerance` (m, max norm of its residual) on the contact set; x_ and ax_ = A·x.
  void newton_system(double tolerance);
  void conjugate_gradients(double tolerance);  // symmetric A
  void bicgstab(double tolerance);             // otherwise

  Eigen::MatrixXd a_;
  Eigen::VectorXd a_diagonal_;
  std::shared_ptr<const PointSprings> springs_;
  bool symmetric_ = true;
  std::unique_ptr<WindowConvolution> product_;

  Eigen::VectorXd delta_, force_, slope_, gap_;
  // Per solve: C's diagonal, the mask of (3) and its preconditioner, the step x and A·x, and the
  // Krylov methods' vectors.
  Eigen::VectorXd compliance_, mask_, inverse_diagonal_, x_, ax_, r_, z_, p_, ap_, mp_;
  Eigen::VectorXd shadow_, s_, hat_s_, at_, t_;  // BiCGSTAB's r̂₀, s, K⁻¹s, A·K⁻¹s, (A + C)·K⁻¹s
  // The Newton step Δy, the coordinate y and δ it starts from (the line search's path).
  Eigen::VectorXd step_, coordinate_, previous_;
  std::vector<char> active_, in_contact_;
  std::vector<Eigen::Index> moved_;  // points whose δ is set outside Newton (leaving or joining)
  Eigen::VectorXd shifted_;
  int iterations_ = 0;
  long cg_iterations_ = 0;
};

}  // namespace rollnoise
