// The regularised least squares of the equivalent-source solves (least_squares.hpp): the normal
// equations (Cholesky of AᴴA + λ²I) against the Householder QR of [A; λI], the condition check
// that chooses between them, and the tyre meshes' solves, which take the normal equations.
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "radiation/least_squares.hpp"
#include "radiation/sphere_points.hpp"
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", x);
  return text;
}

double relative_difference(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(LeastSquares, NormalEquationsAndQrAgreeOnAWellConditionedProblem) {
  std::srand(17);
  const Eigen::MatrixXcd a = Eigen::MatrixXcd::Random(300, 120);
  const Eigen::MatrixXcd b = Eigen::MatrixXcd::Random(300, 3);
  const Eigen::MatrixXcd x = Eigen::MatrixXcd::Random(2, 120);
  RegularisedLeastSquares normal(a), qr(a, LeastSquaresMethod::qr);
  const double lambda = 1e-3 * std::sqrt(normal.largest_singular_value_squared(Eigen::VectorXcd::Ones(120)));
  normal.factorise(lambda);
  qr.factorise(lambda);
  EXPECT_TRUE(normal.normal_equations());
  EXPECT_FALSE(qr.normal_equations());
  EXPECT_GT(normal.reciprocal_condition(), 1e-3);
  EXPECT_LE(relative_difference(normal.solve(b), qr.solve(b)), 1e-12);
  EXPECT_LE(relative_difference(normal.apply_pseudo_inverse_right(x), qr.apply_pseudo_inverse_right(x)), 1e-12);
  // The regularised solution satisfies (AᴴA + λ²I) q = Aᴴb.
  const Eigen::MatrixXcd q = qr.solve(b);
  const Eigen::MatrixXcd lhs = a.adjoint() * a * q + lambda * lambda * q;
  EXPECT_LE(relative_difference(lhs, a.adjoint() * b), 1e-12);
  // X A⁺ is the transpose problem: (X A⁺) b = X q.
  EXPECT_LE(relative_difference(normal.apply_pseudo_inverse_right(x) * b, x * q), 1e-12);
}

TEST(LeastSquares, IllConditionedProblemsTakeTheQr) {
  // Columns nearly dependent: κ(A) ≈ 1e8, κ(AᴴA) ≈ 1e16.
  std::srand(19);
  Eigen::MatrixXcd a = Eigen::MatrixXcd::Random(200, 40);
  a.col(39) = a.col(38) + 1e-8 * Eigen::VectorXcd::Random(200);
  RegularisedLeastSquares automatic(a);
  automatic.factorise(0.0);
  EXPECT_FALSE(automatic.normal_equations());
  EXPECT_LT(automatic.reciprocal_condition(), 1e-11);
  // The QR's answer fits as well as the least-squares solution can (the SVD's).
  const Eigen::VectorXcd b = Eigen::VectorXcd::Random(200);
  const Eigen::VectorXcd q = automatic.solve(b);
  const Eigen::VectorXcd best = a.bdcSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(b);
  EXPECT_LE((a * q - b).norm(), (1.0 + 1e-9) * (a * best - b).norm());
  EXPECT_THROW(automatic.factorise(0.0), std::logic_error);
  EXPECT_THROW(RegularisedLeastSquares(Eigen::MatrixXcd(0, 3)), std::invalid_argument);
}

// The stage's meshes are well enough conditioned for the normal equations (κ(VᴴV) 1e6–1e9), and
// on them the transfer to the receivers is the QR's to far better than the mesh's own error.
TEST(LeastSquares, TyreMeshTransfersByNormalEquationsAreTheQrs) {
  TyreSurfaceMeshSpec spec;
  spec.geometry = TyreGeometry::deformed;
  spec.across = 16;
  spec.contact_refinement = 10.0;
  const TyreSurfaceMesh mesh = make_tyre_surface_mesh(spec);
  Eigen::Matrix3Xd receivers(3, 3);
  receivers << 0.2, -0.2, 0.0, 0.29, 0.29, 7.5, 0.1, 0.1, 1.2;
  for (double f : {500.0, 4000.0}) {
    // The stage's sources: monopoles at 500 Hz, combined at 4 kHz.
    EquivalentSources normal = make_tyre_model(mesh, Medium{}, f > kCombinedSourcesAboveHz);
    EquivalentSources qr = make_tyre_model(mesh, Medium{}, f > kCombinedSourcesAboveHz);
    qr.set_least_squares_method(LeastSquaresMethod::qr);
    const double omega = 2 * kPi * f;
    const EquivalentSourceSolve a = normal.solve(omega), b = qr.solve(omega);
    EXPECT_TRUE(a.normal_equations()) << f;
    EXPECT_GT(a.reciprocal_condition(), 1e-9) << f;
    const Eigen::MatrixXcd p = normal.pressure_matrix(omega, receivers);
    const double difference = relative_difference(a.transfer(p), b.transfer(p));
    EXPECT_LE(difference, 1e-6) << f;
    RecordProperty("rcond_" + std::to_string(static_cast<int>(f)) + "Hz", scientific(a.reciprocal_condition()));
    RecordProperty("normal_vs_qr_" + std::to_string(static_cast<int>(f)) + "Hz", scientific(difference));
    std::printf("%.0f Hz: rcond %.2e, normal equations vs QR %.2e\n", f, a.reciprocal_condition(), difference);
  }
}

}  // namespace
}  // namespace rollnoise
