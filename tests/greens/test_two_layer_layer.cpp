// The two-layer tyre's building blocks, each against a reference that shares none of its code:
//   - f(μ) = tanh(√μ)/√μ, its divided differences (continuous across their switches) and f of a
//     3×3 matrix (diagonalisable: eigendecomposition; defective: the Jordan-block formula with
//     derivatives in long double);
//   - the causal modulus: its reference values, passivity, and its equality with a positive
//     superposition of Debye relaxations (hence causal) computed by quadrature;
//   - the orthotropic stiffness and its physical checks;
//   - the exact layer stiffness against the transfer matrix exp(A·h) built from the raw field
//     equations (where a transfer matrix is still accurate), the free-plate dispersion against
//     the Rayleigh–Lamb equations, the static case against ω → 0, and large k·h without
//     overflow;
//   - the stack's reciprocity and mirror symmetries.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "greens/causal_modulus.hpp"
#include "greens/layer_stiffness.hpp"
#include "greens/orthotropic_material.hpp"
#include "greens/tanh_sqrt_function.hpp"
#include "greens/two_layer_stack.hpp"
#include "two_layer_test_support.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using cld = std::complex<long double>;
using std::numbers::pi;

// f and its first two derivatives in long double, straight from the definitions (valid away from
// μ = 0, where the test does not use them).
cld f_ld(cld mu) {
  const cld s = std::sqrt(mu);
  return std::tanh(s) / s;
}
cld f1_ld(cld mu) {
  const cld s = std::sqrt(mu), t = std::tanh(s), sech2 = 1.0L - t * t;
  return (s * sech2 - t) / (2.0L * s * s * s);
}
cld f2_ld(cld mu) {  // f''
  const cld s = std::sqrt(mu), t = std::tanh(s), sech2 = 1.0L - t * t;
  return (3.0L * t - 3.0L * s * sech2 - 2.0L * s * s * t * sech2) / (4.0L * s * s * s * s * s);
}
cd to_cd(cld z) { return {static_cast<double>(z.real()), static_cast<double>(z.imag())}; }

double relative(cd a, cd b) { return std::abs(a - b) / std::abs(b); }

// ---------------------------------------------------------------------------------------------
// 1. f(μ) = tanh(√μ)/√μ.

TEST(TanhSqrt, ScalarAgainstLongDoubleDefinition) {
  // Points on both sides of the series switch (|μ| = 1e-3), large, complex, propagating (μ < 0).
  const std::vector<cd> points = {{1e-6, 0}, {-3e-4, 2e-4}, {9.99e-4, 0}, {1.001e-3, 0}, {0.3, -0.2},
                                  {5.0, 1.0}, {-1.0, 0.0},  {-30.0, 0.5}, {1e4, -1e3},  {1e10, 1e6}};
  for (const cd mu : points) {
    // Near 0 the long-double definition loses digits itself: compare with its Taylor series.
    const cld m(mu.real(), mu.imag());
    const cld reference = std::abs(mu) < 1e-2 ? 1.0L - m / 3.0L + 2.0L * m * m / 15.0L - 17.0L * m * m * m / 315.0L +
                                                    62.0L * m * m * m * m / 2835.0L
                                              : f_ld(m);
    EXPECT_LT(relative(tanh_sqrt(mu), to_cd(reference)), 2e-15) << mu;
  }
  // Poles at −(π(j + ½))²: the pole distance finds them.
  EXPECT_NEAR(tanh_sqrt_pole_distance(cd(-pi * pi / 4, 0)), 0.0, 1e-12);
  EXPECT_NEAR(tanh_sqrt_pole_distance(cd(-(2.5 * pi) * (2.5 * pi) + 0.1, 0.2)), std::hypot(0.1, 0.2), 1e-9);
  EXPECT_NEAR(tanh_sqrt_pole_distance(cd(3.0, 4.0)), std::abs(cd(3.0 + pi * pi / 4, 4.0)), 1e-12);
}

