#pragma once
// The static contact under a load W (MODEL.md §2, "Preload and start"): the indentation d of
// the body towards a flat road such that the contact forces, the solution of the LCP
//   F ≥ 0,  gap = h − d + C·F ≥ 0,  Fᵀ·gap = 0,
// add up to W. ΣF(d) is piecewise linear and increasing in d: the secant of two trials on the
// same contact set (Newton's step on that set), kept inside a regula-falsi bracket, ends on the
// exact d. The trials share one PMatrixLcpSolver, warm-started and with its factor kept.
#include <Eigen/Core>

namespace rollnoise {

struct StaticContact {
  double indentation = 0.0;  // d, m
  Eigen::VectorXd force;     // N, per point
};

// `compliance`: the static compliance, a P-matrix (symmetric positive definite for a body at
// rest; non-symmetric for a rolling, damped one); `undeformed_gap`: h per point at d = 0 (m);
// `load`: W ≥ 0 (N).
StaticContact solve_static_contact(const Eigen::MatrixXd& compliance,
                                   const Eigen::VectorXd& undeformed_gap, double load);

}  // namespace rollnoise
