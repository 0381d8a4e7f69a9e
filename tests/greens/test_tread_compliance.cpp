// Local compliance of the tread (MODEL.md §4, "Local deformation of the tread"): Love's
// rectangle formula against closed forms, the Boussinesq far field and independent quadrature;
// the assembled half-space compliance against Hertz theory through the static contact solver;
// the Winkler bedding against its paraboloid solution.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "gauss_legendre.hpp"
#include "contact/static_contact.hpp"
#include "greens/tread_compliance.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

constexpr double kE = 10e6;   // Pa, a soft tread rubber
constexpr double kNu = 0.5;   // incompressible
const double kLove = (1.0 - kNu * kNu) / (pi * kE);  // (1 − ν²)/(πE), m/N per m (Boussinesq)

// ---------------------------------------------------------------------------------------------
// Independent quadrature of the Boussinesq kernel over the rectangle |ξ| ≤ a, |η| ≤ b.

using Rule = test::GaussRule;
using test::gauss_legendre;

// Composite Gauss–Legendre of f over [lo, hi] with `panels` panels.
template <class F>
double composite(F f, double lo, double hi, int panels, const Rule& rule) {
  double sum = 0.0;
  const double h = (hi - lo) / panels;
  for (int k = 0; k < panels; ++k) {
    const double mid = lo + (k + 0.5) * h;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      sum += rule.weights[i] * f(mid + 0.5 * h * rule.nodes[i]);
  }
  return 0.5 * h * sum;
}

// ∬ 1/r over the rectangle for a point outside it: the kernel is smooth there, so a tensor
// Gauss–Legendre rule converges geometrically (64 panels of 8 nodes: panel ≤ 1/30 of the side,
// the points below are ≥ 0.2·a away, error far below 1e-12).
double quadrature_outside(double x, double y, double a, double b) {
  const Rule rule = gauss_legendre(8);
  return composite(
      [&](double xi) {
        return composite([&](double eta) { return 1.0 / std::hypot(x - xi, y - eta); }, -b, b, 64,
                         rule);
      },
      -a, a, 64, rule);
}

// ∬ 1/r over the rectangle for a point inside it or on its boundary: in polar coordinates about
// the point the singularity cancels (dA/r = dρ dθ), leaving ∮ ρ(θ) dθ with ρ the distance to the
// boundary along θ, smooth between the corner directions (which are the panel breaks).
double quadrature_inside(double x, double y, double a, double b) {
  const Rule rule = gauss_legendre(10);
  auto rho = [&](double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    double t = INFINITY;
    if (c > 0.0) t = std::min(t, (a - x) / c);
    if (c < 0.0) t = std::min(t, (-a - x) / c);
    if (s > 0.0) t = std::min(t, (b - y) / s);
    if (s < 0.0) t = std::min(t, (-b - y) / s);
    return t;
  };
  std::vector<double> breaks{0.0, 2.0 * pi};
  for (double cx : {-a, a})
    for (double cy : {-b, b}) {
      if (cx == x && cy == y) continue;
      double theta = std::atan2(cy - y, cx - x);
      if (theta < 0.0) theta += 2.0 * pi;
      breaks.push_back(theta);
    }
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
    if (breaks[k + 1] > breaks[k]) sum += composite(rho, breaks[k], breaks[k + 1], 64, rule);
  return sum;
}

TEST(LoveRectangle, CentreAndCornerOfASquare) {
  // Square 2a × 2a, centre: ∬ dA/r = 8 triangles ∫_0^{π/4} ∫_0^{a/cos θ} dρ dθ
  // = 8a·∫_0^{π/4} sec θ dθ = 8a·ln(1 + √2). (Often quoted as 4·c·ln(1 + √2) for the side
  // c = 2a.) The corner is a quarter of the centre of the 4a × 4a square: 4a·ln(1 + √2).
  for (double a : {1e-3, 0.01, 0.37}) {
    const double centre = kLove * 8.0 * a * std::log(1.0 + std::sqrt(2.0));
    EXPECT_NEAR(love_rectangle_displacement(0.0, 0.0, a, a, kE, kNu), centre, 1e-14 * centre);
    const double corner = 0.5 * centre;
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0})
        EXPECT_NEAR(love_rectangle_displacement(sx * a, sy * a, a, a, kE, kNu), corner, 1e-14 * corner);
  }
  // (1 − ν²)/E scaling.
  EXPECT_NEAR(love_rectangle_displacement(0.0, 0.0, 0.01, 0.01, 2e6, 0.3),
              (1.0 - 0.09) / (pi * 2e6) * 0.08 * std::log(1.0 + std::sqrt(2.0)), 1e-20);
}

