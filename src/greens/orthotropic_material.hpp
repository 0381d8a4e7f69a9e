#pragma once
// A homogeneous elastic solid with orthotropic symmetry whose axes are x (circumferential),
// y (lateral) and z (normal to the layer): the belt of the two-layer tyre; the isotropic tread
// is the special case. Engineering constants in, stiffnesses out (MODEL.md §4).
//
// Compliance (Voigt order xx, yy, zz, yz, xz, xy; ν_ij = −ε_j/ε_i under a stress along i,
// ν_ji = ν_ij·E_j/E_i):
//   ε_xx = σ_xx/E_x − ν_yx σ_yy/E_y − ν_zx σ_zz/E_z      γ_yz = σ_yz/G_yz
//   ε_yy = −ν_xy σ_xx/E_x + σ_yy/E_y − ν_zy σ_zz/E_z     γ_xz = σ_xz/G_xz
//   ε_zz = −ν_xz σ_xx/E_x − ν_yz σ_yy/E_y + σ_zz/E_z     γ_xy = σ_xy/G_xy
// The stiffness C is its inverse: the 3×3 normal block inverted, C44 = G_yz, C55 = G_xz,
// C66 = G_xy. A strain energy that is positive for every strain needs the normal block of the
// compliance to be positive definite (Lempriere 1968: |ν_ij| < √(E_i/E_j) and
// 1 − ν_xy ν_yx − ν_yz ν_zy − ν_xz ν_zx − 2 ν_yx ν_zy ν_xz > 0).
#include <string>

namespace rollnoise {

struct OrthotropicConstants {
  double youngs_x = 0.0, youngs_y = 0.0, youngs_z = 0.0;  // Pa
  double shear_xy = 0.0, shear_xz = 0.0, shear_yz = 0.0;  // Pa
  double poisson_xy = 0.0, poisson_xz = 0.0, poisson_yz = 0.0;

  // E and ν with G = E/(2(1 + ν)) on every plane; −1 < ν < 0.5.
  static OrthotropicConstants isotropic(double youngs_modulus, double poisson_ratio);
};

// The nine independent stiffnesses (Pa), C_ij in Voigt notation.
struct OrthotropicStiffness {
  double c11 = 0.0, c22 = 0.0, c33 = 0.0, c12 = 0.0, c13 = 0.0, c23 = 0.0;
  double c44 = 0.0, c55 = 0.0, c66 = 0.0;
};

// Checks the constants (finite, positive moduli, positive-definite compliance); returns an
// empty string when they are physical, else what is wrong (naming the constant with `prefix`,
// e.g. "belt_").
std::string orthotropic_problem(const OrthotropicConstants& constants, const std::string& prefix = "");

// The stiffness of physical constants; std::invalid_argument with orthotropic_problem() otherwise.
OrthotropicStiffness orthotropic_stiffness(const OrthotropicConstants& constants);

}  // namespace rollnoise
