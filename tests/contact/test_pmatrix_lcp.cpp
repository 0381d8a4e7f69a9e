// The P-matrix LCP of the whole-G0 contact step (pmatrix_lcp.hpp) and the bordered LU that keeps
// its factor across steps (bordered_lu.hpp). The dense-LU solve_pmatrix_lcp is checked against
// enumeration of all basic sets; the persistent solver against it, step by step, on a rolling
// sequence of a translation-invariant, non-symmetric matrix like the two-layer tyre's G0.
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "contact/bordered_lu.hpp"
#include "contact/pmatrix_lcp.hpp"
#include "contact/window_convolution.hpp"

namespace rollnoise {
namespace {

// A P-matrix: symmetric positive definite part plus a skew part of relative size `skew`.
Eigen::MatrixXd random_p_matrix(Eigen::Index n, double skew, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(n, n), k(n, n);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
  for (Eigen::Index i = 0; i < k.size(); ++i) k.data()[i] = normal(rng);
  Eigen::MatrixXd m = b.transpose() * b / static_cast<double>(n);
  m.diagonal().array() += 0.05;
  m /= m.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd antisymmetric = 0.5 * (k - k.transpose());
  return m + skew * antisymmetric / antisymmetric.cwiseAbs().maxCoeff();
}

Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) q(i) = normal(rng);
  return q;
}

// The KKT conditions, scaled by |q| and |M|·|z|.
double kkt_violation(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w = m * z + q;
  const double scale = q.cwiseAbs().maxCoeff() + m.cwiseAbs().maxCoeff() * z.cwiseAbs().maxCoeff();
  const double complementarity = (z.array() * w.array()).abs().maxCoeff() / std::max(1.0, z.cwiseAbs().maxCoeff());
  return std::max({-z.minCoeff(), -w.minCoeff(), complementarity, 0.0}) / scale;
}

// M_AA⁻¹·(−q_A) on the indices A of `set` by a dense LU of the block, zero elsewhere: the
// reference for one basic set.
Eigen::VectorXd solve_on_set(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& set, const Eigen::VectorXd& q) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(q.size());
  const auto p = static_cast<Eigen::Index>(set.size());
  if (p == 0) return z;
  Eigen::MatrixXd block(p, p);
  Eigen::VectorXd rhs(p);
  for (Eigen::Index a = 0; a < p; ++a) {
    rhs(a) = -q(set[a]);
    for (Eigen::Index b = 0; b < p; ++b) block(a, b) = m(set[a], set[b]);
  }
  const Eigen::VectorXd za = block.partialPivLu().solve(rhs);
  for (Eigen::Index a = 0; a < p; ++a) z(set[a]) = za(a);
  return z;
}

TEST(PMatrixLcp, AgreesWithEnumerationOfAllBasicSets) {
  // A P-matrix LCP has exactly one solution: the one basic set whose z ≥ 0 with w ≥ 0 off it.
  std::mt19937_64 rng(11);
  const Eigen::Index n = 7;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::MatrixXd m = random_p_matrix(n, 0.4, rng);
    const Eigen::VectorXd q = random_vector(n, rng);
    Eigen::VectorXd expected;
    int found = 0;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
      std::vector<Eigen::Index> set;
      for (Eigen::Index i = 0; i < n; ++i)
        if (mask & (1u << i)) set.push_back(i);
      const Eigen::VectorXd z = solve_on_set(m, set, q);
      const Eigen::VectorXd w = m * z + q;
      bool ok = true;
      for (Eigen::Index i = 0; i < n; ++i) ok = ok && z(i) >= -1e-12 && w(i) >= -1e-12;
      if (ok) {
        expected = z;
        ++found;
      }
    }
    ASSERT_EQ(found, 1) << "trial " << trial;
    EXPECT_LE((solve_pmatrix_lcp(m, q).z - expected).cwiseAbs().maxCoeff(), 1e-12) << "trial " << trial;
    PMatrixLcpSolver solver(m, 3);
    EXPECT_LE((solver.solve(q).z - expected).cwiseAbs().maxCoeff(), 1e-12) << "trial " << trial;
  }
}