TEST(LoveRectangle, TendsToBoussinesqFarAway) {
  const double a = 0.01, b = 0.006;
  const double force = 4.0 * a * b;  // unit pressure
  double worst_ratio = 0.0;  // |relative − quadrupole|/(a/r)⁴
  for (double phi : {0.0, 0.4, pi / 4.0, 1.3, pi / 2.0}) {
    for (double r_over_a : {10.0, 30.0, 100.0, 300.0}) {
      const double r = r_over_a * a;
      const double x = r * std::cos(phi), y = r * std::sin(phi);
      const double w = love_rectangle_displacement(x, y, a, b, kE, kNu);
      const double boussinesq = kLove * force / r;
      const double relative = w / boussinesq - 1.0;
      // O((a/r)²) as required...
      EXPECT_LT(std::abs(relative), (a * a + b * b) / (r * r)) << "phi " << phi << " r/a " << r_over_a;
      // ...and it is the quadrupole term of 1/|r − s| averaged over the rectangle
      // (⟨s_x²⟩ = a²/3, ⟨s_y²⟩ = b²/3): [(3cos²φ − 1)a² + (3sin²φ − 1)b²]/(6r²). The rest is
      // the hexadecapole term, measured ≤ 0.09·(a/r)⁴ here at every r (so it is not noise);
      // beyond r ≈ 100a the cancellation between the corner terms (round-off ~1e-16·(r/a)²
      // relative, 6e-12 at 300a) becomes comparable, so the O(a⁴/r⁴) check stops at 100a.
      if (r_over_a > 100.0) continue;
      const double c = std::cos(phi), s = std::sin(phi);
      const double quadrupole = ((3.0 * c * c - 1.0) * a * a + (3.0 * s * s - 1.0) * b * b) / (6.0 * r * r);
      worst_ratio = std::max(worst_ratio, std::abs(relative - quadrupole) / std::pow(a / r, 4.0));
      EXPECT_NEAR(relative, quadrupole, 0.15 * std::pow(a / r, 4.0)) << "phi " << phi << " r/a " << r_over_a;
    }
  }
  std::printf("  max |w/w_B - 1 - quadrupole| / (a/r)^4 = %.3g\n", worst_ratio);
}

TEST(LoveRectangle, EvenInXAndY) {
  const double a = 0.01, b = 0.006;
  for (double x : {0.0, 0.003, 0.01, 0.017, 0.2})
    for (double y : {0.0, 0.002, 0.006, 0.05}) {
      const double w = love_rectangle_displacement(x, y, a, b, kE, kNu);
      EXPECT_GT(w, 0.0);
      EXPECT_EQ(love_rectangle_displacement(-x, y, a, b, kE, kNu), w);
      EXPECT_EQ(love_rectangle_displacement(x, -y, a, b, kE, kNu), w);
      EXPECT_EQ(love_rectangle_displacement(-x, -y, a, b, kE, kNu), w);
      // Swapping the axes together with the rectangle's sides.
      EXPECT_NEAR(love_rectangle_displacement(y, x, b, a, kE, kNu), w, 1e-15 * w);
    }
}

TEST(LoveRectangle, ContinuousAcrossEdgesAndCorners) {
  const double a = 0.01, b = 0.006;
  const double centre = love_rectangle_displacement(0.0, 0.0, a, b, kE, kNu);
  // Points on an edge or a corner, and just either side: w is continuous with a derivative
  // that is only log-singular, so |Δw| ≲ (1−ν²)/(πE)·ε·ln(a/ε) ≈ 1e-7 of w for ε = 1e-9·a.
  const double eps = 1e-9 * a;
  struct Point {
    double x, y;
  };
  for (const Point p : {Point{a, 0.0}, Point{a, 0.3 * b}, Point{0.0, b}, Point{-0.7 * a, -b}, Point{a, b},
                        Point{-a, b}}) {
    const double w = love_rectangle_displacement(p.x, p.y, a, b, kE, kNu);
    ASSERT_TRUE(std::isfinite(w));
    for (double dx : {-eps, 0.0, eps})
      for (double dy : {-eps, 0.0, eps}) {
        const double near = love_rectangle_displacement(p.x + dx, p.y + dy, a, b, kE, kNu);
        ASSERT_TRUE(std::isfinite(near));
        EXPECT_NEAR(near, w, 1e-7 * centre) << p.x << ", " << p.y;
      }
  }
  // Tiny and huge offsets stay finite (no 0·∞ in the logarithms).
  EXPECT_TRUE(std::isfinite(love_rectangle_displacement(a + 1e-300, b, a, b, kE, kNu)));
  EXPECT_TRUE(std::isfinite(love_rectangle_displacement(1e12, 0.0, a, b, kE, kNu)));
}

