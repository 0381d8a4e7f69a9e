#include "contact/static_contact.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>

#include "contact/pmatrix_lcp.hpp"

namespace rollnoise {

StaticContact solve_static_contact(const Eigen::MatrixXd& compliance,
                                   const Eigen::VectorXd& undeformed_gap, double load) {
  if (!(load >= 0.0)) throw std::invalid_argument("static load must be >= 0");
  const Eigen::Index n = undeformed_gap.size();
  const double touch = undeformed_gap.minCoeff();  // below this d nothing touches
  StaticContact result{touch, Eigen::VectorXd::Zero(n)};
  if (load == 0.0) return result;

  Eigen::VectorXd force = Eigen::VectorXd::Zero(n);
  // Each solve starts from the last one's contact set: the indentations tried converge.
  std::vector<char> basic;
  auto total_at = [&](double d) {
    PMatrixLcpResult r = solve_pmatrix_lcp(compliance, (undeformed_gap.array() - d).matrix(),
                                           basic.empty() ? nullptr : &basic);
    force = std::move(r.z);
    basic = std::move(r.basic);
    return force.sum();
  };
  // First guess: every point in contact.
  const double all_in = compliance.partialPivLu().solve(Eigen::VectorXd::Ones(n)).sum();
  double lo = touch;
  double hi = touch + load / std::abs(all_in);
  while (total_at(hi) < load) {
    lo = hi;
    hi = touch + 2.0 * (hi - touch);
    if (!std::isfinite(hi)) throw std::runtime_error("static contact: no indentation carries the load");
  }
  double d = hi;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double total = total_at(d);
    if (std::abs(total - load) <= 1e-14 * load) break;
    (total < load ? lo : hi) = d;
    // On the current active set ΣF is linear in d with slope 1ᵀ·C_AA⁻¹·1.
    std::vector<Eigen::Index> active;
    for (Eigen::Index i = 0; i < n; ++i)
      if (force(i) > 0.0) active.push_back(i);
    double next = 0.5 * (lo + hi);
    if (!active.empty()) {
      const auto m = static_cast<Eigen::Index>(active.size());
      Eigen::MatrixXd caa(m, m);
      for (Eigen::Index a = 0; a < m; ++a)
        for (Eigen::Index b = 0; b < m; ++b) caa(a, b) = compliance(active[a], active[b]);
      const double slope = caa.partialPivLu().solve(Eigen::VectorXd::Ones(m)).sum();
      const double newton = d + (load - total) / slope;
      if (newton >= lo && newton <= hi) next = newton;
    }
    if (next == d) break;
    d = next;
  }
  total_at(d);
  result.indentation = d;
  result.force = force;
  return result;
}

}  // namespace rollnoise