TEST(PMatrixLcp, SequenceOfNearbyProblemsMeetsKktAndMatchesTheReference) {
  std::mt19937_64 rng(5);
  const Eigen::Index n = 300;
  const Eigen::MatrixXd m = random_p_matrix(n, 0.2, rng);
  for (const Eigen::Index capacity : {Eigen::Index{0}, Eigen::Index{8}, Eigen::Index{64}}) {
    PMatrixLcpSolver solver(m, capacity);
    Eigen::VectorXd q = random_vector(n, rng);
    for (int step = 0; step < 30; ++step) {
      q += 0.05 * random_vector(n, rng);  // nearby problems: a few indices change state
      const PMatrixLcpResult& fast = solver.solve(q);
      const PMatrixLcpResult reference = solve_pmatrix_lcp(m, q);
      EXPECT_LE(kkt_violation(m, q, fast.z), 1e-10) << "capacity " << capacity << ", step " << step;
      EXPECT_LE((fast.z - reference.z).cwiseAbs().maxCoeff(), 1e-10 * reference.z.cwiseAbs().maxCoeff())
          << "capacity " << capacity << ", step " << step;
      EXPECT_EQ(fast.basic, reference.basic);
    }
    if (capacity == 64) {
      EXPECT_LT(solver.factorisations(), 30) << "the bordered updates were not used";
    }
  }
}

// A contact matrix on a W × L window that depends on x_a − x_b (and the two lateral rows), like
// a rolling tyre's G0: decaying, with a lag along x that makes it non-symmetric.
struct Window {
  int length = 40, lateral = 6;
  Eigen::Index points() const { return Eigen::Index{length} * lateral; }
  Eigen::Index index(int i, int j) const { return i + Eigen::Index{length} * j; }
};

// G(p, q) = kernel(x_p − x_q, y_p − y_q) in cells: translation invariant by construction.
template <class Kernel>
Eigen::MatrixXd window_matrix(const Window& w, Kernel&& kernel) {
  Eigen::MatrixXd m(w.points(), w.points());
  for (int ja = 0; ja < w.lateral; ++ja)
    for (int ia = 0; ia < w.length; ++ia)
      for (int jb = 0; jb < w.lateral; ++jb)
        for (int ib = 0; ib < w.length; ++ib) m(w.index(ia, ja), w.index(ib, jb)) = kernel(ia - ib, ja - jb);
  return m;
}

Eigen::MatrixXd rolling_matrix(const Window& w) {
  return window_matrix(w, [](double dx, double dy) {
    const double r = std::sqrt(dx * dx + dy * dy);
    // Local compliance, a decaying coupling (a positive definite kernel), and a lag that leaves
    // the symmetric part alone: the response trails the load (+x).
    return ((r == 0.0 ? 2.0 : 0.0) + std::exp(-r / 3.0)) * (1.0 + 0.15 * std::tanh(0.5 * dx));
  });
}

std::vector<Eigen::Index> shift_back(const Window& w) {
  std::vector<Eigen::Index> map(static_cast<std::size_t>(w.points()), -1);
  for (int j = 0; j < w.lateral; ++j)
    for (int i = 1; i < w.length; ++i) map[static_cast<std::size_t>(w.index(i, j))] = w.index(i - 1, j);
  return map;
}

TEST(PMatrixLcp, RollingSequenceWithShiftedFactorsMatchesTheReferenceStepByStep) {
  const Window w;
  const Eigen::MatrixXd m = rolling_matrix(w);
  const std::vector<Eigen::Index> shift = shift_back(w);
  ASSERT_TRUE(matrix_unchanged_by(m, shift));
  // A parabolic tyre pressed into a road whose texture moves one cell towards −x per step.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  std::vector<double> road(400);
  for (double& r : road) r = 0.4 * normal(rng);
  PMatrixLcpSolver solver(m, 48);
  std::vector<char> reference_start;
  const int steps = 120;
  for (int step = 0; step < steps; ++step) {
    Eigen::VectorXd q(w.points());
    for (int j = 0; j < w.lateral; ++j)
      for (int i = 0; i < w.length; ++i) {
        const double x = i - 0.5 * w.length;
        q(w.index(i, j)) = 0.02 * x * x - 6.0 - road[static_cast<std::size_t>(i + step) % road.size()] * (1 + j % 2);
      }
    if (step > 0) solver.relabel(shift, true);
    const PMatrixLcpResult& fast = solver.solve(q);
    const PMatrixLcpResult reference = solve_pmatrix_lcp(m, q);
    ASSERT_LE(kkt_violation(m, q, fast.z), 1e-10) << "step " << step;
    ASSERT_LE((fast.z - reference.z).cwiseAbs().maxCoeff(), 1e-10 * reference.z.cwiseAbs().maxCoeff()) << "step " << step;
    const long in_contact = std::count(fast.basic.begin(), fast.basic.end(), 1);
    ASSERT_GT(in_contact, 10);
    ASSERT_LT(in_contact, w.points() - 10);
  }
  EXPECT_LT(solver.factorisations(), steps / 2) << "the shifted factor was not kept";
  // A matrix that is not translation invariant is recognised (its factor is then redone).
  EXPECT_FALSE(matrix_unchanged_by(m + 1e-3 * Eigen::MatrixXd::Identity(w.points(), w.points()).rowwise().reverse(), shift));
}