TEST(LoveRectangle, AgreesWithQuadratureOfBoussinesqKernel) {
  const double a = 0.01, b = 0.006;
  struct Point {
    double x, y;
  };
  // Outside: tensor Gauss–Legendre. Both rules converge geometrically (smooth integrands on
  // each panel); measured agreement with the closed form is ~1e-15, so 1e-12 relative is
  // round-off with margin (the brief asked for ~1e-6).
  double worst = 0.0;
  for (const Point p : {Point{1.2 * a, 0.0}, Point{3.0 * a, 0.5 * b}, Point{1.4 * a, 1.5 * b},
                        Point{0.2 * a, -1.4 * b}, Point{-8.0 * a, 5.0 * b}}) {
    const double expected = kLove * quadrature_outside(p.x, p.y, a, b);
    worst = std::max(worst, std::abs(love_rectangle_displacement(p.x, p.y, a, b, kE, kNu) / expected - 1.0));
    EXPECT_NEAR(love_rectangle_displacement(p.x, p.y, a, b, kE, kNu), expected, 1e-12 * expected)
        << p.x << ", " << p.y;
  }
  // Inside and on the boundary: polar coordinates about the (singular) point.
  for (const Point p : {Point{0.0, 0.0}, Point{0.3 * a, 0.2 * b}, Point{-0.7 * a, 0.5 * b},
                        Point{0.95 * a, -0.9 * b}, Point{a, 0.3 * b}, Point{-0.4 * a, -b}, Point{a, b}}) {
    const double expected = kLove * quadrature_inside(p.x, p.y, a, b);
    worst = std::max(worst, std::abs(love_rectangle_displacement(p.x, p.y, a, b, kE, kNu) / expected - 1.0));
    EXPECT_NEAR(love_rectangle_displacement(p.x, p.y, a, b, kE, kNu), expected, 1e-12 * expected)
        << p.x << ", " << p.y;
  }
  std::printf("  max relative difference from quadrature: %.2g\n", worst);
}

