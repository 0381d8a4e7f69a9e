#include "contact/static_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "contact/illinois_bracket.hpp"
#include "contact/pmatrix_lcp.hpp"

namespace rollnoise {

StaticContact solve_static_contact(const Eigen::MatrixXd& compliance,
                                   const Eigen::VectorXd& undeformed_gap, double load) {
  if (!(load >= 0.0)) throw std::invalid_argument("static load must be >= 0");
  const Eigen::Index n = undeformed_gap.size();
  const double touch = undeformed_gap.minCoeff();  // below this d nothing touches
  StaticContact result{touch, Eigen::VectorXd::Zero(n)};
  if (load == 0.0) return result;

  // The trials' LCPs share the matrix, and their q = h − d differ by a constant: one solver,
  // each solve warm-started from the last contact set, whose block stays factorised across the
  // trials (bordered_lu.hpp). A fresh dense factorisation per pivoting iteration of every trial,
  // and two more for the bracket and the slope, were a third of a 0.2 s tyre run (issue 13).
  PMatrixLcpSolver lcp(compliance, std::min<Eigen::Index>(n, 128));
  Eigen::VectorXd q(n);
  auto excess = [&](double d) {
    q = (undeformed_gap.array() - d).matrix();
    return lcp.solve(q).z.sum() - load;
  };
  // A bracket [lo, hi] with ΣF(lo) ≤ W ≤ ΣF(hi). The first guess takes the points as uncoupled
  // and all in contact (Σ 1/C_ii per metre, stiffer than the coupled body), doubled until it
  // carries the load.
  IllinoisBracket bracket =
      bracket_by_doubling(touch, -load, load / compliance.diagonal().cwiseInverse().sum(), INFINITY,
                          "static contact: no indentation carries the load", excess);
  // ΣF(d) is piecewise linear and increasing, linear on each contact set: two trials on the same
  // set give the exact root of that piece by their secant (Newton's step with the slope
  // 1ᵀ·C_AA⁻¹·1, without a factorisation of its own). Otherwise regula falsi on the bracket.
  double d = bracket.hi, f = bracket.f_hi;
  std::vector<char> last_set = lcp.result().basic;
  double last_d = d, last_f = f;
  bool have_last = false;
  for (int iteration = 0; iteration < 200 && std::abs(f) > 1e-14 * load; ++iteration) {
    double next = bracket.regula_falsi();
    if (have_last && lcp.result().basic == last_set && d != last_d) {
      const double secant = d - f * (d - last_d) / (f - last_f);
      if (secant >= bracket.lo && secant <= bracket.hi) next = secant;
    }
    if (!(next > bracket.lo && next < bracket.hi)) next = 0.5 * (bracket.lo + bracket.hi);
    if (next == d || bracket.hi - bracket.lo <= 1e-15 * std::abs(bracket.hi)) break;
    last_set = lcp.result().basic;
    last_d = d;
    last_f = f;
    have_last = true;
    d = next;
    f = excess(d);
    bracket.narrow(d, f);
  }
  result.indentation = d;
  result.force = lcp.result().z;
  return result;
}

}  // namespace rollnoise