TEST(BorderedLu, SolvesSetsNearTheBaseAsADenseLuDoes) {
  std::mt19937_64 rng(8);
  const Eigen::Index n = 120;
  auto m = std::make_shared<const Eigen::MatrixXd>(random_p_matrix(n, 0.3, rng));
  BorderedLu lu(m, 40);
  std::uniform_int_distribution<Eigen::Index> pick(0, n - 1);
  std::vector<char> set(static_cast<std::size_t>(n), 0);
  for (Eigen::Index i = 0; i < n; i += 2) set[static_cast<std::size_t>(i)] = 1;
  Eigen::VectorXd z;
  for (int round = 0; round < 60; ++round) {
    for (int flips = 0; flips < 3; ++flips) {
      char& flag = set[static_cast<std::size_t>(pick(rng))];
      flag = !flag;
    }
    const Eigen::VectorXd q = random_vector(n, rng);
    lu.solve(set, q, z);
    std::vector<Eigen::Index> active;
    for (Eigen::Index i = 0; i < n; ++i)
      if (set[static_cast<std::size_t>(i)]) active.push_back(i);
    const Eigen::VectorXd expected = solve_on_set(*m, active, q);
    for (Eigen::Index i = 0; i < n; ++i)
      if (!set[static_cast<std::size_t>(i)]) {
        ASSERT_EQ(z(i), 0.0);
      }
    for (const Eigen::Index i : active)
      ASSERT_NEAR(z(i), expected(i), 1e-10 * expected.cwiseAbs().maxCoeff()) << "round " << round;
  }
  // 180 flips in all, 40 at most kept: a few refactorisations, far fewer than solves.
  EXPECT_GE(lu.factorisations(), 2);
  EXPECT_LE(lu.factorisations(), 20);
}

TEST(BorderedLu, ABaseIndexThatLeavesTheWindowForcesAFreshFactor) {
  const Window w{10, 2};
  auto m = std::make_shared<const Eigen::MatrixXd>(rolling_matrix(w));
  BorderedLu lu(m, 10);
  std::vector<char> set(static_cast<std::size_t>(w.points()), 0);
  set[static_cast<std::size_t>(w.index(0, 0))] = 1;  // leaves with the shift
  set[static_cast<std::size_t>(w.index(5, 1))] = 1;
  Eigen::VectorXd z;
  lu.solve(set, Eigen::VectorXd::Constant(w.points(), -1.0), z);
  EXPECT_EQ(lu.factorisations(), 1);
  lu.relabel(shift_back(w));
  std::vector<char> moved(set.size(), 0);
  moved[static_cast<std::size_t>(w.index(4, 1))] = 1;
  lu.solve(moved, Eigen::VectorXd::Constant(w.points(), -1.0), z);
  EXPECT_EQ(lu.factorisations(), 2);
  EXPECT_NEAR(z(w.index(4, 1)), 1.0 / (*m)(0, 0), 1e-14);
}

// The FFT product against the dense one, m·z, on three random z.
void expect_dense_product(WindowConvolution& product, const Eigen::MatrixXd& m, std::uint64_t seed,
                          const std::string& label) {
  std::mt19937_64 rng(seed);
  Eigen::VectorXd y;
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd z = random_vector(m.rows(), rng);
    product.apply(z, y);
    const Eigen::VectorXd expected = m * z;
    EXPECT_LE((y - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff()) << label;
  }
}

TEST(WindowConvolution, EqualsTheDenseProductOfATranslationInvariantMatrix) {
  for (const Window w : {Window{40, 6}, Window{7, 1}, Window{1, 3}}) {
    const Eigen::MatrixXd m = rolling_matrix(w);
    WindowConvolution product(m, w.length, w.lateral);
    expect_dense_product(product, m, 17, std::to_string(w.length) + " x " + std::to_string(w.lateral));
  }
}

