// The nonlinear tread's semismooth Newton (tread_newton_contact.hpp) against the KINSOL
// reference (nonlinear_tread_contact.hpp) on the same problems: dense, on random patches, and
// with FFT products on the rolling plate's G0 over a sequence of steps on a rough road, the
// warm start moved with the road as in the rolling loop. n = 1 against the exact linear LCP.
//
// Tolerances. Both solvers stop at round-off of the gap (1e-13·‖q‖∞ here, KINSOL's polish at
// its noise level), so the KKT residual max|min(δ, gap)| is checked at 1e-11·‖q‖∞ (the brief's
// 1e-10 with a margin). The forces differ by the gap error divided by the contact's stiffness,
// i.e. about cond(A + C)·1e-13 relative; 1e-8 of max F leaves room for a condition number of
// 1e5, far above what these patches have (about 10 scaled by their diagonal).
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact/contact_matrix_structure.hpp"
#include "contact/nonlinear_tread_contact.hpp"
#include "contact/pmatrix_lcp.hpp"
#include "contact/rolling_modes.hpp"
#include "contact/tread_newton_contact.hpp"
#include "rolling_test_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "rolling_test_roads.hpp"

namespace rollnoise {
namespace {

// Recorded in the test XML (gtest --gtest_output=xml) for the measured accuracies.
std::string sci(double value) {
  std::ostringstream text;
  text.precision(2);
  text << std::scientific << value;
  return text.str();
}

// max_p |min(δ_p, gap_p)| with gap = q + A·F + δ recomputed densely, over max|q|; and F ≥ 0.
double kkt_residual(const Eigen::MatrixXd& a, const Eigen::VectorXd& q, const Eigen::VectorXd& force,
                    const Eigen::VectorXd& delta) {
  const Eigen::VectorXd gap = q + a * force + delta;
  double worst = 0.0;
  for (Eigen::Index p = 0; p < q.size(); ++p) {
    worst = std::max(worst, std::abs(std::min(delta(p), gap(p))));
    if (force(p) < 0.0 || delta(p) < 0.0) return INFINITY;
  }
  return worst / q.cwiseAbs().maxCoeff();
}

// A patch of nx × ny points 5 mm apart with a structural compliance that decays with distance
// (an exponential kernel: positive definite in any dimension), about 1 µm/N at a point.
struct Patch {
  Eigen::MatrixXd a;
  Eigen::VectorXd q;
};

Patch make_patch(int nx, int ny, std::mt19937_64& rng) {
  const Eigen::Index size = Eigen::Index{nx} * ny;
  Patch patch{Eigen::MatrixXd(size, size), Eigen::VectorXd(size)};
  const auto x = [nx](Eigen::Index p) { return 5e-3 * static_cast<double>(p % nx); };
  const auto y = [nx](Eigen::Index p) { return 5e-3 * static_cast<double>(p / nx); };
  for (Eigen::Index p = 0; p < size; ++p)
    for (Eigen::Index r = 0; r < size; ++r)
      patch.a(p, r) = 1e-6 * std::exp(-std::hypot(x(p) - x(r), y(p) - y(r)) / 0.02);
  // A tyre's undeformed gap pressed 1 mm into a rough road.
  std::uniform_real_distribution<double> roughness(-2e-4, 2e-4);
  const double cx = 0.5 * x(size - 1), cy = 0.5 * y(size - 1);
  for (Eigen::Index p = 0; p < size; ++p)
    patch.q(p) = (std::pow(x(p) - cx, 2) + std::pow(y(p) - cy, 2)) / (2 * 0.3) - 1e-3 + roughness(rng);
  return patch;
}

TEST(TreadNewtonContact, MatchesKinsolOnRoughPatches) {
  std::mt19937_64 rng(7);
  double worst_force = 0.0, worst_kkt = 0.0;
  for (const double exponent : {1.0, 1.5, 2.0, 2.5, 2.7, 3.0}) {
    // Soft, comparable and stiff springs against the structure (k·δ^{n−1} at δ = 0.1 mm against
    // 1/A_pp = 1e6 N/m).
    for (const double relative : {0.05, 1.0, 30.0}) {
      const Patch patch = make_patch(9, 7, rng);
      const double k = relative * 1e6 / std::pow(1e-4, exponent - 1.0);
      const Eigen::VectorXd stiffness = Eigen::VectorXd::Constant(patch.q.size(), k);
      NonlinearTreadContact reference(patch.a, stiffness, exponent);
      TreadNewtonContact newton(patch.a, stiffness, exponent);
      const Eigen::VectorXd& expected = reference.solve(patch.q);
      const Eigen::VectorXd& force = newton.solve(patch.q);
      ASSERT_GT(expected.maxCoeff(), 0.0);
      // The rough road leaves some points out of contact inside the patch.
      EXPECT_LT((expected.array() > 0.0).count(), patch.q.size());
      EXPECT_LE((force - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.maxCoeff())
          << "n = " << exponent << ", stiffness ×" << relative;
      worst_force = std::max(worst_force, (force - expected).cwiseAbs().maxCoeff() / expected.maxCoeff());
      worst_kkt = std::max(worst_kkt, kkt_residual(patch.a, patch.q, force, newton.compression()));
      EXPECT_LE(kkt_residual(patch.a, patch.q, force, newton.compression()), 1e-11)
          << "n = " << exponent << ", stiffness ×" << relative;
      EXPECT_LE((newton.gap() - (patch.q + patch.a * force + newton.compression())).cwiseAbs().maxCoeff(),
                1e-12 * patch.q.cwiseAbs().maxCoeff());
      EXPECT_GE(newton.iterations(), 1);
    }
  }
  RecordProperty("worst_force_difference", sci(worst_force));
  RecordProperty("worst_kkt_residual", sci(worst_kkt));
}

TEST(TreadNewtonContact, NonSymmetricComplianceMatchesKinsol) {
  // The steady-rolling compliance: damping skews it (here by 5 % of its largest entry, with a
  // positive-definite symmetric part); BiCGSTAB instead of CG, max |gap| as the merit.
  std::mt19937_64 rng(13);
  for (const double exponent : {1.0, 1.5, 2.3}) {
    Patch patch = make_patch(9, 7, rng);
    const Eigen::Index size = patch.q.size();
    Eigen::MatrixXd skew(size, size);
    for (Eigen::Index p = 0; p < size; ++p)
      for (Eigen::Index r = 0; r < size; ++r) skew(p, r) = std::tanh(5e-3 * static_cast<double>(p - r) / 0.01);
    patch.a += 0.05 * 1e-6 * skew;  // antisymmetric: the symmetric part stays positive definite
    const Eigen::VectorXd stiffness = Eigen::VectorXd::Constant(size, 1e6 / std::pow(1e-4, exponent - 1.0));
    NonlinearTreadContact reference(patch.a, stiffness, exponent, /*require_symmetric=*/false);
    TreadNewtonContact newton(patch.a, stiffness, exponent, {}, /*require_symmetric=*/false);
    EXPECT_THROW(TreadNewtonContact(patch.a, stiffness, exponent), std::invalid_argument);
    const Eigen::VectorXd& expected = reference.solve(patch.q);
    const Eigen::VectorXd& force = newton.solve(patch.q);
    EXPECT_LE((force - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.maxCoeff()) << "n = " << exponent;
    EXPECT_LE(kkt_residual(patch.a, patch.q, force, newton.compression()), 1e-11) << "n = " << exponent;
    // And again from there, warm, for a nearby q.
    const Eigen::VectorXd nearby = patch.q.array() - 2e-5;
    EXPECT_LE((newton.solve(nearby) - reference.solve(nearby)).cwiseAbs().maxCoeff(), 1e-8 * expected.maxCoeff());
  }
}

TEST(TreadNewtonContact, ExponentOneIsTheLinearLcp) {
  // F = k·δ: gap = q + (A + diag(1/k))·F, the LCP of the Winkler tread.
  std::mt19937_64 rng(11);
  const Patch patch = make_patch(10, 6, rng);
  std::uniform_real_distribution<double> spread(0.5, 2.0);
  Eigen::VectorXd stiffness(patch.q.size());
  for (Eigen::Index p = 0; p < stiffness.size(); ++p) stiffness(p) = 1e6 * spread(rng);
  const Eigen::MatrixXd m = patch.a + Eigen::MatrixXd(stiffness.cwiseInverse().asDiagonal());
  const PMatrixLcpResult lcp = solve_pmatrix_lcp(m, patch.q);
  TreadNewtonContact newton(patch.a, stiffness, 1.0);
  newton.solve(patch.q);
  EXPECT_LE((newton.force() - lcp.z).cwiseAbs().maxCoeff(), 1e-10 * lcp.z.maxCoeff());
}

// The rolling plate's G0 (symmetric part) on a 16 × 4 window, the road moving one cell a step.
TEST(TreadNewtonContact, WindowProductsMatchKinsolStepByStep) {
  const KroppPlate plate(test::small_plate(0.1));
  const TyreGrid grid = test::small_grid();
  const double speed = 22.2;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd g0 = rolling.sheared_lag(0);
  const Eigen::MatrixXd s = 0.5 * (g0 + g0.transpose());
  const Eigen::Index points = grid.points();
  std::vector<Eigen::Index> shift_back(static_cast<std::size_t>(points), -1);
  for (int j = 0; j < grid.lateral; ++j)
    for (int i = 1; i < grid.window; ++i) shift_back[static_cast<std::size_t>(i + grid.window * j)] = i - 1 + grid.window * j;
  ASSERT_TRUE(matrix_unchanged_by(s, shift_back));
  const test::Bumps road;
  const Eigen::VectorXd h = grid.undeformed_gap();
  for (const double exponent : {1.5, 2.0}) {
    // Deflections comparable with the Winkler tread's 4e8 N/m³ at these loads.
    const Eigen::VectorXd stiffness =
        Eigen::VectorXd::Constant(points, 4e8 * grid.dx() * grid.dy() / std::pow(1e-3, exponent - 1.0));
    NonlinearTreadContact reference(s, stiffness, exponent);
    TreadNewtonContact newton(s, stiffness, exponent, ContactWindow{grid.window, grid.lateral});
    double worst_force = 0.0, worst_kkt = 0.0;
    int iterations = 0;
    for (int step = 0; step < 40; ++step) {
      Eigen::VectorXd q(points);
      for (int j = 0; j < grid.lateral; ++j)
        for (int i = 0; i < grid.window; ++i)
          q(i + grid.window * j) = h(i + grid.window * j) - 4e-3 -
                                   road.height(grid.x(i) + step * grid.dx(), grid.y(j) - 0.5 * grid.width);
      if (step > 0) newton.relabel(shift_back);  // the road moved a cell: so did the contacts
      const Eigen::VectorXd& expected = reference.solve(q);
      const Eigen::VectorXd& force = newton.solve(q);
      ASSERT_GT(expected.maxCoeff(), 0.0);
      worst_force = std::max(worst_force, (force - expected).cwiseAbs().maxCoeff() / expected.maxCoeff());
      worst_kkt = std::max(worst_kkt, kkt_residual(s, q, force, newton.compression()));
      iterations += newton.iterations();
    }
    EXPECT_LE(worst_force, 1e-8) << "n = " << exponent;
    EXPECT_LE(worst_kkt, 1e-11) << "n = " << exponent;
    const std::string tag = "_n" + std::to_string(static_cast<int>(10 * exponent));
    RecordProperty("worst_force_difference" + tag, sci(worst_force));
    RecordProperty("worst_kkt_residual" + tag, sci(worst_kkt));
    RecordProperty("newton_iterations_per_step_n" + std::to_string(static_cast<int>(10 * exponent)), iterations / 40);
    // This coarse window (29 mm cells) moves the contact by whole asperities a step: a few
    // exchanges of the contact set of a few Newton iterations each.
    EXPECT_LE(iterations, 40 * 20) << "n = " << exponent;
  }
}

TEST(TreadNewtonContact, ZeroQAndFarFromTheRoad) {
  std::mt19937_64 rng(3);
  const Patch patch = make_patch(5, 4, rng);
  const Eigen::VectorXd stiffness = Eigen::VectorXd::Constant(patch.q.size(), 1e8);
  TreadNewtonContact newton(patch.a, stiffness, 1.5);
  EXPECT_EQ(newton.solve(Eigen::VectorXd::Zero(patch.q.size())).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd clear = Eigen::VectorXd::Constant(patch.q.size(), 1e-3);
  EXPECT_EQ(newton.solve(clear).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(newton.iterations(), 0);
  EXPECT_LE((newton.gap() - clear).cwiseAbs().maxCoeff(), 0.0);
}

TEST(TreadNewtonContact, RejectsBadArguments) {
  std::mt19937_64 rng(5);
  const Patch patch = make_patch(4, 3, rng);
  const Eigen::Index size = patch.q.size();
  const Eigen::VectorXd k = Eigen::VectorXd::Constant(size, 1e8);
  Eigen::MatrixXd skew = patch.a;
  skew(0, 1) *= 1.01;
  EXPECT_THROW(TreadNewtonContact(skew, k, 1.5), std::invalid_argument);
  EXPECT_THROW(TreadNewtonContact(patch.a, k.head(size - 1), 1.5), std::invalid_argument);
  EXPECT_THROW(TreadNewtonContact(patch.a, -k, 1.5), std::invalid_argument);
  EXPECT_THROW(TreadNewtonContact(patch.a, k, 0.5), std::invalid_argument);
  EXPECT_THROW(TreadNewtonContact(patch.a, k, 1.5, ContactWindow{5, 3}), std::invalid_argument);
  TreadNewtonContact newton(patch.a, k, 1.5);
  EXPECT_THROW(newton.solve(Eigen::VectorXd::Zero(size + 1)), std::invalid_argument);
  Eigen::VectorXd nan_q = patch.q;
  nan_q(2) = NAN;
  EXPECT_THROW(newton.solve(nan_q), std::invalid_argument);
  EXPECT_THROW(newton.warm_start(Eigen::VectorXd::Zero(size - 1)), std::invalid_argument);
  EXPECT_THROW(newton.relabel(std::vector<Eigen::Index>(static_cast<std::size_t>(size + 1), -1)), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
