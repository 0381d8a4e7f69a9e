#include "contact/pmatrix_lcp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/LU>

namespace rollnoise {

PMatrixLcpResult solve_pmatrix_lcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                                   const std::vector<char>* start) {
  const Eigen::Index n = q.size();
  if (m.rows() != n || m.cols() != n) throw std::invalid_argument("P-matrix LCP: sizes differ");
  PMatrixLcpResult result{Eigen::VectorXd::Zero(n), q, 0, {}};
  // Start from the guess, or from the points that penetrate with no force.
  std::vector<char> basic(static_cast<std::size_t>(n), 0);
  if (start && static_cast<Eigen::Index>(start->size()) == n) basic = *start;
  else
    for (Eigen::Index i = 0; i < n; ++i) basic[i] = q(i) < 0.0;
  const double tolerance = 1e-13 * (q.cwiseAbs().maxCoeff() + 1e-300);
  Eigen::Index best = n + 1;
  int backups = 10;
  const int max_iterations = static_cast<int>(10 * n + 100);
  std::vector<Eigen::Index> active;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    active.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (basic[i]) active.push_back(i);
    const auto p = static_cast<Eigen::Index>(active.size());
    result.z.setZero();
    if (p > 0) {
      Eigen::MatrixXd block(p, p);
      Eigen::VectorXd rhs(p);
      for (Eigen::Index a = 0; a < p; ++a) {
        rhs(a) = -q(active[a]);
        for (Eigen::Index b = 0; b < p; ++b) block(a, b) = m(active[a], active[b]);
      }
      const Eigen::VectorXd za = block.partialPivLu().solve(rhs);
      for (Eigen::Index a = 0; a < p; ++a) result.z(active[a]) = za(a);
    }
    result.w = m * result.z + q;
    for (const Eigen::Index i : active) result.w(i) = 0.0;  // zero by construction
    // Infeasible indices: negative z among the basic ones, negative w among the others.
    Eigen::Index infeasible = 0;
    Eigen::Index last = -1;
    for (Eigen::Index i = 0; i < n; ++i) {
      const bool bad = basic[i] ? result.z(i) < -tolerance : result.w(i) < -tolerance;
      if (bad) {
        ++infeasible;
        last = i;
      }
    }
    result.iterations = iteration;
    if (infeasible == 0) {
      result.z = result.z.cwiseMax(0.0);
      result.basic = basic;
      return result;
    }
    if (infeasible < best || backups > 0) {
      if (infeasible < best) {
        best = infeasible;
        backups = 10;
      } else {
        --backups;
      }
      for (Eigen::Index i = 0; i < n; ++i) {
        if (basic[i] ? result.z(i) < -tolerance : result.w(i) < -tolerance) basic[i] = !basic[i];
      }
    } else {
      basic[last] = !basic[last];  // Murty's rule, on the largest infeasible index
    }
  }
  throw std::runtime_error("P-matrix LCP did not converge in " + std::to_string(max_iterations) +
                           " iterations (n = " + std::to_string(n) + "): is the matrix a P-matrix?");
}

}  // namespace rollnoise
