#include "greens/tread_compliance.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollnoise {
namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string(what) + " must be finite and > 0");
  }
}

void require_elastic(double youngs_modulus, double poisson_ratio) {
  require_positive(youngs_modulus, "Young's modulus");
  // ν = 0.5 (incompressible rubber) is a valid limit: the surface Green's function only needs
  // 1 − ν² > 0.
  if (!(poisson_ratio >= 0.0 && poisson_ratio <= 0.5)) {
    throw std::invalid_argument("Poisson's ratio must lie in [0, 0.5]");
  }
}

// An antiderivative of 1/√(u² + v²) in u and v (∂²F/∂u∂v = 1/r):
//   F(u, v) = u·asinh(v/|u|) + v·asinh(u/|v|).
// It is the form of Love (1929) / Johnson (1985, §3.3) with the functions of one variable
// (−u ln|u|, −v ln|v|) removed, which makes F odd in u and in v, continuous everywhere and
// F(0, v) = F(u, 0) = 0: the limits u·ln|u| → 0 at an edge or corner need no special case.
double corner_term(double u, double v) {
  double sum = 0.0;
  if (u != 0.0) {
    const double t = v / std::abs(u);
    // |u| below 1e-308·|v|: the term is ~u·ln(2|v|/|u|), negligible, and t overflowed.
    if (std::isfinite(t)) sum += u * std::asinh(t);
  }
  if (v != 0.0) {
    const double t = u / std::abs(v);
    if (std::isfinite(t)) sum += v * std::asinh(t);
  }
  return sum;
}

// ∬ dξdη/√((x−ξ)² + (y−η)²) over |ξ| ≤ a, |η| ≤ b. Boussinesq: a point force P gives
// w = (1 − ν²)·P/(πE·r) (Johnson 1985, §3.2), so a uniform pressure p on the rectangle gives
// w = (1 − ν²)·p/(πE) times this integral, which is F summed over the corners of
// [x−a, x+a] × [y−b, y+b] (Love 1929). It is even in x and y: evaluating at |x|, |y| makes the
// computed value exactly even too, hence an exactly symmetric compliance. Far away the corner
// terms cancel to O(ab/r): the relative round-off grows like 1e-16·(r/a)², ~1e-11 at r = 1000a,
// which is harmless for contact grids.
double love_integral(double x, double y, double a, double b) {
  x = std::abs(x);
  y = std::abs(y);
  return corner_term(x + a, y + b) - corner_term(x - a, y + b) - corner_term(x + a, y - b) +
         corner_term(x - a, y - b);
}

}  // namespace

Eigen::MatrixXd winkler_compliance(Eigen::Index points, double cell_dx, double cell_dy,
                                   double stiffness_per_area) {
  if (points < 0) throw std::invalid_argument("number of points must be >= 0");
  require_positive(cell_dx, "cell dx");
  require_positive(cell_dy, "cell dy");
  require_positive(stiffness_per_area, "Winkler stiffness per area");
  // Each point is a spring of stiffness k_w·dx·dy, independent of its neighbours.
  const double compliance = 1.0 / (stiffness_per_area * cell_dx * cell_dy);
  return Eigen::MatrixXd::Identity(points, points) * compliance;
}

double love_rectangle_displacement(double x, double y, double a, double b, double youngs_modulus,
                                   double poisson_ratio) {
  require_positive(a, "rectangle half-width a");
  require_positive(b, "rectangle half-width b");
  require_elastic(youngs_modulus, poisson_ratio);
  if (!std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("point must be finite");
  return (1.0 - poisson_ratio * poisson_ratio) / (std::numbers::pi * youngs_modulus) *
         love_integral(x, y, a, b);
}

Eigen::MatrixXd halfspace_compliance(const Eigen::MatrixX2d& positions, double cell_dx, double cell_dy,
                                     double youngs_modulus, double poisson_ratio) {
  require_positive(cell_dx, "cell dx");
  require_positive(cell_dy, "cell dy");
  require_elastic(youngs_modulus, poisson_ratio);
  if (!positions.allFinite()) throw std::invalid_argument("positions must be finite");
  const Eigen::Index n = positions.rows();
  // A unit force on cell q is the pressure 1/(dx·dy) over that cell.
  const double scale = (1.0 - poisson_ratio * poisson_ratio) /
                       (std::numbers::pi * youngs_modulus * cell_dx * cell_dy);
  const double a = 0.5 * cell_dx;
  const double b = 0.5 * cell_dy;
  Eigen::MatrixXd c(n, n);
  for (Eigen::Index q = 0; q < n; ++q) {
    for (Eigen::Index p = q; p < n; ++p) {
      const double value = scale * love_integral(positions(p, 0) - positions(q, 0),
                                                 positions(p, 1) - positions(q, 1), a, b);
      // Reciprocity (equal cells, w even in x and y): one evaluation fills both triangles,
      // so C is exactly symmetric.
      c(p, q) = value;
      c(q, p) = value;
    }
  }
  return c;
}

}  // namespace rollnoise