TEST(TanhSqrt, DividedDifferencesAcrossTheirSwitches) {
  // At each centre, pairs and triples spread across the switches at s/r = 1e-8 (derivatives)
  // and 1/16 (Cauchy integral), and beyond (difference quotients),
  // against long double: the quotient where it is accurate (s/r ≥ 1e-3), else the Taylor
  // form f'(c) + O(s²), f''(c)/2 + O(s²). And just below and above each switch the values
  // agree to round-off: the switch is continuous.
  const std::vector<cd> centres = {{0.7, 0.3}, {12.0, -5.0}, {-6.0, 0.4}, {-40.0, 2.0}, {2e3, 1e2}};
  double worst = 0.0, worst_jump = 0.0;
  for (const cd c : centres) {
    const double r = tanh_sqrt_pole_distance(c);
    const cd direction = std::polar(1.0, 0.7);
    for (const double fraction : {1e-12, 1e-9, 0.99e-8, 1.01e-8, 1e-6, 1e-3, 0.02, 0.062, 0.063, 0.1, 0.3}) {
      const double s = fraction * r;
      const cd a = c - s * direction, b = c + s * direction;
      cd reference2, reference3;
      const cd third = c + s * direction * cd(0.0, 1.0);  // triple: a, b, and one off the line
      const cd centroid3 = (a + b + third) / 3.0;
      if (fraction >= 1e-3) {
        const cld la(a.real(), a.imag()), lb(b.real(), b.imag()), lt(third.real(), third.imag());
        const cld ab = (f_ld(la) - f_ld(lb)) / (la - lb), bt = (f_ld(lb) - f_ld(lt)) / (lb - lt);
        reference2 = to_cd(ab);
        reference3 = to_cd((ab - bt) / (la - lt));
      } else {
        reference2 = to_cd(f1_ld(cld(c.real(), c.imag())));
        reference3 = to_cd(f2_ld(cld(centroid3.real(), centroid3.imag())) / 2.0L);
      }
      const double e2 = relative(tanh_sqrt_divided(a, b), reference2);
      const double e3 = relative(tanh_sqrt_divided(a, b, third), reference3);
      // The Taylor reference itself is off by O((s/r)²).
      const double allowed = 1e-12 + (fraction < 1e-3 ? 10 * fraction * fraction : 0.0);
      EXPECT_LT(e2, allowed) << "centre " << c << " s/r " << fraction;
      EXPECT_LT(e3, allowed) << "centre " << c << " s/r " << fraction;
      if (fraction >= 1e-3 || fraction < 1e-8) worst = std::max({worst, e2, e3});
    }
    // Continuity: one step across each switch, of 2e-13 relative in the spread s (the
    // function itself changes by ~(s/r)²·2e-13 over it, below 1e-14).
    for (const double at : {1e-8, 1.0 / 16.0}) {
      const auto pair = [&](double fraction) {
        const double s = fraction * r;
        return tanh_sqrt_divided(c - s * direction, c + s * direction);
      };
      const auto triple = [&](double fraction) {
        const double s = fraction * r;
        return tanh_sqrt_divided(c - s * direction, c + s * direction, c + s * direction * cd(0.0, 1.0));
      };
      worst_jump = std::max({worst_jump, relative(pair(at * (1 + 1e-13)), pair(at * (1 - 1e-13))),
                             relative(triple(at * (1 + 1e-13)), triple(at * (1 - 1e-13)))});
    }
  }
  std::printf("divided differences: worst error %.2e, worst jump across a switch %.2e\n", worst, worst_jump);
  EXPECT_LT(worst_jump, 1e-13);
}

TEST(TanhSqrt, MatrixFunctionDiagonalisableAndDefective) {
  // A diagonalisable matrix with distinct eigenvalues: V f(D) V⁻¹.
  Eigen::Matrix3cd m;
  m << cd(2.0, 0.3), cd(-1.0, 0.5), cd(0.2, 0.0),  //
      cd(0.4, -0.1), cd(-3.0, 0.2), cd(1.5, 1.0),  //
      cd(0.0, 0.7), cd(0.3, 0.0), cd(9.0, -2.0);
  const Eigen::ComplexEigenSolver<Eigen::Matrix3cd> eigen(m);
  Eigen::Vector3cd fd;
  for (int i = 0; i < 3; ++i) fd(i) = tanh_sqrt(eigen.eigenvalues()(i));
  const Eigen::Matrix3cd expected = eigen.eigenvectors() * fd.asDiagonal() * eigen.eigenvectors().inverse();
  EXPECT_LT((tanh_sqrt(m) - expected).norm() / expected.norm(), 1e-13);

  // A defective one: a 3×3 Jordan block J = μI + N, f(J) = f I + f' N + (f''/2) N², similar
  // by a non-unitary S so that Schur has to find the structure.
  for (const cd mu : {cd(1.3, 0.2), cd(-7.0, 0.1), cd(400.0, -30.0), cd(1e-4, 0.0)}) {
    Eigen::Matrix3cd j = mu * Eigen::Matrix3cd::Identity();
    j(0, 1) = 1.0;
    j(1, 2) = 1.0;
    Eigen::Matrix3cd s;
    s << 1.0, 2.0, 0.0, 0.5, 1.0, 1.0, cd(0, 1), 0.0, 3.0;
    const cld lm(mu.real(), mu.imag());
    const bool small = std::abs(mu) < 1e-2;
    // Near 0 the derivatives from the series f = 1 − μ/3 + 2μ²/15 − 17μ³/315 + 62μ⁴/2835:
    // f' = −1/3 + 4μ/15 − 17μ²/105 + 248μ³/2835, f''/2 = 2/15 − 17μ/105 + 124μ²/945.
    const cd f0 = small ? tanh_sqrt(mu) : to_cd(f_ld(lm));
    const cd f1 = small ? cd(-1.0 / 3.0) + 4.0 * mu / 15.0 - 17.0 * mu * mu / 105.0 + 248.0 * mu * mu * mu / 2835.0
                        : to_cd(f1_ld(lm));
    const cd f2 = small ? cd(2.0 / 15.0) - 17.0 * mu / 105.0 + 124.0 * mu * mu / 945.0 : to_cd(f2_ld(lm) / 2.0L);
    Eigen::Matrix3cd fj = f0 * Eigen::Matrix3cd::Identity();
    fj(0, 1) = fj(1, 2) = f1;
    fj(0, 2) = f2;
    const Eigen::Matrix3cd expected_j = s * fj * s.inverse();
    const Eigen::Matrix3cd got = tanh_sqrt(Eigen::Matrix3cd(s * j * s.inverse()));
    EXPECT_LT((got - expected_j).norm() / expected_j.norm(), 1e-9) << mu;
  }
}