TEST(WindowConvolution, SubtractsAColumnOfTheDenseMatrixFromItsKernel) {
  // Every column of a translation-invariant matrix, lags of both signs, against the dense one.
  for (const Window w : {Window{12, 3}, Window{5, 1}}) {
    const Eigen::MatrixXd m = rolling_matrix(w);
    const WindowConvolution product(m, w.length, w.lateral);
    std::mt19937_64 rng(37);
    const Eigen::VectorXd start = random_vector(m.rows(), rng);
    for (Eigen::Index point = 0; point < m.cols(); ++point) {
      Eigen::VectorXd y = start;
      product.subtract_column(point, 0.75, y);
      const Eigen::VectorXd expected = start - 0.75 * m.col(point);
      EXPECT_LE((y - expected).cwiseAbs().maxCoeff(), 1e-15 * expected.cwiseAbs().maxCoeff()) << "column " << point;
    }
    Eigen::VectorXd y = start;
    EXPECT_THROW(product.subtract_column(m.cols(), 1.0, y), std::invalid_argument);
  }
}

TEST(WindowConvolution, FourBinsARegisterGiveTheSameBitsAsTwo) {
  // The AVX multiply-adds (where the processor has them) against SSE2's, folded (L > 1) and whole.
  for (const Window w : {Window{40, 6}, Window{52, 20}, Window{7, 1}}) {
    const Eigen::MatrixXd m = rolling_matrix(w);
    WindowConvolution wide(m, w.length, w.lateral), narrow(m, w.length, w.lateral);
    if (!wide.use_avx(true)) GTEST_SKIP() << "this processor has no AVX: only the SSE2 products run";
    EXPECT_FALSE(narrow.use_avx(false));
    expect_dense_product(narrow, m, 29, "SSE2, " + std::to_string(w.length) + " x " + std::to_string(w.lateral));
    std::mt19937_64 rng(31);
    Eigen::VectorXd y_wide, y_narrow;
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd z = random_vector(m.rows(), rng);
      wide.apply(z, y_wide);
      narrow.apply(z, y_narrow);
      EXPECT_TRUE(y_wide == y_narrow) << w.length << " x " << w.lateral << ": max difference "
                                      << (y_wide - y_narrow).cwiseAbs().maxCoeff();
    }
  }
}

TEST(WindowConvolution, FoldsALaterallySymmetricMatrixIntoEvenAndOddRowsAndLeavesOthersWhole) {
  // Rows that couple by more than their distance (a tyre stiffer at its shoulders), with the lag
  // along x: symmetric about the centre line, or (with the tilt) not.
  for (const double tilt : {0.0, 0.05})
    for (const Window w : {Window{33, 8}, Window{20, 7}, Window{9, 2}}) {
      const auto kernel = [&](int dx, int ja, int jb) {
        const double centre = ja + jb - (w.lateral - 1.0);
        return (dx == 0 && ja == jb ? 3.0 : 0.0) +
               std::exp(-std::abs(dx) / 3.0 - std::abs(ja - jb) / 2.0) * (1.0 + 0.1 * centre * centre + tilt * ja) *
                   (1.0 + 0.15 * std::tanh(0.5 * dx));
      };
      Eigen::MatrixXd m(w.points(), w.points());
      for (int ja = 0; ja < w.lateral; ++ja)
        for (int ia = 0; ia < w.length; ++ia)
          for (int jb = 0; jb < w.lateral; ++jb)
            for (int ib = 0; ib < w.length; ++ib) m(w.index(ia, ja), w.index(ib, jb)) = kernel(ia - ib, ja, jb);
      WindowConvolution product(m, w.length, w.lateral);
      EXPECT_EQ(product.lateral_symmetry(), tilt == 0.0) << w.length << " x " << w.lateral;
      expect_dense_product(product, m, 23,
                           std::to_string(w.length) + " x " + std::to_string(w.lateral) + ", tilt " + std::to_string(tilt));
    }
}

