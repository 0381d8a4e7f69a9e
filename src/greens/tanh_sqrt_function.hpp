#pragma once
// f(μ) = tanh(√μ)/√μ of a scalar and of a 3×3 complex matrix: the one transcendental function
// behind the exact layer stiffness (layer_stiffness.hpp).
//
// f is even in √μ, so it is a single-valued function of μ, analytic everywhere except its poles
// μ_j = −(π(j + ½))², j = 0, 1, … (the clamped-layer resonances). It is bounded where a plain
// transfer matrix overflows: |f| ≈ |μ|^{−1/2} for large |μ| off the negative axis.
//
// A matrix function f(M) is computed without eigenvectors, so that repeated eigenvalues (the
// isotropic S waves, always) and defective ones (P and S at ω → 0, and the static case exactly)
// need no special case: M = U T U* (complex Schur form, U unitary) and f(T) from the divided
// differences of f on the diagonal of T (Higham, Functions of Matrices, 2008, Thm 4.11):
//   F_ii = f(t_ii),  F_01 = t_01 f[t_00, t_11],  F_12 = t_12 f[t_11, t_22],
//   F_02 = t_02 f[t_00, t_22] + t_01 t_12 f[t_00, t_11, t_22].
// Divided differences of points that lie close together compared with their distance r to the
// nearest pole (within r/8 of their centre) come from the Cauchy integral on a circle about
// them (trapezoidal rule: 64 nodes on radius r/2, or 24 nodes on r/8 for points within r/64,
// such as the round-off split of a repeated root; error below 1e-19 either way); for confluent
// points this is the derivative, exactly in the limit; points within 1e-8·r, such as a repeated
// root, take the derivatives f', f''/2 at their centre directly. Points farther apart use the recursive
// difference quotient, whose cancellation is then bounded by a small factor. The switch is continuous
// to round-off (tests/greens/test_two_layer_layer.cpp).
#include <complex>

#include <Eigen/Core>

namespace rollnoise {

std::complex<double> tanh_sqrt(std::complex<double> mu);
// Divided differences f[a, b] and f[a, b, c] (any order of the points; equal points allowed).
std::complex<double> tanh_sqrt_divided(std::complex<double> a, std::complex<double> b);
std::complex<double> tanh_sqrt_divided(std::complex<double> a, std::complex<double> b, std::complex<double> c);
// f(M) for any 3×3 complex matrix whose eigenvalues are not poles of f.
Eigen::Matrix3cd tanh_sqrt(const Eigen::Matrix3cd& m);

// The distance from μ to the nearest pole of f.
double tanh_sqrt_pole_distance(std::complex<double> mu);

}  // namespace rollnoise