TEST(TanhSqrt, TwoRootFormForAMinimalPolynomialOfDegreeTwo) {
  // f(M) = f(μ1)I + f[μ1, μ2](M − μ1 I) when (x − μ1)(x − μ2) annihilates M: roots P, S, S with
  // independent S eigenvectors (an isotropic layer at ω ≠ 0), and a Jordan block of size 2 with
  // a simple root equal to it (ω = 0), against the Schur–Parlett form and the Jordan formula.
  Eigen::Matrix3cd s;
  s << 1.0, 2.0, 0.0, 0.5, 1.0, 1.0, cd(0, 1), 0.0, 3.0;
  const Eigen::Matrix3cd si = s.inverse();
  for (const auto& [p, q] : {std::pair{cd(3.0, 0.1), cd(1.0, 0.1)}, {cd(-20.0, 1.0), cd(-19.9, 1.0)},
                             {cd(500.0, -3.0), cd(499.9999, -3.0)}, {cd(0.2, 0.0), cd(0.2 + 1e-12, 0.0)}}) {
    const Eigen::Matrix3cd m = s * Eigen::Vector3cd(p, q, q).asDiagonal() * si;
    const Eigen::Matrix3cd expected = tanh_sqrt(m);
    EXPECT_LT((tanh_sqrt(m, q, p) - expected).norm() / expected.norm(), 1e-10) << p << " " << q;
  }
  for (const cd mu : {cd(1.3, 0.2), cd(-7.0, 0.1), cd(400.0, -30.0)}) {
    Eigen::Matrix3cd j = mu * Eigen::Matrix3cd::Identity();
    j(0, 1) = 1.0;  // a 2-block and a 1-block: (x − μ)² annihilates it
    const cld lm(mu.real(), mu.imag());
    Eigen::Matrix3cd fj = to_cd(f_ld(lm)) * Eigen::Matrix3cd::Identity();
    fj(0, 1) = to_cd(f1_ld(lm));
    const Eigen::Matrix3cd expected = s * fj * si;
    EXPECT_LT((tanh_sqrt(Eigen::Matrix3cd(s * j * si), mu, mu) - expected).norm() / expected.norm(), 1e-12) << mu;
  }
}