TEST(PMatrixLcp, WellConditionedSymmetricStepsByConjugateGradientsMatchTheFactor) {
  // A symmetric, strongly diagonally dominant window matrix (a Winkler tread under a belt): the
  // solver takes conjugate gradients with FFT products, and must give the factor's answers.
  const Window w;
  const Eigen::MatrixXd m = window_matrix(w, [](double dx, double dy) {
    return (dx == 0 && dy == 0 ? 5.0 : 0.0) + 0.02 * std::exp(-std::sqrt(dx * dx + dy * dy) / 4.0);
  });
  const std::vector<Eigen::Index> shift = shift_back(w);
  ASSERT_TRUE(matrix_unchanged_by(m, shift));
  PMatrixLcpSolver iterative(m, 48, ContactWindow{w.length, w.lateral});
  PMatrixLcpSolver factorised(m, 48);
  ASSERT_TRUE(iterative.iterative());
  ASSERT_FALSE(factorised.iterative());
  std::mt19937_64 rng(4);
  std::normal_distribution<double> normal;
  std::vector<double> road(300);
  for (double& r : road) r = 0.4 * normal(rng);
  for (int step = 0; step < 60; ++step) {
    Eigen::VectorXd q(w.points());
    for (int j = 0; j < w.lateral; ++j)
      for (int i = 0; i < w.length; ++i) {
        const double x = i - 0.5 * w.length;
        q(w.index(i, j)) = 0.02 * x * x - 3.0 - road[static_cast<std::size_t>(i + step) % road.size()];
      }
    if (step > 0) {
      iterative.relabel(shift, true);
      factorised.relabel(shift, true);
    }
    const PMatrixLcpResult& a = iterative.solve(q);
    const PMatrixLcpResult& b = factorised.solve(q);
    ASSERT_LE(kkt_violation(m, q, a.z), 1e-10) << "step " << step;
    ASSERT_LE((a.z - b.z).cwiseAbs().maxCoeff(), 1e-10 * b.z.cwiseAbs().maxCoeff()) << "step " << step;
    ASSERT_EQ(a.basic, b.basic) << "step " << step;
  }
  EXPECT_EQ(iterative.factorisations(), 0);
  EXPECT_GT(iterative.cg_iterations(), 0);
  // A matrix that is not diagonally dominant keeps the factor.
  EXPECT_FALSE(PMatrixLcpSolver(rolling_matrix(w) + rolling_matrix(w).transpose(), 48, ContactWindow{w.length, w.lateral}).iterative());
}

}  // namespace
}  // namespace rollnoise

