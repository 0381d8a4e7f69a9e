#pragma once
// The exact dynamic stiffness of one homogeneous orthotropic elastic layer (axes x, y in the
// plane, z across it) for a field e^{i(k_x x + k_y y + ωt)}: the 3-D elastodynamic equations,
// no plate theory (MODEL.md §4, the two-layer tyre).
//
// Face vectors: u = (u_x, u_y, u_z) the displacement, f = the external force per area on the
// face (the traction τ = (σ_xz, σ_yz, σ_zz) on the top face, −τ on the bottom face):
//   [f_bottom; f_top] = K [u_bottom; u_top]   (K 6×6).
//
// Method. The state (u, τ) obeys d/dz [u; τ] = A [u; τ] (the Stroh form). For orthotropic
// symmetry with an axis along z the state splits into E = (u_x, u_y, σ_zz) and
// O = (u_z, σ_xz, σ_yz) with E' = B·O and O' = C·E (B, C 3×3), so E'' = (BC)·E. About the
// mid-plane ζ = 0 (half-thickness a) every solution is a sum of
//   - the symmetric family: E even in ζ, O odd:  E = cosh(ζ√M_E)E₀, O = C·sinh(ζ√M_E)/√M_E·E₀,
//     so at the face O = C·f(M_E)·E with M_E = a²BC;
//   - the antisymmetric family: E = B·f(M_O)·O at the face, M_O = a²CB;
// where f(μ) = tanh(√μ)/√μ (tanh_sqrt_function.hpp), all in units of a. f is bounded where the
// exponentials of a transfer matrix overflow (large k·h: the faces decouple, as in the
// stiffness method of Kausel & Roësset 1981 and Rokhlin & Wang 2002), it needs no eigenvectors
// (the repeated S root of an isotropic layer, the defective P = S root at ω → 0 and the static
// case ω = 0 are exact), and f(μ) → 1 − μ/3 carries thin layers and low frequencies without
// cancellation. Each family's relation between face displacements and tractions is solved for
// the tractions: the half-layer stiffnesses K_s, K_a (3×3, traction on the top face per top-face
// displacement). With P = diag(1, 1, −1) (the mirror ζ → −ζ):
//   f_top    = ½(K_s + K_a) u_top + ½(K_s − K_a) P u_bottom
//   f_bottom = ½P(K_s − K_a) u_top + ½P(K_s + K_a) P u_bottom.
// K has poles where the layer with both faces held resonates (a stiffness method's nature); the
// zeros of det K_s and det K_a are the symmetric and antisymmetric free-plate (Rayleigh–Lamb)
// modes.
#include <complex>

#include <Eigen/Core>

#include "greens/orthotropic_material.hpp"

namespace rollnoise {

using Matrix6cd = Eigen::Matrix<std::complex<double>, 6, 6>;

struct LayerStiffness {
  Eigen::Matrix3cd symmetric;      // K_s, N/m³ (traction per displacement per … per metre)
  Eigen::Matrix3cd antisymmetric;  // K_a
  // The 6×6 K of the header, rows and columns [bottom (x, y, z); top (x, y, z)].
  Matrix6cd matrix() const;
};

// `stiffness` holds the reference constants and `modulus_factor` the complex factor ψ(ω) that
// multiplies all of them (CausalModulus). kx, ky in rad/m (real), ω in rad/s (complex allowed:
// Im ω ≤ 0 for the exponential window).
LayerStiffness layer_stiffness(const OrthotropicStiffness& stiffness, std::complex<double> modulus_factor,
                               double density, double thickness, double kx, double ky, std::complex<double> omega);

}  // namespace rollnoise