// layer_stiffness computes B·f(CB) as f(BC)·B: the two agree for any 3×3 B and C (f(M) is a
// polynomial in M, and B(CB)^j = (BC)^j B), a singular B included.
TEST(TanhSqrt, MatrixFunctionIntertwinesProducts) {
  Eigen::Matrix3cd b, c;
  b << cd(0.0, -0.3), 1.0, 0.0,  //
      cd(0.0, -0.2), 0.0, 1.7,  //
      cd(-0.8, 0.05), cd(0.0, -0.3), cd(0.0, -0.2);
  c << cd(0.0, -0.1), cd(0.0, -0.07), 0.02,  //
      cd(25.0, 1.0), 3.0, cd(0.0, -0.1),  //
      3.0, cd(9.0, 0.4), cd(0.0, -0.07);
  for (const double scale : {1e-3, 0.1, 1.0, 30.0}) {
    const Eigen::Matrix3cd bs = scale * b;
    const Eigen::Matrix3cd left = bs * tanh_sqrt(Eigen::Matrix3cd(c * bs));
    const Eigen::Matrix3cd right = tanh_sqrt(Eigen::Matrix3cd(bs * c)) * bs;
    EXPECT_LT((left - right).norm() / right.norm(), 1e-12) << scale;
  }
  Eigen::Matrix3cd singular = b;
  singular.col(2) = 2.0 * singular.col(0);
  const Eigen::Matrix3cd left = singular * tanh_sqrt(Eigen::Matrix3cd(c * singular));
  const Eigen::Matrix3cd right = tanh_sqrt(Eigen::Matrix3cd(singular * c)) * singular;
  EXPECT_LT((left - right).norm() / right.norm(), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// 2. The causal modulus.

TEST(CausalModulus, ReferenceValuesPassivityAndDebyeSuperposition) {
  const double eta = 0.1;
  const CausalModulus modulus(eta);
  const double w_ref = 2 * pi * CausalModulus::reference_frequency;
  const cd at_ref = modulus.factor(w_ref);
  EXPECT_NEAR(at_ref.real(), 1.0, 1e-14);
  EXPECT_NEAR(at_ref.imag(), eta, 1e-14);
  // Static: real, the relaxed modulus, and the limit of small ω (first order in ω).
  EXPECT_EQ(modulus.factor(0.0), cd(modulus.static_factor(), 0.0));
  EXPECT_LT(std::abs(modulus.factor(1e-6) - modulus.factor(0.0)), 1e-7);
  EXPECT_GT(modulus.static_factor(), 0.5);
  EXPECT_LT(modulus.static_factor(), 1.0);

  // A positive superposition of Debye relaxations iωτ/(1 + iωτ), evenly in ln τ over the band,
  // by Gauss–Legendre quadrature: each is causal (its pole at ω = i/τ) and passive, so the
  // modulus is. Fit its strength at one frequency, then it must reproduce every other,
  // including complex frequencies of the exponential window.
  const double ln1 = std::log(1.0 / (2 * pi * CausalModulus::band_high));
  const double ln2 = std::log(1.0 / (2 * pi * CausalModulus::band_low));
  const test::Quadrature q = test::composite_rule(ln1, ln2, 400, test::gauss_legendre(8));
  const auto debye = [&](cd w) {
    cd sum = 0.0;
    for (std::size_t i = 0; i < q.nodes.size(); ++i) {
      const cd x = cd(0.0, 1.0) * w * std::exp(q.nodes[i]);
      sum += q.weights[i] * x / (1.0 + x);
    }
    return sum;
  };
  const cd strength = (at_ref / modulus.static_factor() - 1.0) / debye(w_ref);
  EXPECT_GT(strength.real(), 0.0);
  EXPECT_LT(std::abs(strength.imag()), 1e-12 * strength.real());
  double worst = 0.0;
  for (const cd w : {cd(1.0), cd(60.0), cd(700.0, -5.0), cd(3e4, -200.0), cd(2e6), cd(100.0, -40.0)}) {
    const cd expected = modulus.static_factor() * (1.0 + strength.real() * debye(w));
    worst = std::max(worst, relative(modulus.factor(w), expected));
  }
  EXPECT_LT(worst, 1e-10);
  // Passive at every real frequency, and a nearly constant loss over the tyre's band.
  for (double f = 0.01; f < 1e7; f *= 1.3) EXPECT_GT(modulus.factor(2 * pi * f).imag(), 0.0) << f;
  for (double f = 100.0; f <= 5000.0; f *= 1.2) {
    EXPECT_NEAR(modulus.loss_factor_at(2 * pi * f), eta, 0.13 * eta) << f;
  }
  std::printf("causal modulus, eta = 0.1: static factor %.4f, loss at 100 Hz %.4f, 1 kHz %.4f, 5 kHz %.4f\n",
              modulus.static_factor(), modulus.loss_factor_at(2 * pi * 100), modulus.loss_factor_at(w_ref),
              modulus.loss_factor_at(2 * pi * 5000));
  // Elastic, and too much loss.
  EXPECT_EQ(CausalModulus(0.0).factor(123.0), cd(1.0, 0.0));
  EXPECT_THROW(CausalModulus{CausalModulus::largest_loss_factor()}, std::invalid_argument);  // braces: clang reads parentheses as a declaration
  EXPECT_THROW(CausalModulus(-0.01), std::invalid_argument);
  EXPECT_NO_THROW(CausalModulus(0.3));
}

// ---------------------------------------------------------------------------------------------
// 3. The orthotropic material.

TEST(OrthotropicMaterial, StiffnessInvertsTheComplianceAndChecksArePhysical) {
  const double e = 2e9, nu = 0.3;
  const OrthotropicStiffness iso = orthotropic_stiffness(OrthotropicConstants::isotropic(e, nu));
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  EXPECT_NEAR(iso.c11 / (lambda + 2 * mu), 1.0, 1e-14);
  EXPECT_NEAR(iso.c12 / lambda, 1.0, 1e-14);
  EXPECT_NEAR(iso.c55 / mu, 1.0, 1e-14);
  // A belt-like ply: C·S = I on the normal block.
  const OrthotropicConstants belt{3e9, 1.3e9, 3e7, 8e8, 1e7, 1e7, 0.3, 0.45, 0.45};
  const OrthotropicStiffness c = orthotropic_stiffness(belt);
  Eigen::Matrix3d cm, sm;
  cm << c.c11, c.c12, c.c13, c.c12, c.c22, c.c23, c.c13, c.c23, c.c33;
  sm << 1 / belt.youngs_x, -belt.poisson_xy / belt.youngs_x, -belt.poisson_xz / belt.youngs_x,  //
      -belt.poisson_xy / belt.youngs_x, 1 / belt.youngs_y, -belt.poisson_yz / belt.youngs_y,   //
      -belt.poisson_xz / belt.youngs_x, -belt.poisson_yz / belt.youngs_y, 1 / belt.youngs_z;
  EXPECT_LT((cm * sm - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_EQ(orthotropic_problem(belt), "");
  // Non-physical sets are named.
  OrthotropicConstants bad = belt;
  bad.poisson_xy = 0.9;  // |ν_xy| ≥ √(E_x/E_y)? no: 0.9 < 1.52, but ν_yx·ν_xy pushes the block indefinite with ν_yz
  bad.poisson_yz = 6.5;  // √(E_y/E_z) = 6.58: allowed alone
  EXPECT_NE(orthotropic_problem(bad, "belt_").find("not positive definite"), std::string::npos)
      << orthotropic_problem(bad, "belt_");
  bad = belt;
  bad.poisson_xy = 1.6;
  EXPECT_NE(orthotropic_problem(bad, "belt_").find("belt_poisson_xy"), std::string::npos);
  bad = belt;
  bad.shear_xz = 0.0;
  EXPECT_NE(orthotropic_problem(bad, "belt_").find("belt_shear_modulus_xz"), std::string::npos);
  EXPECT_THROW(orthotropic_stiffness(bad), std::invalid_argument);
  EXPECT_THROW(OrthotropicConstants::isotropic(1e6, 0.5), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// 4. The exact layer stiffness.

// The Stroh matrix A of d/dz [u; τ] = A [u; τ] for the field e^{i(kx x + ky y + ωt)}, straight
// from the field equations (Hooke's law and ρü = ∇·σ), with u = (u_x, u_y, u_z) and
// τ = (σ_xz, σ_yz, σ_zz): column j is the derivative of the state e_j. In long double, so that
// the transfer matrix below is a reference to ~1e-15 where e^{2λh} stays below ~1e4.
using cl = cld;
using Matrix6cl = Eigen::Matrix<cl, 6, 6>;

Matrix6cl stroh_matrix(const OrthotropicStiffness& s0, cd psi_d, double rho, double kx_d, double ky_d, cd omega_d) {
  const cl i(0.0L, 1.0L), psi(psi_d.real(), psi_d.imag()), omega(omega_d.real(), omega_d.imag());
  const long double kx = kx_d, ky = ky_d;
  const cl c11 = psi * (long double)s0.c11, c22 = psi * (long double)s0.c22, c33 = psi * (long double)s0.c33,
           c12 = psi * (long double)s0.c12, c13 = psi * (long double)s0.c13, c23 = psi * (long double)s0.c23,
           c44 = psi * (long double)s0.c44, c55 = psi * (long double)s0.c55, c66 = psi * (long double)s0.c66;
  const cl inertia = (long double)rho * omega * omega;
  Matrix6cl a;
  for (int j = 0; j < 6; ++j) {
    Eigen::Matrix<cl, 6, 1> st = Eigen::Matrix<cl, 6, 1>::Zero();
    st(j) = 1.0L;
    const cl ux = st(0), uy = st(1), uz = st(2), sxz = st(3), syz = st(4), szz = st(5);
    // σ_xz = C55(u_x' + i kx u_z), σ_yz = C44(u_y' + i ky u_z), σ_zz = C13 ε_xx + C23 ε_yy + C33 u_z'.
    const cl dux = sxz / c55 - i * kx * uz;
    const cl duy = syz / c44 - i * ky * uz;
    const cl duz = (szz - c13 * i * kx * ux - c23 * i * ky * uy) / c33;
    const cl sxx = c11 * i * kx * ux + c12 * i * ky * uy + c13 * duz;
    const cl syy = c12 * i * kx * ux + c22 * i * ky * uy + c23 * duz;
    const cl sxy = c66 * (i * ky * ux + i * kx * uy);
    // −ρω² u = ∂x σ_x· + ∂y σ_y· + ∂z σ_z·.
    const cl dsxz = -inertia * ux - i * kx * sxx - i * ky * sxy;
    const cl dsyz = -inertia * uy - i * kx * sxy - i * ky * syy;
    const cl dszz = -inertia * uz - i * kx * sxz - i * ky * syz;
    a.col(j) << dux, duy, duz, dsxz, dsyz, dszz;
  }
  return a;
}

// The layer stiffness from the transfer matrix P = exp(A·h) (tractions scaled by C55 so that
// the exponential is well scaled).
Matrix6cd transfer_matrix_stiffness(const OrthotropicStiffness& s0, cd psi, double rho, double h, double kx,
                                    double ky, cd omega) {
  const long double scale = s0.c55;
  Eigen::Matrix<cl, 6, 1> d;
  d << 1.0L, 1.0L, 1.0L, scale, scale, scale;
  const Matrix6cl a = d.cwiseInverse().asDiagonal() * stroh_matrix(s0, psi, rho, kx, ky, omega) * d.asDiagonal();
  const Matrix6cl p = (a * cl((long double)h)).exp();
  using Matrix3cl = Eigen::Matrix<cl, 3, 3>;
  const Matrix3cl puu = p.block<3, 3>(0, 0), put = p.block<3, 3>(0, 3), ptu = p.block<3, 3>(3, 0),
                  ptt = p.block<3, 3>(3, 3);
  const Matrix3cl put_inv = put.inverse();
  Matrix6cl k;
  // τ_b = P_ut⁻¹(u_t − P_uu u_b), τ_t = P_tu u_b + P_tt τ_b; f_b = −τ_b, f_t = τ_t.
  k.block<3, 3>(0, 0) = scale * put_inv * puu;
  k.block<3, 3>(0, 3) = -scale * put_inv;
  k.block<3, 3>(3, 0) = scale * (ptu - ptt * put_inv * puu);
  k.block<3, 3>(3, 3) = scale * ptt * put_inv;
  Matrix6cd out;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) out(r, c) = cd((double)k(r, c).real(), (double)k(r, c).imag());
  return out;
}

TEST(LayerStiffness, MatchesTheTransferMatrixWhereItIsAccurate) {
  // From ω = 0 exactly (the isotropic layer's P and S roots coincide: a defective Jordan block)
  // through frequencies at which they split by round-off, by a little and by much: the divided
  // differences pass through all their regimes on this sweep, and the stiffness must match the
  // reference at each, so the static case is exact and the switches do not show. Wavenumbers
  // up to e^{λh} ≈ 2e3 (the belt's shear-lag root λ ≈ 17k).
  const OrthotropicStiffness belt = orthotropic_stiffness({3e9, 1.3e9, 3e7, 8e8, 1e7, 1e7, 0.3, 0.45, 0.45});
  const OrthotropicStiffness rubber = orthotropic_stiffness(OrthotropicConstants::isotropic(4e6, 0.48));
  const CausalModulus lossy(0.1);
  double worst = 0.0;
  struct Case {
    const OrthotropicStiffness* s;
    double rho, h;
  };
  for (const Case& c : {Case{&belt, 2000.0, 0.003}, Case{&rubber, 1150.0, 0.007}}) {
    for (const double kx : {0.0, 3.0, 40.0, 150.0}) {
      for (const double ky : {0.0, 17.0, 120.0}) {
        for (const cd omega : {cd(0.0), cd(1e-6), cd(1e-3), cd(0.3), cd(30.0), cd(2 * pi * 90), cd(2 * pi * 1500, -30.0),
                               cd(2 * pi * 6000)}) {
          if (kx == 0.0 && ky == 0.0 && omega == 0.0) continue;  // a free translation: K is singular
          for (const bool loss : {false, true}) {
            const cd psi = loss ? lossy.factor(omega) : cd(1.0);
            const Matrix6cd got = layer_stiffness(*c.s, psi, c.rho, c.h, kx, ky, omega).matrix();
            const Matrix6cd expected = transfer_matrix_stiffness(*c.s, psi, c.rho, c.h, kx, ky, omega);
            const double e = (got - expected).norm() / expected.norm();
            worst = std::max(worst, e);
            EXPECT_LT(e, 1e-11) << "h " << c.h << " kx " << kx << " ky " << ky << " omega " << omega;
          }
        }
      }
    }
  }
  std::printf("layer stiffness against exp(A h) in long double: worst relative difference %.2e\n", worst);
}

// Rayleigh–Lamb, in forms without poles (d = h/2, p² = ω²/c_P² − k², q² = ω²/c_S² − k²):
//   symmetric:      (q² − k²)² cos(pd)·sin(qd)/q + 4k²·p sin(pd)·cos(qd) = 0
//   antisymmetric:  (q² − k²)² sin(pd)/p·cos(qd) + 4k²·cos(pd)·q sin(qd) = 0
// with sin(xd)/x, x·sin(xd) and cos(xd) real for either sign of x².
double sin_over(double x2, double d) {
  if (x2 > 0) return std::sin(std::sqrt(x2) * d) / std::sqrt(x2);
  if (x2 < 0) return std::sinh(std::sqrt(-x2) * d) / std::sqrt(-x2);
  return d;
}
double cos_of(double x2, double d) { return x2 >= 0 ? std::cos(std::sqrt(x2) * d) : std::cosh(std::sqrt(-x2) * d); }

double rayleigh_lamb(bool symmetric, double k, double omega, double cp, double cs, double d) {
  const double p2 = omega * omega / (cp * cp) - k * k, q2 = omega * omega / (cs * cs) - k * k;
  const double a = (q2 - k * k) * (q2 - k * k);
  if (symmetric) return a * cos_of(p2, d) * sin_over(q2, d) + 4 * k * k * p2 * sin_over(p2, d) * cos_of(q2, d);
  return a * sin_over(p2, d) * cos_of(q2, d) + 4 * k * k * cos_of(p2, d) * q2 * sin_over(q2, d);
}

// Roots of g on [lo, hi] from sign changes on `steps` intervals, refined by bisection.
std::vector<double> roots(const std::function<double(double)>& g, double lo, double hi, int steps) {
  std::vector<double> found;
  double a = lo, ga = g(lo);
  for (int i = 1; i <= steps; ++i) {
    const double b = lo + (hi - lo) * i / steps, gb = g(b);
    if ((ga > 0) != (gb > 0)) {
      double x0 = a, x1 = b, g0 = ga;
      for (int it = 0; it < 200 && x1 - x0 > 1e-15 * x1; ++it) {
        const double mid = 0.5 * (x0 + x1), gm = g(mid);
        if ((gm > 0) == (g0 > 0)) {
          x0 = mid;
          g0 = gm;
        } else {
          x1 = mid;
        }
      }
      found.push_back(0.5 * (x0 + x1));
    }
    a = b;
    ga = gb;
  }
  return found;
}

TEST(LayerStiffness, FreePlateDispersionIsRayleighLamb) {
  // A free isotropic plate (lossless): the zeros of det K_s and det K_a on the (x, z) block
  // (k along x, so SH decouples) are its symmetric and antisymmetric Lamb modes.
  const double h = 0.01, d = h / 2, rho = 1500.0;
  double worst = 0.0;
  int compared = 0;
  for (const double nu : {0.3, 0.48}) {
    const OrthotropicStiffness s = orthotropic_stiffness(OrthotropicConstants::isotropic(2e9, nu));
    const double cs = std::sqrt(s.c55 / rho), cp = std::sqrt(s.c11 / rho);
    for (const double k : {20.0, 300.0, 1500.0}) {
      for (const bool symmetric : {true, false}) {
        const auto model = [&](double omega) {
          const LayerStiffness l = layer_stiffness(s, 1.0, rho, h, k, 0.0, omega);
          const Eigen::Matrix3cd& m = symmetric ? l.symmetric : l.antisymmetric;
          return (m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0)).real();
        };
        // Up to a little past the third shear cut-off.
        const double top = cs * std::hypot(k, 3.2 * pi / d);
        const std::vector<double> expected =
            roots([&](double w) { return rayleigh_lamb(symmetric, k, w, cp, cs, d); }, 1.0, top, 4000);
        ASSERT_FALSE(expected.empty());
        for (const double w : expected) {
          // The model's sign change within ±1e-5 of the reference root.
          const std::vector<double> got = roots(model, w * (1 - 1e-5), w * (1 + 1e-5), 1);
          ASSERT_EQ(got.size(), 1u) << "no zero of det K near the Lamb mode at " << w << " rad/s, k = " << k;
          // A zero, not a pole: |det| falls there.
          EXPECT_LT(std::abs(model(got[0])), 1e-6 * std::abs(model(w * (1 - 1e-3))));
          const double e = std::abs(got[0] / w - 1);
          worst = std::max(worst, e);
          EXPECT_LT(e, 1e-6) << (symmetric ? "symmetric" : "antisymmetric") << " k " << k << " nu " << nu;
          ++compared;
        }
      }
    }
  }
  std::printf("free plate: %d Lamb modes, worst relative frequency difference %.2e\n", compared, worst);
}

TEST(LayerStiffness, StaticIsTheLimitOfLowFrequencyAndLargeKhDoesNotOverflow) {
  // (The layer alone at ω = 0 and on the way up is checked against the reference above.)
  const OrthotropicStiffness belt = orthotropic_stiffness({3e9, 1.3e9, 3e7, 8e8, 1e7, 1e7, 0.3, 0.45, 0.45});
  const OrthotropicStiffness rubber = orthotropic_stiffness(OrthotropicConstants::isotropic(4e6, 0.48));
  // The stack with causal loss: Ĝ(ω) − Ĝ(0) = O(ω) (the relaxation), and ω = 0 is the limit.
  const TwoLayerStack stack(ElasticLayer{belt, 2000.0, 0.003, 0.05}, ElasticLayer{rubber, 1150.0, 0.007, 0.1}, 6e4,
                            9e3, 1.5e6, 0.08);
  const Eigen::Matrix3cd g0 = stack.surface_compliance(20.0, 17.0, 0.0);
  double previous = 0.0;
  for (const double omega : {1e-2, 1e-4, 1e-6, 1e-8}) {
    const double change = (stack.surface_compliance(20.0, 17.0, omega) - g0).norm() / g0.norm();
    std::printf("stack: omega %.0e rad/s: |G(omega) - G(0)|/|G(0)| = %.3e\n", omega, change);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / change, 100.0, 1.0);  // first order in ω
    }
    previous = change;
  }
  EXPECT_LT(previous, 1e-9);

  // Large k·h: finite, and the faces decouple: the top face of a thick rubber layer is the
  // static half-space, û_z/τ_z = 2(1 − ν²)/(E k), whatever lies below.
  for (const double kh : {1e2, 1e3, 1e5, 1e7}) {
    const double h = 0.007, k = kh / h;
    const LayerStiffness l = layer_stiffness(rubber, 1.0, 1150.0, h, k, 0.0, 0.0);
    const Matrix6cd km = l.matrix();
    ASSERT_TRUE(km.allFinite()) << kh;
    // (The coupling is e^{−kh} in exact arithmetic; computed as the difference of the two
    // families' stiffnesses it is at the level of their rounding.)
    const double coupling = km.block<3, 3>(3, 0).norm(), face = km.block<3, 3>(3, 3).norm();
    EXPECT_LT(coupling, 1e-13 * face) << kh;
    const Eigen::Matrix3cd g = km.block<3, 3>(3, 3).inverse();
    const double nu = 0.48, e = 4e6;
    EXPECT_NEAR(g(2, 2).real() * e * k / (2 * (1 - nu * nu)), 1.0, 1e-12) << kh;
    // The whole stack too (thin belt below: still the half-space at the surface).
    const Eigen::Matrix3cd gs = stack.surface_compliance(k, 0.0, 2 * pi * 1000.0);
    ASSERT_TRUE(gs.allFinite()) << kh;
  }
}

// ---------------------------------------------------------------------------------------------
// 5. The stack's symmetries.

TEST(TwoLayerStack, ReciprocityAndMirrorSymmetries) {
  const TwoLayerParameters p = test::tyre_like_two_layer(0, 1);
  const TwoLayerStack stack = make_two_layer_stack(p);
  const Eigen::Matrix3d mirror_x = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  const Eigen::Matrix3d mirror_y = Eigen::Vector3d(1, -1, 1).asDiagonal();
  double worst = 0.0;
  for (const double kx : {3.0, 60.0, 700.0}) {
    for (const double ky : {17.0, 250.0}) {
      for (const cd omega : {cd(0.0), cd(600.0), cd(2 * pi * 2500, -40.0)}) {
        const Eigen::Matrix3cd g = stack.surface_compliance(kx, ky, omega);
        // Reciprocity: Ĝ(k)ᵀ = Ĝ(−k); mirrors: Ĝ(−kx, ky) = Π_x Ĝ Π_x, Ĝ(kx, −ky) = Π_y Ĝ Π_y.
        const Eigen::Matrix3cd minus = stack.surface_compliance(-kx, -ky, omega);
        const Eigen::Matrix3cd mx = stack.surface_compliance(-kx, ky, omega);
        const Eigen::Matrix3cd my = stack.surface_compliance(kx, -ky, omega);
        const double n = g.norm();
        worst = std::max({worst, (g.transpose() - minus).norm() / n, (mirror_x * g * mirror_x - mx).norm() / n,
                          (mirror_y * g * mirror_y - my).norm() / n});
      }
    }
  }
  std::printf("stack reciprocity and mirror symmetry: worst %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
}  // namespace rollnoise
