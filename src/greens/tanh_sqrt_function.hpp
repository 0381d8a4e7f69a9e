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
// nearest pole (within r/16 of their centre) come from the Cauchy integral on a circle of radius
// r/4 about them (trapezoidal rule, 28 nodes: error below 2e-17); points within 1e-8·r, such as
// a repeated root split by round-off, take the derivatives f', f''/2 at their centre. Points
// farther apart use the recursive difference quotient, whose cancellation is then bounded by a
// small factor. The switches are continuous
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
// f(M) for a matrix whose minimal polynomial divides (x − μ1)(x − μ2), given μ1 and μ2: then
// f(M) = f(μ1)·I + f[μ1, μ2]·(M − μ1·I) exactly (Hermite interpolation), μ1 = μ2 included. An
// isotropic layer is such a case: its three roots are P, S, S, the two S waves (SV and SH) have
// independent eigenvectors, and at ω = 0, where P = S, the Jordan block has size 2. With μ1, μ2
// known in closed form this needs neither a Schur form nor a split of a repeated root.
Eigen::Matrix3cd tanh_sqrt(const Eigen::Matrix3cd& m, std::complex<double> mu1, std::complex<double> mu2);

// The distance from μ to the nearest pole of f.
double tanh_sqrt_pole_distance(std::complex<double> mu);

}  // namespace rollnoise
