#pragma once
// The per-step contact of a rolling tyre with a nonlinear tread (F = k·δⁿ per point, MODEL.md
// §4), over the points that can touch. The KINSOL problem (nonlinear_spring_contact.hpp) is
// dense in its points, and a contact window has a thousand, most of them clear of the road: the
// problem is solved on the candidates, the points that penetrate with no force (q < 0) and those
// in contact a step before, and any point whose gap the solution closes joins them for another
// solve. The result is the solution of the whole window.
//
// The rolling tyre now solves its steps and steady state by TreadNewtonContact
// (tread_newton_contact.hpp: 2.5 ms a step against this one's 7.2 s on plate_rough_80kmh,
// docs/performance.md); this solver is the reference the tests compare it with (NonlinearTreadSolver::kinsol).
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class NonlinearTreadContact {
 public:
  // structural: the structure's instantaneous compliance A (P × P); stiffness: k_p (N/m^n);
  // exponent n ≥ 1. require_symmetric as for NonlinearSpringContact.
  NonlinearTreadContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                        bool require_symmetric = true);

  // F ≥ 0 with gap = q + A·F + δ ≥ 0, F·gap = 0, δ = (F/k)^{1/n}.
  const Eigen::VectorXd& solve(const Eigen::Ref<const Eigen::VectorXd>& q);
  const Eigen::VectorXd& force() const noexcept { return force_; }
  const Eigen::VectorXd& compression() const noexcept { return compression_; }  // δ
  const Eigen::VectorXd& gap() const noexcept { return gap_; }
  int iterations() const noexcept { return iterations_; }  // Newton iterations, all sub-solves

 private:
  Eigen::MatrixXd a_;
  Eigen::VectorXd k_;
  double exponent_;
  bool require_symmetric_;
  Eigen::VectorXd force_, compression_, gap_;
  Eigen::VectorXd previous_compression_;  // the warm start of the next sub-problem
  std::vector<char> candidate_;
  int iterations_ = 0;
};

}  // namespace rollnoise