namespace rollnoise {
namespace {

// A plate-like window matrix (a Winkler tread's own compliance, coupled smoothly to the whole
// patch by a belt, scaled condition number about 1.6) and a rough road moving under it one cell
// a step: the q of each step.
struct PlateLikeRolling {
  Window w{48, 8};
  Eigen::MatrixXd m = window_matrix(w, [](double dx, double dy) {
    return (dx == 0 && dy == 0 ? 1.0 : 0.0) + 0.004 * std::exp(-std::sqrt(dx * dx + 4.0 * dy * dy) / 5.0);
  });
  std::vector<double> road = [] {
    std::mt19937_64 rng(6);
    std::normal_distribution<double> normal;
    std::vector<double> heights(500);
    for (double& r : heights) r = 0.3 * normal(rng);
    return heights;
  }();
  Eigen::VectorXd q(int step) const {
    Eigen::VectorXd gaps(w.points());
    for (int j = 0; j < w.lateral; ++j)
      for (int i = 0; i < w.length; ++i) {
        const double x = i - 0.5 * w.length;
        gaps(w.index(i, j)) = 0.004 * x * x - 1.0 - road[static_cast<std::size_t>(i + step + 37 * j) % road.size()];
      }
    return gaps;
  }
  // Step `step` for two solvers of this matrix: the road moved on one cell (their warm starts
  // relabelled, after the first step) and solved. Returns the step's q.
  Eigen::VectorXd roll(int step, PMatrixLcpSolver& a, PMatrixLcpSolver& b) const {
    const Eigen::VectorXd gaps = q(step);
    if (step > 0) {
      const std::vector<Eigen::Index> shift = shift_back(w);
      a.relabel(shift, true);
      b.relabel(shift, true);
    }
    a.solve(gaps);
    b.solve(gaps);
    return gaps;
  }
};

TEST(PMatrixLcp, EarlyDecidedExchangesFollowTheExactSolvesPivotForPivot) {
  // Conjugate gradients that stop once a pivoting iteration's exchange is decided must take the
  // exact solves' path, pivot for pivot, and end at the same solution, which the dense reference
  // confirms (to the last solve's residual of 1e-11 rather than 1e-13).
  const PlateLikeRolling rolling;
  const Window& w = rolling.w;
  const Eigen::MatrixXd& m = rolling.m;
  PMatrixLcpSolver early(m, 48, ContactWindow{w.length, w.lateral});
  PMatrixLcpSolver exact(m, 48, ContactWindow{w.length, w.lateral});
  early.correct_warm_start(false);  // the same first set as the exact solves'
  exact.decide_early(false);
  ASSERT_TRUE(early.iterative());
  long pivots = 0;
  for (int step = 0; step < 150; ++step) {
    const Eigen::VectorXd q = rolling.roll(step, early, exact);
    const PMatrixLcpResult& a = early.result();
    const PMatrixLcpResult& b = exact.result();
    const PMatrixLcpResult reference = solve_pmatrix_lcp(m, q);
    ASSERT_EQ(a.iterations, b.iterations) << "step " << step;
    ASSERT_EQ(a.basic, b.basic) << "step " << step;
    ASSERT_EQ(a.basic, reference.basic) << "step " << step;
    // The KKT conditions to 1e-10 with a margin: the last solve stops at a residual of 1e-11.
    ASSERT_LE(kkt_violation(m, q, a.z), 2e-11) << "step " << step;
    ASSERT_LE((a.z - b.z).cwiseAbs().maxCoeff(), 1e-10 * b.z.cwiseAbs().maxCoeff()) << "step " << step;
    ASSERT_LE((a.z - reference.z).cwiseAbs().maxCoeff(), 1e-10 * reference.z.cwiseAbs().maxCoeff()) << "step " << step;
    pivots += a.iterations;
  }
  EXPECT_GT(pivots, 100) << "the road should force exchanges at most steps";
  EXPECT_LT(early.cg_iterations(), exact.cg_iterations()) << "no exchange was decided early";
}

TEST(PMatrixLcp, AWarmStartCorrectedByItsGapsReachesTheSameSolutionInFewerPivots) {
  // The last step's set corrected by the warm forces' gaps before the first solve must end at
  // the exact solver's set and solution (the dense reference's), in fewer pivoting iterations.
  const PlateLikeRolling rolling;
  const Window& w = rolling.w;
  const Eigen::MatrixXd& m = rolling.m;
  PMatrixLcpSolver corrected(m, 48, ContactWindow{w.length, w.lateral});
  PMatrixLcpSolver exact(m, 48, ContactWindow{w.length, w.lateral});
  exact.decide_early(false);
  long pivots_corrected = 0, pivots_exact = 0;
  for (int step = 0; step < 150; ++step) {
    const Eigen::VectorXd q = rolling.roll(step, corrected, exact);
    const PMatrixLcpResult& a = corrected.result();
    const PMatrixLcpResult& b = exact.result();
    const PMatrixLcpResult reference = solve_pmatrix_lcp(m, q);
    ASSERT_EQ(a.basic, reference.basic) << "step " << step;
    ASSERT_LE(kkt_violation(m, q, a.z), 2e-11) << "step " << step;
    ASSERT_LE((a.z - reference.z).cwiseAbs().maxCoeff(), 1e-10 * reference.z.cwiseAbs().maxCoeff()) << "step " << step;
    pivots_corrected += a.iterations;
    pivots_exact += b.iterations;
  }
  EXPECT_GT(pivots_exact, 100) << "the road should force exchanges at most steps";
  EXPECT_LT(pivots_corrected, pivots_exact);
}

TEST(PMatrixLcp, TheConjugateGradientsPassGivesTheSameBitsFourValuesAtATimeAsOne) {
  // The AVX pass over the window (updates and sign tests) against the scalar loop: the same
  // operations per value, so the same iterates, exchanges and solutions, bit for bit.
  const PlateLikeRolling rolling;
  const Window& w = rolling.w;
  PMatrixLcpSolver wide(rolling.m, 48, ContactWindow{w.length, w.lateral});
  PMatrixLcpSolver narrow(rolling.m, 48, ContactWindow{w.length, w.lateral});
  if (!wide.use_avx(true)) GTEST_SKIP() << "this processor has no AVX: only the scalar pass runs";
  ASSERT_FALSE(narrow.use_avx(false));
  ASSERT_TRUE(wide.iterative());
  for (int step = 0; step < 150; ++step) {
    rolling.roll(step, wide, narrow);
    ASSERT_EQ(wide.result().basic, narrow.result().basic) << "step " << step;
    ASSERT_EQ(wide.result().iterations, narrow.result().iterations) << "step " << step;
    for (Eigen::Index i = 0; i < w.points(); ++i) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(wide.result().z(i)), std::bit_cast<std::uint64_t>(narrow.result().z(i)))
          << "step " << step << ", point " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(wide.result().w(i)), std::bit_cast<std::uint64_t>(narrow.result().w(i)))
          << "step " << step << ", point " << i;
    }
  }
  EXPECT_EQ(wide.cg_iterations(), narrow.cg_iterations());
}

}  // namespace
}  // namespace rollnoise
