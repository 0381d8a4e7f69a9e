// The per-step LCP (MODEL.md §2): x ≥ 0, w = A·x + q ≥ 0, xᵀw = 0. Checked against the KKT
// conditions on random SPD problems up to n = 1000, against brute-force enumeration of all
// active sets for small n, and on the degenerate cases.
#include <cmath>
#include <random>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "contact/lcp_solver.hpp"

namespace rollnoise {
namespace {

// A random SPD matrix scaled to max |A_ij| ≈ 1, like a contact compliance: a smooth coupling
// (a Gram matrix) plus a local diagonal.
Eigen::MatrixXd random_spd(Eigen::Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(n, n);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
  Eigen::MatrixXd a = b.transpose() * b / static_cast<double>(n);
  a.diagonal().array() += 0.05;
  return a / a.cwiseAbs().maxCoeff();
}

Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) q(i) = normal(rng);
  return q;
}

// KKT residuals, all scaled by the problem's size (|A| ≈ 1, |q| ≈ 1).
struct Kkt {
  double negative_x, negative_w, complementarity;
};

Kkt kkt(const Eigen::MatrixXd& a, const Eigen::VectorXd& q, const Eigen::VectorXd& x) {
  const Eigen::VectorXd w = a * x + q;
  const double scale = q.cwiseAbs().maxCoeff() + a.cwiseAbs().maxCoeff() * x.cwiseAbs().maxCoeff();
  return {std::max(0.0, -x.minCoeff()) / scale, std::max(0.0, -w.minCoeff()) / scale,
          (x.array() * w.array()).abs().maxCoeff() / (scale * std::max(1.0, x.cwiseAbs().maxCoeff()))};
}

class RandomLcp : public ::testing::TestWithParam<int> {};