TEST(LoveRectangle, RejectsInvalidInput) {
  EXPECT_THROW(love_rectangle_displacement(0, 0, 0.0, 1.0, kE, kNu), std::invalid_argument);
  EXPECT_THROW(love_rectangle_displacement(0, 0, 1.0, -1.0, kE, kNu), std::invalid_argument);
  EXPECT_THROW(love_rectangle_displacement(0, 0, 1.0, 1.0, 0.0, kNu), std::invalid_argument);
  EXPECT_THROW(love_rectangle_displacement(0, 0, 1.0, 1.0, kE, 0.6), std::invalid_argument);
  EXPECT_THROW(love_rectangle_displacement(0, 0, 1.0, 1.0, kE, -0.1), std::invalid_argument);
  EXPECT_THROW(love_rectangle_displacement(NAN, 0, 1.0, 1.0, kE, kNu), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Assembled compliances.

// Centres of the cells of a square grid of pitch h that lie within `radius` of the origin (a
// cell centre at the origin): the contact of a sphere never leaves that disc, so the other
// cells would only enlarge the dense problem.
struct Grid {
  Eigen::MatrixX2d positions;
  std::vector<int> i, j;  // integer cell indices
};

Grid disc_grid(double h, double radius) {
  const int half = static_cast<int>(std::ceil(radius / h));
  Grid grid;
  for (int i = -half; i <= half; ++i)
    for (int j = -half; j <= half; ++j)
      if (std::hypot(i * h, j * h) <= radius) {
        grid.i.push_back(i);
        grid.j.push_back(j);
      }
  grid.positions.resize(static_cast<Eigen::Index>(grid.i.size()), 2);
  for (std::size_t k = 0; k < grid.i.size(); ++k) {
    grid.positions(static_cast<Eigen::Index>(k), 0) = grid.i[k] * h;
    grid.positions(static_cast<Eigen::Index>(k), 1) = grid.j[k] * h;
  }
  return grid;
}

// The axisymmetric contact on the disc grid, reduced by the grid's 8 symmetries (x → −x,
// y → −y, x ↔ y). The problem is invariant under them and its solution unique (strictly
// convex QP), so the solution is symmetric: one unknown per orbit, G_I = total force of orbit I
// (m_I cells). Then gap_I = h_I − d + Σ_J B_IJ·G_J with
//   B_IJ = Σ_{p∈I} Σ_{q∈J} C_pq / (m_I·m_J),
// symmetric and positive definite (C restricted to symmetric loads), and ΣG = W: the same
// solve_static_contact applies to ~1/8 of the unknowns (the dense active-set solve on all
// ~2400 cells takes ~10 s per load, on the orbits well under 1 s).
struct Folded {
  Eigen::MatrixXd compliance;   // B
  Eigen::VectorXd gap;          // h per orbit
  Eigen::VectorXd multiplicity; // m_I
  Eigen::VectorXd radius;       // r of the orbit's cells
  std::vector<Eigen::Index> orbit;  // per cell
};

Folded fold(const Grid& grid, const Eigen::MatrixXd& c, const Eigen::VectorXd& gap) {
  const Eigen::Index n = grid.positions.rows();
  std::vector<Eigen::Index> orbit(static_cast<std::size_t>(n));
  std::vector<std::pair<int, int>> keys;
  for (Eigen::Index p = 0; p < n; ++p) {
    const int u = std::abs(grid.i[static_cast<std::size_t>(p)]);
    const int v = std::abs(grid.j[static_cast<std::size_t>(p)]);
    const std::pair<int, int> key{std::max(u, v), std::min(u, v)};
    const auto found = std::find(keys.begin(), keys.end(), key);
    orbit[static_cast<std::size_t>(p)] = found - keys.begin();
    if (found == keys.end()) keys.push_back(key);
  }
  const auto m = static_cast<Eigen::Index>(keys.size());
  Folded folded{Eigen::MatrixXd::Zero(m, m), Eigen::VectorXd::Zero(m), Eigen::VectorXd::Zero(m),
                Eigen::VectorXd::Zero(m), orbit};
  for (Eigen::Index p = 0; p < n; ++p) {
    const Eigen::Index op = orbit[static_cast<std::size_t>(p)];
    folded.multiplicity(op) += 1.0;
    folded.gap(op) = gap(p);
    folded.radius(op) = grid.positions.row(p).norm();
    for (Eigen::Index q = 0; q < n; ++q) folded.compliance(op, orbit[static_cast<std::size_t>(q)]) += c(p, q);
  }
  for (Eigen::Index a = 0; a < m; ++a)
    for (Eigen::Index b = 0; b < m; ++b)
      folded.compliance(a, b) /= folded.multiplicity(a) * folded.multiplicity(b);
  // Exact symmetry for the LCP's check (the two summation orders differ in the last bits).
  folded.compliance = (0.5 * (folded.compliance + folded.compliance.transpose())).eval();
  return folded;
}

TEST(HalfspaceCompliance, IsLoveOverCellAreaAndSymmetric) {
  Eigen::MatrixX2d positions(5, 2);
  positions << 0.0, 0.0, 0.004, 0.0, 0.0, 0.003, -0.012, 0.009, 0.004, 0.003;
  const double dx = 0.004, dy = 0.003;
  const Eigen::MatrixXd c = halfspace_compliance(positions, dx, dy, kE, kNu);
  ASSERT_EQ(c.rows(), 5);
  ASSERT_EQ(c.cols(), 5);
  for (Eigen::Index p = 0; p < 5; ++p)
    for (Eigen::Index q = 0; q < 5; ++q) {
      EXPECT_EQ(c(p, q), c(q, p));
      const double expected = love_rectangle_displacement(positions(p, 0) - positions(q, 0),
                                                          positions(p, 1) - positions(q, 1), dx / 2,
                                                          dy / 2, kE, kNu) /
                              (dx * dy);
      EXPECT_NEAR(c(p, q), expected, 1e-15 * expected);
    }
  // Strictly positive definite (the contact LCP needs it).
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c).eigenvalues().minCoeff(), 0.0);
  EXPECT_THROW(halfspace_compliance(positions, 0.0, dy, kE, kNu), std::invalid_argument);
  EXPECT_THROW(halfspace_compliance(positions, dx, dy, -1.0, kNu), std::invalid_argument);
  EXPECT_EQ(halfspace_compliance(Eigen::MatrixX2d(0, 2), dx, dy, kE, kNu).size(), 0);
}

