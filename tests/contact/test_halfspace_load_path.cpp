// The exact load path of one contact cell (halfspace_load_path.hpp) against an independent
// solver, the constrained conjugate gradients of HalfspaceTextureContact, at approaches along the
// path; against Hertz; and its bounds: the law never falls, and never beats the flat punch.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "contact/halfspace_load_path.hpp"
#include "contact/halfspace_texture_contact.hpp"

namespace rollnoise {
namespace {

constexpr double E = 4e6;
constexpr double nu = 0.45;

// F at approach δ on the piecewise linear path.
double force_at(const std::vector<LoadPathPoint>& path, double approach) {
  for (std::size_t e = 1; e < path.size(); ++e)
    if (approach <= path[e].approach) {
      const LoadPathPoint& a = path[e - 1];
      const LoadPathPoint& b = path[e];
      return b.approach > a.approach ? a.force + (b.force - a.force) * (approach - a.approach) / (b.approach - a.approach)
                                     : b.force;
    }
  return path.back().force;
}

std::vector<double> random_texture(std::size_t n, double rms, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, rms);
  std::vector<double> h(n);
  for (double& v : h) v = normal(rng);
  return h;
}

TEST(HalfspaceLoadPath, AgreesWithConjugateGradientsAlongThePath) {
  // A cell of 4 × 15 pixels of 0.5 mm (2 mm × 7.5 mm, a contact cell at 80 km/h) over a random
  // texture of 0.1 mm rms, up to full contact.
  const std::size_t nx = 4, ny = 15;
  const double px = 5e-4;
  HalfspaceLoadPath path_solver(nx, ny, px, px, E, nu);
  const HalfspaceTextureContact reference(nx, ny, px, px, E, nu);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::vector<double> h = random_texture(nx * ny, 1e-4, seed);
    const std::vector<LoadPathPoint> path = path_solver.trace(h, 200.0);
    ASSERT_GE(path.size(), 3u);
    const double end = path.back().approach;
    for (double fraction : {0.002, 0.01, 0.05, 0.2, 0.5, 0.9}) {
      const double approach = fraction * end;
      const HalfspaceContactResult r = reference.solve(h, approach, 1e-12, 5000);
      ASSERT_TRUE(r.converged);
      EXPECT_NEAR(force_at(path, approach), r.force, 1e-6 * r.force + 1e-12) << "seed " << seed << ", δ = " << approach;
    }
  }
}

TEST(HalfspaceLoadPath, HertzSphere) {
  // A paraboloid of R = 10 mm on 40 × 40 pixels of 10 µm: F = (4/3)E*√R·δ^{3/2} (2 %) where
  // the contact radius √(Rδ) spans 8 to 15 pixels.
  const std::size_t n = 40;
  const double px = 1e-5, radius = 0.01;
  std::vector<double> h(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double x = (static_cast<double>(i) - 19.5) * px, y = (static_cast<double>(j) - 19.5) * px;
      h[i * n + j] = -(x * x + y * y) / (2.0 * radius);
    }
  HalfspaceLoadPath solver(n, n, px, px, E, nu);
  const double e_star = E / (1.0 - nu * nu);
  const double apex = (2.0 * 0.25 * px * px) / (2.0 * radius);  // the highest pixels sit this far below the apex
  const std::vector<LoadPathPoint> path = solver.trace(h, 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(2.5e-6, 1.5));
  for (double approach : {0.65e-6, 1.2e-6, 2.2e-6}) {
    const double hertz = 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(approach, 1.5);
    EXPECT_NEAR(force_at(path, approach - apex) / hertz, 1.0, 0.02) << "δ = " << approach;
  }
}

TEST(HalfspaceLoadPath, NeverFallsAndNeverBeatsTheFlatPunch) {
  const std::size_t nx = 6, ny = 20;
  HalfspaceLoadPath solver(nx, ny, 4e-4, 4e-4, E, nu);
  // A flat cell is the punch itself: F = δ / c_punch from the first touch.
  const std::vector<double> flat(nx * ny, 1e-4);
  const std::vector<LoadPathPoint> punch = solver.trace(flat, 10.0);
  ASSERT_EQ(punch.size(), 2u);
  EXPECT_EQ(punch.back().contacts, static_cast<int>(nx * ny));
  EXPECT_NEAR(punch.back().approach, 10.0 * solver.punch_compliance(), 1e-12 * punch.back().approach);
  // A rough cell: δ ≥ c_punch·F at every event (the energy argument of
  // docs/physics/contact.md), and F and δ increase along the path.
  const std::vector<LoadPathPoint> path = solver.trace(random_texture(nx * ny, 2e-4, 7), 50.0);
  for (std::size_t e = 1; e < path.size(); ++e) {
    EXPECT_GE(path[e].approach, path[e - 1].approach);
    EXPECT_GE(path[e].force, path[e - 1].force);
    EXPECT_GE(path[e].approach, solver.punch_compliance() * path[e].force * (1.0 - 1e-12));
  }
  EXPECT_DOUBLE_EQ(path.back().force, 50.0);
}

TEST(HalfspaceLoadPath, RejectsBadInput) {
  HalfspaceLoadPath solver(2, 2, 1e-4, 1e-4, E, nu);
  EXPECT_THROW(solver.trace(std::vector<double>(3, 0.0), 1.0), std::invalid_argument);
  EXPECT_THROW(solver.trace(std::vector<double>{0.0, NAN, 0.0, 0.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(solver.trace(std::vector<double>(4, 0.0), 0.0), std::invalid_argument);
  EXPECT_THROW(HalfspaceLoadPath(0, 2, 1e-4, 1e-4, E, nu), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