TEST_P(RandomLcp, MeetsKktConditions) {
  const Eigen::Index n = GetParam();
  std::mt19937_64 rng(1234 + static_cast<unsigned>(n));
  const Eigen::MatrixXd a = random_spd(n, rng);
  LcpSolver solver(a);
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd q = random_vector(n, rng);
    const Eigen::VectorXd x = solver.solve(q);
    const Kkt r = kkt(a, q, x);
    EXPECT_EQ(r.negative_x, 0.0);
    EXPECT_LE(r.negative_w, 1e-10);
    EXPECT_LE(r.complementarity, 1e-10);
    EXPECT_LE((solver.slack() - (a * x + q)).cwiseAbs().maxCoeff(), 1e-10);
    if (n >= 20) {  // a mixed active set, so the test exercises the pivoting
      EXPECT_GT(solver.active_count(), 0);
      EXPECT_LT(solver.active_count(), n);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, RandomLcp, ::testing::Values(1, 2, 5, 20, 100, 400, 1000));

TEST(LcpSolver, AgreesWithBruteForceEnumeration) {
  // For an SPD matrix the LCP has exactly one solution: the one active set whose solution is
  // ≥ 0 with w ≥ 0 off the set. Enumerate all 2^n sets.
  std::mt19937_64 rng(7);
  const Eigen::Index n = 8;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::MatrixXd a = random_spd(n, rng);
    const Eigen::VectorXd q = random_vector(n, rng);
    Eigen::VectorXd expected;
    int found = 0;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
      std::vector<Eigen::Index> set;
      for (Eigen::Index i = 0; i < n; ++i)
        if (mask & (1u << i)) set.push_back(i);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
      if (!set.empty()) {
        const auto m = static_cast<Eigen::Index>(set.size());
        Eigen::MatrixXd aa(m, m);
        Eigen::VectorXd qa(m);
        for (Eigen::Index i = 0; i < m; ++i) {
          qa(i) = q(set[i]);
          for (Eigen::Index j = 0; j < m; ++j) aa(i, j) = a(set[i], set[j]);
        }
        const Eigen::VectorXd xa = aa.ldlt().solve(-qa);
        for (Eigen::Index i = 0; i < m; ++i) x(set[i]) = xa(i);
      }
      const Eigen::VectorXd w = a * x + q;
      if (x.minCoeff() >= -1e-12 && w.minCoeff() >= -1e-12) {
        expected = x;
        ++found;
      }
    }
    ASSERT_EQ(found, 1) << "the enumeration found " << found << " solutions";
    LcpSolver solver(a);
    EXPECT_LE((solver.solve(q) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(LcpSolver, WarmStartGivesTheSameAnswerInFewerChanges) {
  std::mt19937_64 rng(11);
  const Eigen::Index n = 200;
  const Eigen::MatrixXd a = random_spd(n, rng);
  const Eigen::VectorXd q = random_vector(n, rng);
  LcpSolver warm(a);
  warm.solve(q);
  const int cold_changes = warm.iterations();
  // A small change of q, as from one time step to the next.
  const Eigen::VectorXd q2 = q + 1e-3 * random_vector(n, rng);
  const Eigen::VectorXd x_warm = warm.solve(q2);
  LcpSolver cold(a);
  const Eigen::VectorXd x_cold = cold.solve(q2);
  EXPECT_LE((x_warm - x_cold).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(warm.iterations(), cold_changes / 4);
  // The same q again: the warm start is the answer, no change at all.
  warm.solve(q2);
  EXPECT_EQ(warm.iterations(), 0);
}

TEST(LcpSolver, NothingInContact) {
  std::mt19937_64 rng(3);
  const Eigen::MatrixXd a = random_spd(50, rng);
  LcpSolver solver(a);
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(50, 1e-3);
  EXPECT_EQ(solver.solve(q), Eigen::VectorXd::Zero(50));
  EXPECT_EQ(solver.active_count(), 0);
  EXPECT_EQ(solver.slack(), q);
}

TEST(LcpSolver, EverythingInContact) {
  std::mt19937_64 rng(5);
  const Eigen::MatrixXd a = random_spd(50, rng);
  // q = −A·x* with x* > 0: the solution is x*, all active, w = 0.
  const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(50, 1.0, 2.0);
  LcpSolver solver(a);
  const Eigen::VectorXd x = solver.solve(-a * expected);
  EXPECT_EQ(solver.active_count(), 50);
  EXPECT_LE((x - expected).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(LcpSolver, DuplicatePointsShareTheLoadEqually) {
  // Points 1 and 2 at the same place: equal rows of the structural coupling, each with its own
  // local compliance, so A stays positive definite and the load splits equally.
  Eigen::MatrixXd a(3, 3);
  a << 2.0, 1.9, 0.5,  //
      1.9, 2.0, 0.5,   //
      0.5, 0.5, 2.0;
  const Eigen::VectorXd q = Eigen::Vector3d(-1.0, -1.0, 0.2);
  LcpSolver solver(a);
  const Eigen::VectorXd x = solver.solve(q);
  EXPECT_NEAR(x(0), x(1), 1e-15);
  EXPECT_NEAR(x(0), 1.0 / 3.9, 1e-15);  // (a11 + a12)·x = 1
  EXPECT_EQ(x(2), 0.0);
  // Exactly duplicated points with no local compliance (A singular on them): any split is a
  // solution; the solver must still meet the KKT conditions. A is then only semi-definite,
  // which the constructor rejects, so perturb by round-off only.
  Eigen::MatrixXd s(2, 2);
  s << 1.0, 1.0 - 1e-12, 1.0 - 1e-12, 1.0;
  LcpSolver near_singular(s);
  const Eigen::VectorXd y = near_singular.solve(Eigen::Vector2d(-1.0, -1.0));
  const Kkt r = kkt(s, Eigen::Vector2d(-1.0, -1.0), y);
  EXPECT_LE(r.negative_w, 1e-10);
  EXPECT_LE(r.complementarity, 1e-10);
  EXPECT_NEAR(y.sum(), 1.0, 1e-9);
}

TEST(LcpSolver, RejectsMatricesThatAreNotSymmetricPositiveDefinite) {
  Eigen::MatrixXd indefinite(2, 2);
  indefinite << 1.0, 2.0, 2.0, 1.0;
  EXPECT_THROW(LcpSolver{indefinite}, NotPositiveDefiniteError);
  Eigen::MatrixXd asymmetric(2, 2);
  asymmetric << 1.0, 0.1, 0.0, 1.0;
  EXPECT_THROW(LcpSolver{asymmetric}, NotPositiveDefiniteError);
  Eigen::MatrixXd with_nan = Eigen::MatrixXd::Identity(2, 2);
  with_nan(0, 0) = std::nan("");
  EXPECT_THROW(LcpSolver{with_nan}, NotPositiveDefiniteError);
}

}  // namespace
}  // namespace rollnoise
