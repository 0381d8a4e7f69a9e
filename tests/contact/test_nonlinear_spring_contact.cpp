// Contact with nonlinear local springs F = k·δⁿ in series with a linear structure (MODEL.md §4):
// checked against the exact linear LCP solver (n = 1), against a scalar root found by bisection
// (one point), against the KKT conditions on random problems, against plain Newton on the
// smooth all-in-contact system, and on the degenerate cases. Units are physical (A ≈ 1 µm/N,
// q ≈ 0.1 mm) so that the solver's internal scaling is exercised.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "contact/lcp_solver.hpp"
#include "contact/nonlinear_spring_contact.hpp"

namespace rollnoise {
namespace {

constexpr double kCompliance = 1e-6;  // m/N, a structural compliance scale
constexpr double kLength = 1e-4;      // m, the scale of q

// A random SPD matrix with max |A_ij| = 1 (a smooth Gram-matrix coupling plus a local diagonal),
// symmetrised exactly.
Eigen::MatrixXd random_spd(Eigen::Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd b(n, n);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = normal(rng);
  Eigen::MatrixXd a = b.transpose() * b / static_cast<double>(n);
  a.diagonal().array() += 0.05;
  a = 0.5 * (a + a.transpose()).eval();
  return a / a.cwiseAbs().maxCoeff();
}

Eigen::VectorXd random_normal(Eigen::Index n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = normal(rng);
  return v;
}

Eigen::VectorXd random_uniform(Eigen::Index n, double lo, double hi, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(lo, hi);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(rng);
  return v;
}

// Recorded in the test XML (gtest --gtest_output=xml) for the measured accuracies.
std::string sci(double value) {
  std::ostringstream text;
  text.precision(3);
  text << std::scientific << value;
  return text.str();
}

// A stiffness k0 that balances the spring and the structure at δ ≈ kLength: k0·kLengthⁿ ≈
// kLength/kCompliance, so that both compliances matter in the solution.
double balanced_stiffness(double exponent) {
  return kLength / kCompliance / std::pow(kLength, exponent);
}

// ------------------------------------------------------------------------------------------
// 1. n = 1 is the linear LCP with compliance A + diag(1/k).

class LinearSprings : public ::testing::TestWithParam<int> {};

TEST_P(LinearSprings, MatchesLcpSolver) {
  const Eigen::Index size = GetParam();
  std::mt19937_64 rng(4242 + static_cast<unsigned>(size));
  const Eigen::MatrixXd a = kCompliance * random_spd(size, rng);
  const Eigen::VectorXd k = (1.0 / kCompliance) * random_uniform(size, 0.5, 2.0, rng);
  NonlinearSpringContact springs(a, k, 1.0);
  Eigen::MatrixXd lcp_matrix = a;
  lcp_matrix.diagonal() += k.cwiseInverse();
  LcpSolver lcp(lcp_matrix);
  double worst = 0.0;
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::VectorXd q = kLength * random_normal(size, rng);
    const Eigen::VectorXd reference = lcp.solve(q);
    const Eigen::VectorXd force = springs.solve(q);
    // Force scale: the reference's largest force, or q over the compliance if none is in contact.
    const double force_scale = std::max(reference.cwiseAbs().maxCoeff(),
                                        q.cwiseAbs().maxCoeff() / lcp_matrix.diagonal().maxCoeff());
    const double difference = (force - reference).cwiseAbs().maxCoeff() / force_scale;
    worst = std::max(worst, difference);
    EXPECT_LE(difference, 1e-10) << "size " << size << " trial " << trial;
    // δ = F/k for the linear spring.
    EXPECT_LE((springs.compression() - force.cwiseQuotient(k)).cwiseAbs().maxCoeff(),
              1e-14 * springs.compression().cwiseAbs().maxCoeff() + 1e-300);
  }
  RecordProperty("max_relative_force_difference", sci(worst));
}

INSTANTIATE_TEST_SUITE_P(Sizes, LinearSprings, ::testing::Values(1, 2, 10, 50, 120, 200));

// ------------------------------------------------------------------------------------------
// 2. One Hertz-like point (n = 1.5) on a scalar compliance: δ solves q + a·k·δ^1.5 + δ = 0.

// The root of q + a k δⁿ + δ on [0, −q] by bisection (the function rises from q < 0 to a k|q|ⁿ > 0)
// down to adjacent doubles: an independent, derivative-free reference.
double bisection_root(double q, double a, double k, double n) {
  double lo = 0.0;
  double hi = -q;
  for (int i = 0; i < 2000; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (q + a * k * std::pow(mid, n) + mid < 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

TEST(NonlinearSpringContact, SinglePointMatchesBisection) {
  const double a = 2e-6;  // m/N
  const double k = 5e8;   // N/m^1.5: a few N at δ ≈ 10 µm
  const double n = 1.5;
  NonlinearSpringContact contact(Eigen::MatrixXd::Constant(1, 1, a), Eigen::VectorXd::Constant(1, k), n);
  double worst_delta = 0.0;
  double worst_force = 0.0;
  // A sweep in and out of contact over five decades, so warm starts cross the contact boundary.
  const double sweep[] = {-1e-4, -1e-3, -1e-5, 2e-5, -1e-7, -1e-9, 1e-3, -3e-4, 0.0, -2e-6};
  for (const double q : sweep) {
    contact.solve(Eigen::VectorXd::Constant(1, q));
    const double delta = contact.compression()(0);
    const double force = contact.force()(0);
    if (q >= 0.0) {
      // Out of contact: no force, the gap is q itself.
      EXPECT_EQ(force, 0.0) << "q = " << q;
      EXPECT_EQ(delta, 0.0) << "q = " << q;
      EXPECT_EQ(contact.gap()(0), q) << "q = " << q;
      continue;
    }
    const double root = bisection_root(q, a, k, n);
    const double force_reference = k * std::pow(root, n);
    const double delta_error = std::abs(delta - root) / root;
    const double force_error = std::abs(force - force_reference) / force_reference;
    worst_delta = std::max(worst_delta, delta_error);
    worst_force = std::max(worst_force, force_error);
    EXPECT_LE(delta_error, 1e-13) << "q = " << q;
    EXPECT_LE(force_error, 1e-13) << "q = " << q;
    EXPECT_LE(std::abs(contact.gap()(0)), 1e-14 * -q) << "q = " << q;
  }
  RecordProperty("max_relative_delta_error", sci(worst_delta));
  RecordProperty("max_relative_force_error", sci(worst_force));
}

TEST(NonlinearSpringContact, RigidStructureCompressesOnlyTheSpring) {
  // A = 0: the spring takes the whole interpenetration, δ = max(−q, 0).
  NonlinearSpringContact contact(Eigen::MatrixXd::Zero(3, 3), Eigen::VectorXd::Constant(3, 1e10), 2.0);
  const Eigen::Vector3d q(-1e-4, 2e-5, -3e-6);
  contact.solve(q);
  EXPECT_NEAR(contact.compression()(0), 1e-4, 1e-18);
  EXPECT_EQ(contact.compression()(1), 0.0);
  EXPECT_NEAR(contact.compression()(2), 3e-6, 1e-20);
  EXPECT_NEAR(contact.force()(0), 1e10 * 1e-8, 1e-12);
}

// ------------------------------------------------------------------------------------------
// 3. KKT conditions on random problems with n = 1.5 and 2.

struct RandomCase {
  int size;
  double exponent;
};

void PrintTo(const RandomCase& c, std::ostream* os) { *os << "P = " << c.size << ", n = " << c.exponent; }

class RandomNonlinear : public ::testing::TestWithParam<RandomCase> {};

TEST_P(RandomNonlinear, MeetsComplementarity) {
  const auto [size, exponent] = GetParam();
  std::mt19937_64 rng(777 + static_cast<unsigned>(size) + static_cast<unsigned>(10 * exponent));
  const Eigen::MatrixXd a = kCompliance * random_spd(size, rng);
  const Eigen::VectorXd k = balanced_stiffness(exponent) * random_uniform(size, 0.5, 2.0, rng);
  NonlinearSpringContact contact(a, k, exponent);
  double worst_gap = 0.0;
  double worst_product = 0.0;
  for (int trial = 0; trial < 4; ++trial) {
    // Mixed signs: part of the points in contact; a negative offset on later trials pushes more in.
    const Eigen::VectorXd q = kLength * (random_normal(size, rng).array() - 0.3 * trial).matrix();
    contact.solve(q);
    const Eigen::VectorXd& delta = contact.compression();
    const Eigen::VectorXd& force = contact.force();
    const double s = q.cwiseAbs().maxCoeff();
    // Tolerance: the solver's target, 1e-12 relative to the length scale s. The round-off of
    // gap = q + A·F + δ is ≈ eps·(|q| + ‖A‖∞‖F‖∞ + |δ|) ≈ 1e-15·s here, three decades below.
    const double tol = 1e-12;
    // Independent recomputation of F and gap from δ.
    const Eigen::VectorXd force_check = k.cwiseProduct(delta.array().pow(exponent).matrix());
    const Eigen::VectorXd gap = q + a * force_check + delta;
    EXPECT_GE(delta.minCoeff(), 0.0);
    EXPECT_LE((force - force_check).cwiseAbs().maxCoeff(), 1e-13 * force_check.cwiseAbs().maxCoeff() + 1e-300);
    EXPECT_LE((contact.gap() - gap).cwiseAbs().maxCoeff(), tol * s);
    const double negative_gap = std::max(0.0, -gap.minCoeff()) / s;
    const double product = (delta.array() * gap.array()).abs().maxCoeff() / (s * s);
    worst_gap = std::max(worst_gap, negative_gap);
    worst_product = std::max(worst_product, product);
    EXPECT_LE(negative_gap, tol) << "trial " << trial;
    EXPECT_LE(product, tol) << "trial " << trial;
    if (size >= 40) {  // a mixed contact set, so the test exercises the kink of φ
      const Eigen::Index in_contact = (delta.array() > 0.0).count();
      EXPECT_GT(in_contact, 0);
      EXPECT_LT(in_contact, size);
    }
  }
  RecordProperty("max_negative_gap", sci(worst_gap));
  RecordProperty("max_complementarity", sci(worst_product));
}

INSTANTIATE_TEST_SUITE_P(Cases, RandomNonlinear,
                         ::testing::Values(RandomCase{1, 1.5}, RandomCase{5, 1.5}, RandomCase{40, 1.5},
                                           RandomCase{150, 1.5}, RandomCase{5, 2.0}, RandomCase{40, 2.0},
                                           RandomCase{150, 2.0}, RandomCase{40, 3.0}));

TEST(NonlinearSpringContact, StiffSpringsOnRankDeficientStructure) {
  // Springs 10⁴ times stiffer than the balance and a structure of rank 16 for 48 points (a
  // smooth, few-mode coupling without local compliance): nearly the LCP with a singular matrix,
  // the case that motivated the coordinate y = δ + A_pp·F inside the solver.
  std::mt19937_64 rng(21);
  const Eigen::Index size = 48;
  const double exponent = 1.5;
  Eigen::MatrixXd b(16, size);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = std::normal_distribution<double>()(rng);
  Eigen::MatrixXd a = b.transpose() * b;
  a = 0.5 * (a + a.transpose()).eval();
  a *= kCompliance / a.cwiseAbs().maxCoeff();
  const Eigen::VectorXd k = 1e4 * balanced_stiffness(exponent) * random_uniform(size, 0.5, 2.0, rng);
  NonlinearSpringContact contact(a, k, exponent);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = kLength * random_normal(size, rng);
    ASSERT_NO_THROW(contact.solve(q)) << "trial " << trial;
    const Eigen::VectorXd& delta = contact.compression();
    const Eigen::VectorXd gap = q + a * contact.force() + delta;
    const double s = q.cwiseAbs().maxCoeff();
    // Here ‖A‖∞‖F‖∞ ≫ ‖q‖∞ (A·F cancels), so the round-off of gap itself sets the tolerance:
    // 64·eps·(‖q‖∞ + ‖A‖∞‖F‖∞) relative to s.
    const double noise = std::numeric_limits<double>::epsilon() *
                         (s + a.cwiseAbs().rowwise().sum().maxCoeff() * contact.force().cwiseAbs().maxCoeff());
    const double tol = std::max(1e-12, 64.0 * noise / s);
    EXPECT_GE(gap.minCoeff(), -tol * s) << "trial " << trial;
    EXPECT_LE((delta.array() * gap.array()).abs().maxCoeff(), tol * s * s) << "trial " << trial;
    RecordProperty("iterations_trial_" + std::to_string(trial), contact.iterations());
  }
}

// ------------------------------------------------------------------------------------------
// 4. Degenerate cases and warm starts.

TEST(NonlinearSpringContact, AllOutOfContact) {
  std::mt19937_64 rng(11);
  const Eigen::Index size = 30;
  const Eigen::MatrixXd a = kCompliance * random_spd(size, rng);
  NonlinearSpringContact contact(a, Eigen::VectorXd::Constant(size, balanced_stiffness(1.5)), 1.5);
  const Eigen::VectorXd q = kLength * random_uniform(size, 0.1, 1.0, rng);
  contact.solve(q);
  EXPECT_TRUE((contact.force().array() == 0.0).all());
  EXPECT_TRUE((contact.compression().array() == 0.0).all());
  EXPECT_TRUE(contact.gap() == q);
  // From δ = 0 the residual is exactly zero: no Newton step is needed.
  EXPECT_EQ(contact.iterations(), 0);
  // q = 0: touching everywhere with no force.
  contact.solve(Eigen::VectorXd::Zero(size));
  EXPECT_TRUE((contact.force().array() == 0.0).all());
  EXPECT_TRUE((contact.gap().array() == 0.0).all());
}

TEST(NonlinearSpringContact, AllInContactMatchesSmoothNewton) {
  std::mt19937_64 rng(12);
  const Eigen::Index size = 60;
  const double exponent = 1.5;
  // Mostly local compliance with a weak positive coupling: every point stays in contact.
  Eigen::MatrixXd a = Eigen::MatrixXd::Constant(size, size, 0.2 / static_cast<double>(size));
  a.diagonal().array() += 0.8;
  a *= kCompliance;
  const Eigen::VectorXd k = balanced_stiffness(exponent) * random_uniform(size, 0.5, 2.0, rng);
  const Eigen::VectorXd q = -kLength * random_uniform(size, 1.0, 1.5, rng);
  NonlinearSpringContact contact(a, k, exponent);
  contact.solve(q);

  // Reference: Newton on the smooth system q + A·(k∘δⁿ) + δ = 0 (no complementarity), from
  // δ = −q, to convergence.
  Eigen::VectorXd delta = -q;
  for (int i = 0; i < 50; ++i) {
    const Eigen::VectorXd power = delta.array().pow(exponent);
    const Eigen::VectorXd residual = q + a * k.cwiseProduct(power) + delta;
    Eigen::MatrixXd jacobian = a * (exponent * k.array() * delta.array().pow(exponent - 1.0)).matrix().asDiagonal();
    jacobian.diagonal().array() += 1.0;
    const Eigen::VectorXd step = jacobian.partialPivLu().solve(residual);
    delta -= step;
    if (step.cwiseAbs().maxCoeff() <= 1e-16 * delta.cwiseAbs().maxCoeff()) break;
  }
  ASSERT_GT(delta.minCoeff(), 0.0) << "the reference is not all in contact";
  EXPECT_TRUE((contact.compression().array() > 0.0).all());
  const double difference = (contact.compression() - delta).cwiseAbs().maxCoeff() / delta.cwiseAbs().maxCoeff();
  EXPECT_LE(difference, 1e-12);
  EXPECT_LE(contact.gap().cwiseAbs().maxCoeff(), 1e-12 * q.cwiseAbs().maxCoeff());
  RecordProperty("relative_delta_difference", sci(difference));
}

TEST(NonlinearSpringContact, WarmStartSameAnswerFewerIterations) {
  std::mt19937_64 rng(13);
  const Eigen::Index size = 100;
  const double exponent = 1.5;
  const Eigen::MatrixXd a = kCompliance * random_spd(size, rng);
  const Eigen::VectorXd k = balanced_stiffness(exponent) * random_uniform(size, 0.5, 2.0, rng);
  const Eigen::VectorXd q0 = kLength * (random_normal(size, rng).array() - 0.5).matrix();
  // The next time step: a small change of q, as in a rolling run.
  const Eigen::VectorXd q1 = q0 + 0.01 * kLength * random_normal(size, rng);

  NonlinearSpringContact warm(a, k, exponent);
  warm.solve(q0);
  const int first = warm.iterations();
  const Eigen::VectorXd force0 = warm.force();
  // The same q again: the warm start is already the answer.
  warm.solve(q0);
  EXPECT_EQ(warm.iterations(), 0);
  EXPECT_LE((warm.force() - force0).cwiseAbs().maxCoeff(), 1e-14 * force0.cwiseAbs().maxCoeff());
  warm.solve(q1);
  const int warm_iterations = warm.iterations();

  NonlinearSpringContact cold(a, k, exponent);
  cold.solve(q1);
  const int cold_iterations = cold.iterations();
  EXPECT_LE((warm.force() - cold.force()).cwiseAbs().maxCoeff(), 1e-12 * cold.force().cwiseAbs().maxCoeff());
  EXPECT_LT(warm_iterations, cold_iterations);
  RecordProperty("first_solve_iterations", first);
  RecordProperty("warm_iterations", warm_iterations);
  RecordProperty("cold_iterations", cold_iterations);
}

TEST(NonlinearSpringContact, RollingSequenceRuntime) {
  // 200 points, 30 steps of a slowly varying q: records the cost per step (no assertion on
  // time, only that every step converged to complementarity).
  std::mt19937_64 rng(14);
  const Eigen::Index size = 200;
  const double exponent = 1.5;
  const Eigen::MatrixXd a = kCompliance * random_spd(size, rng);
  const Eigen::VectorXd k = balanced_stiffness(exponent) * random_uniform(size, 0.5, 2.0, rng);
  const Eigen::VectorXd base = kLength * (random_normal(size, rng).array() - 0.5).matrix();
  const Eigen::VectorXd drift = kLength * random_normal(size, rng);
  NonlinearSpringContact contact(a, k, exponent);
  int total_iterations = 0;
  const auto start = std::chrono::steady_clock::now();
  const int steps = 30;
  for (int step = 0; step < steps; ++step) {
    const Eigen::VectorXd q = base + std::sin(0.08 * step) * drift;
    contact.solve(q);
    total_iterations += contact.iterations();
    const Eigen::VectorXd gap = q + a * contact.force() + contact.compression();
    const double s = q.cwiseAbs().maxCoeff();
    ASSERT_LE((contact.compression().array() * gap.array()).abs().maxCoeff(), 1e-12 * s * s);
    ASSERT_GE(gap.minCoeff(), -1e-12 * s);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("mean_iterations_per_step", sci(static_cast<double>(total_iterations) / steps));
  RecordProperty("mean_ms_per_step", sci(1e3 * seconds / steps));
}

// ------------------------------------------------------------------------------------------
// 5. Construction and input checks.

TEST(NonlinearSpringContact, RejectsBadArguments) {
  const Eigen::MatrixXd good = kCompliance * Eigen::MatrixXd::Identity(2, 2);
  const Eigen::VectorXd k = Eigen::VectorXd::Constant(2, 1e8);
  EXPECT_NO_THROW(NonlinearSpringContact(good, k, 1.5));
  // A not square.
  EXPECT_THROW(NonlinearSpringContact(Eigen::MatrixXd::Identity(2, 3), k, 1.5), std::invalid_argument);
  // A not finite.
  Eigen::MatrixXd nan_a = good;
  nan_a(0, 1) = nan_a(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(NonlinearSpringContact(nan_a, k, 1.5), std::invalid_argument);
  // A not symmetric.
  Eigen::MatrixXd asymmetric = good;
  asymmetric(0, 1) = 0.5 * kCompliance;
  EXPECT_THROW(NonlinearSpringContact(asymmetric, k, 1.5), std::invalid_argument);
  // A indefinite.
  Eigen::MatrixXd indefinite = good;
  indefinite(0, 1) = indefinite(1, 0) = 2.0 * kCompliance;
  EXPECT_THROW(NonlinearSpringContact(indefinite, k, 1.5), std::invalid_argument);
  // k of the wrong size, zero, negative, not finite.
  EXPECT_THROW(NonlinearSpringContact(good, Eigen::VectorXd::Constant(3, 1e8), 1.5), std::invalid_argument);
  EXPECT_THROW(NonlinearSpringContact(good, Eigen::Vector2d(1e8, 0.0), 1.5), std::invalid_argument);
  EXPECT_THROW(NonlinearSpringContact(good, Eigen::Vector2d(1e8, -1.0), 1.5), std::invalid_argument);
  EXPECT_THROW(NonlinearSpringContact(good, Eigen::Vector2d(1e8, std::numeric_limits<double>::infinity()), 1.5),
               std::invalid_argument);
  // Exponent below 1 (dF/dδ is infinite at δ = 0: the δ formulation is no longer C¹) or NaN.
  EXPECT_THROW(NonlinearSpringContact(good, k, 0.5), std::invalid_argument);
  EXPECT_THROW(NonlinearSpringContact(good, k, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  // q of the wrong size or not finite.
  NonlinearSpringContact contact(good, k, 1.5);
  EXPECT_THROW(contact.solve(Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THROW(contact.solve(Eigen::Vector2d(0.0, std::numeric_limits<double>::quiet_NaN())),
               std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