TEST(WinklerCompliance, IsDiagonalSprings) {
  const Eigen::MatrixXd c = winkler_compliance(4, 0.002, 0.003, 5e9);
  ASSERT_EQ(c.rows(), 4);
  ASSERT_EQ(c.cols(), 4);
  for (Eigen::Index p = 0; p < 4; ++p)
    for (Eigen::Index q = 0; q < 4; ++q)
      EXPECT_EQ(c(p, q), p == q ? 1.0 / (5e9 * 0.002 * 0.003) : 0.0);
  EXPECT_THROW(winkler_compliance(4, 0.0, 0.003, 5e9), std::invalid_argument);
  EXPECT_THROW(winkler_compliance(4, 0.002, -0.003, 5e9), std::invalid_argument);
  EXPECT_THROW(winkler_compliance(4, 0.002, 0.003, 0.0), std::invalid_argument);
  EXPECT_THROW(winkler_compliance(-1, 0.002, 0.003, 5e9), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Hertz: a rigid paraboloid h = r²/(2R) on the discretised half-space (Johnson 1985, §4.2):
//   a = (3WR/(4E*))^{1/3},  δ = a²/R = (9W²/(16RE*²))^{1/3},  p(r) = p0·√(1 − r²/a²),
//   p0 = 3W/(2πa²),  E* = E/(1 − ν²).

constexpr double kRadius = 0.02;                      // m
const double kEStar = kE / (1.0 - kNu * kNu);         // Pa
constexpr double kMaxContactRadius = 0.004;           // m, at the largest load
constexpr double kCellsPerMaxRadius = 24.0;           // grid pitch: a_max/24

double hertz_load_for_radius(double a) { return 4.0 * kEStar * a * a * a / (3.0 * kRadius); }

TEST(HalfspaceCompliance, SymmetryReductionIsExact) {
  // The reduction used below against the full problem on a coarse grid (a/h ≈ 8).
  const double h = kMaxContactRadius / 8.0;
  const Grid grid = disc_grid(h, 1.15 * kMaxContactRadius);
  const Eigen::MatrixXd c = halfspace_compliance(grid.positions, h, h, kE, kNu);
  const Eigen::VectorXd gap = grid.positions.rowwise().squaredNorm() / (2.0 * kRadius);
  const Folded folded = fold(grid, c, gap);
  const double load = hertz_load_for_radius(kMaxContactRadius);
  const StaticContact full = solve_static_contact(c, gap, load);
  const StaticContact reduced = solve_static_contact(folded.compliance, folded.gap, load);
  EXPECT_NEAR(reduced.indentation, full.indentation, 1e-10 * full.indentation);
  // Every cell carries its orbit's share.
  const double max_force = full.force.maxCoeff();
  ASSERT_GT(max_force, 0.0);
  for (Eigen::Index p = 0; p < grid.positions.rows(); ++p) {
    const Eigen::Index o = folded.orbit[static_cast<std::size_t>(p)];
    EXPECT_NEAR(full.force(p), reduced.force(o) / folded.multiplicity(o), 1e-10 * max_force);
  }
}

TEST(HalfspaceCompliance, HertzSphere) {
  const double h = kMaxContactRadius / kCellsPerMaxRadius;
  const Grid grid = disc_grid(h, 1.15 * kMaxContactRadius);
  const Eigen::MatrixXd c = halfspace_compliance(grid.positions, h, h, kE, kNu);
  const Eigen::VectorXd gap = grid.positions.rowwise().squaredNorm() / (2.0 * kRadius);
  const Folded folded = fold(grid, c, gap);
  std::printf("  %ld cells (%ld orbits), cell %.4g mm\n", static_cast<long>(grid.positions.rows()),
              static_cast<long>(folded.gap.size()), h * 1e3);

  std::vector<double> loads, depths;
  // Contact radii of 0.55, 0.7, 0.85 and 1.0 a_max: 13 to 24 cells.
  for (double fraction : {0.55, 0.7, 0.85, 1.0}) {
    const double load = hertz_load_for_radius(fraction * kMaxContactRadius);
    const StaticContact contact = solve_static_contact(folded.compliance, folded.gap, load);
    const double a_hertz = std::cbrt(3.0 * load * kRadius / (4.0 * kEStar));
    const double delta_hertz = std::cbrt(9.0 * load * load / (16.0 * kRadius * kEStar * kEStar));
    double cells_in_contact = 0.0;
    for (Eigen::Index o = 0; o < contact.force.size(); ++o)
      if (contact.force(o) > 0.0) cells_in_contact += folded.multiplicity(o);
    const double a_area = std::sqrt(cells_in_contact * h * h / pi);
    const double delta_error = contact.indentation / delta_hertz - 1.0;
    const double a_error = a_area / a_hertz - 1.0;
    // Pressure against Hertz inside 0.8·a, as a fraction of p0.
    const double p0 = 3.0 * load / (2.0 * pi * a_hertz * a_hertz);
    double pressure_error = 0.0;
    for (Eigen::Index o = 0; o < contact.force.size(); ++o) {
      const double r = folded.radius(o);
      if (r > 0.8 * a_hertz) continue;
      const double hertz = p0 * std::sqrt(1.0 - r * r / (a_hertz * a_hertz));
      const double pressure = contact.force(o) / (folded.multiplicity(o) * h * h);
      pressure_error = std::max(pressure_error, std::abs(pressure - hertz) / p0);
    }
    std::printf("  W = %8.3f N, a/h = %4.1f: delta error %+.5f, a error %+.5f, max |p - p_H|/p0 "
                "(r < 0.8a) %.5f\n",
                load, a_hertz / h, delta_error, a_error, pressure_error);
    // The requirement: 2 %. (Measured: δ within 0.03 %, a within 0.6 %: the area
    // count is a lattice sum over the circle, error ~ perimeter/area ~ h/a.)
    EXPECT_LT(std::abs(delta_error), 0.02) << "W = " << load;
    EXPECT_LT(std::abs(a_error), 0.02) << "W = " << load;
    // Piecewise-constant pressure collocated at cell centres: measured < 0.1 % of p0 away from
    // the edge; 2 % bounds it with margin.
    EXPECT_LT(pressure_error, 0.02) << "W = " << load;
    EXPECT_NEAR(contact.force.sum(), load, 1e-10 * load);
    loads.push_back(load);
    depths.push_back(contact.indentation);
  }
  // W ∝ δ^{3/2}: least-squares slope of ln W against ln δ.
  const double n = static_cast<double>(loads.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const double lx = std::log(depths[k]), ly = std::log(loads[k]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  std::printf("  log-log slope of W(delta): %.4f (Hertz 1.5)\n", slope);
  EXPECT_NEAR(slope, 1.5, 0.03 * 1.5);
}

// Winkler bedding under the same paraboloid: the springs inside r < a = √(2Rδ) carry
// W = ∫ k_w·(δ − r²/2R) dA = π·k_w·R·δ².
TEST(WinklerCompliance, ParaboloidOnBedding) {
  const double h = kMaxContactRadius / kCellsPerMaxRadius;
  const Grid grid = disc_grid(h, 1.15 * kMaxContactRadius);
  const double k_w = 5e9;  // N/m³
  const Eigen::MatrixXd c = winkler_compliance(grid.positions.rows(), h, h, k_w);
  const Eigen::VectorXd gap = grid.positions.rowwise().squaredNorm() / (2.0 * kRadius);
  // Reduced by symmetry as for Hertz (B = diag(1/(k_w·h²·m_I))).
  const Folded folded = fold(grid, c, gap);
  for (double fraction : {0.55, 0.7, 0.85, 1.0}) {
    const double a = fraction * kMaxContactRadius;
    const double delta = a * a / (2.0 * kRadius);
    const double load = pi * k_w * kRadius * delta * delta;
    const StaticContact contact = solve_static_contact(folded.compliance, folded.gap, load);
    const double error = contact.indentation / delta - 1.0;
    std::printf("  Winkler a/h = %4.1f: delta error %+.5f\n", a / h, error);
    // The cell sum Σ(δ − r_i²/2R)⁺·h² is the midpoint rule of the integral with a kink on the
    // circle r = a: a lattice-point error, at most O((h/a)^{3/2}) ≈ 1e-2 relative in W and
    // half that in δ ∝ √W; measured ≤ 1.2e-4 at a/h = 13…24, so 0.5 % is a safe bound.
    EXPECT_LT(std::abs(error), 0.005) << "a/h = " << a / h;
    // Each spring in contact carries its own share: F_i = k_w·h²·(δ − h_i).
    for (Eigen::Index o = 0; o < folded.gap.size(); ++o)
      EXPECT_NEAR(contact.force(o),
                  folded.multiplicity(o) * k_w * h * h * std::max(contact.indentation - folded.gap(o), 0.0),
                  1e-9 * load);
  }
}

}  // namespace
}  // namespace rollnoise
