// The direct history engine against the convolution written out term by term (eq. 3 with a
// constant force for t < 0), and the static contact against its defining conditions.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "contact/direct_history_engine.hpp"
#include "contact/static_contact.hpp"

namespace rollnoise {
namespace {

std::shared_ptr<DiscreteKernel> random_kernel(Eigen::Index points, std::size_t lags, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto kernel = std::make_shared<DiscreteKernel>();
  kernel->time_step = 1e-3;
  kernel->total = Eigen::MatrixXd::Zero(points, points);
  for (std::size_t k = 0; k < lags; ++k) {
    Eigen::MatrixXd g(points, points);
    for (Eigen::Index i = 0; i < g.size(); ++i) g.data()[i] = u(rng) * std::exp(-0.05 * static_cast<double>(k));
    kernel->lags.push_back(g);
    kernel->total += g;
  }
  // A tail beyond the stored lags, as for a kernel cut before it has decayed.
  Eigen::MatrixXd tail(points, points);
  for (Eigen::Index i = 0; i < tail.size(); ++i) tail.data()[i] = 0.01 * u(rng);
  kernel->total += tail;
  return kernel;
}

class DirectEngine : public ::testing::TestWithParam<std::size_t> {};

TEST_P(DirectEngine, EqualsTheConvolutionWrittenOut) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  const Eigen::Index points = 3;
  const std::size_t lags = GetParam();
  const auto kernel = random_kernel(points, lags, rng);
  const Eigen::VectorXd preload = Eigen::Vector3d(1.0, 2.0, 0.5);
  const std::size_t steps = 80;
  DirectHistoryEngine engine(kernel, steps, preload);

  std::vector<Eigen::VectorXd> forces;
  // F(m) for any m, with the preload for m < 0.
  auto force_at = [&](long m) -> Eigen::VectorXd {
    return m < 0 ? preload : forces[static_cast<std::size_t>(m)];
  };
  Eigen::VectorXd u0(points);
  for (std::size_t n = 0; n < steps; ++n) {
    engine.history(u0);
    // u⁰(n) = Σ_{k=1}^{K−1} G[k]·F(n−k) + (total − Σ_{k<K} G[k])·F_pre: the part of the
    // response beyond the stored lags only ever carries the preload.
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(points);
    Eigen::MatrixXd stored = Eigen::MatrixXd::Zero(points, points);
    for (std::size_t k = 0; k < lags; ++k) stored += kernel->lags[k];
    for (std::size_t k = 1; k < lags; ++k) expected += kernel->lags[k] * force_at(static_cast<long>(n) - static_cast<long>(k));
    expected += (kernel->total - stored) * preload;
    EXPECT_LE((u0 - expected).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + expected.cwiseAbs().maxCoeff()))
        << "step " << n;
    Eigen::VectorXd f(points);
    for (Eigen::Index i = 0; i < points; ++i) f(i) = u(rng);
    forces.push_back(f);
    engine.advance(f);
  }
}

// Kernels shorter than, equal to and longer than the run.
INSTANTIATE_TEST_SUITE_P(KernelLengths, DirectEngine, ::testing::Values(1u, 2u, 17u, 80u, 81u, 200u));

TEST(StaticContact, CarriesTheLoadWithComplementarity) {
  // A curved body (h = x²/2R) on a flat road with a coupled compliance.
  const Eigen::Index n = 41;
  Eigen::VectorXd h(n);
  Eigen::MatrixXd c(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = 0.005 * static_cast<double>(i - n / 2);
    h(i) = x * x / (2 * 0.3);
    for (Eigen::Index j = 0; j < n; ++j) c(i, j) = 2e-7 * std::exp(-static_cast<double>(std::abs(i - j)) / 3.0);
    c(i, i) += 1e-6;
  }
  for (double load : {10.0, 300.0, 3000.0}) {
    const StaticContact s = solve_static_contact(c, h, load);
    EXPECT_NEAR(s.force.sum(), load, 1e-12 * load);
    const Eigen::VectorXd gap = h.array() - s.indentation + (c * s.force).array();
    EXPECT_GE(s.force.minCoeff(), 0.0);
    EXPECT_GE(gap.minCoeff(), -1e-15);
    EXPECT_LE((s.force.array() * gap.array()).abs().maxCoeff(), 1e-15 * load);
    // Part of the body is out of contact at the lower loads: the active set matters.
    if (load == 10.0) {
      EXPECT_LT((s.force.array() > 0).count(), n);
    }
  }
  const StaticContact none = solve_static_contact(c, h, 0.0);
  EXPECT_EQ(none.indentation, h.minCoeff());
  EXPECT_EQ(none.force, Eigen::VectorXd::Zero(n));
}

TEST(StaticContact, SdofIndentationIsLoadTimesCompliance) {
  Eigen::MatrixXd c(1, 1);
  c << 1.0 / 1e5 + 1.0 / 500.0;
  const StaticContact s = solve_static_contact(c, Eigen::VectorXd::Zero(1), 4.0);
  EXPECT_NEAR(s.indentation, 4.0 * c(0, 0), 1e-15 * s.indentation);
  EXPECT_NEAR(s.force(0), 4.0, 1e-14);
}

}  // namespace
}  // namespace rollnoise
