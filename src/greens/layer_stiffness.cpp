#include "greens/layer_stiffness.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "greens/tanh_sqrt_function.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;

bool close(double a, double b) { return std::abs(a - b) <= 1e-10 * std::max(std::abs(a), std::abs(b)); }

// Isotropic to round-off: C11 = C22 = C33, C12 = C13 = C23, C44 = C55 = C66 = (C11 − C12)/2.
bool isotropic(const OrthotropicStiffness& s) {
  return close(s.c11, s.c22) && close(s.c11, s.c33) && close(s.c12, s.c13) && close(s.c12, s.c23) &&
         close(s.c44, s.c55) && close(s.c55, s.c66) && close(s.c55, 0.5 * (s.c11 - s.c12));
}

}  // namespace

Matrix6cd LayerStiffness::matrix() const {
  const Eigen::Vector3cd p(1.0, 1.0, -1.0);
  const Eigen::Matrix3cd sum = 0.5 * (symmetric + antisymmetric);
  const Eigen::Matrix3cd difference = 0.5 * (symmetric - antisymmetric);
  Matrix6cd k;
  k.block<3, 3>(0, 0) = p.asDiagonal() * sum * p.asDiagonal();
  k.block<3, 3>(0, 3) = p.asDiagonal() * difference;
  k.block<3, 3>(3, 0) = difference * p.asDiagonal();
  k.block<3, 3>(3, 3) = sum;
  return k;
}

LayerStiffness layer_stiffness(const OrthotropicStiffness& s, cd modulus_factor, double density, double thickness,
                               double kx, double ky, cd omega) {
  const cd i(0.0, 1.0);
  const double a = 0.5 * thickness;
  // Units: lengths in a, stresses in C0 = ψ·C55, tractions as τ̃ = τ·a/C0 (metres, like u).
  // Every ratio of moduli is then real (ψ multiplies all of them) and every entry of B and C
  // is of order (k·a)², (ω·a/c)² or a ratio of moduli.
  const cd c0 = modulus_factor * s.c55;
  const double x = kx * a, y = ky * a;
  const cd inertia = density * omega * omega * a * a / c0;  // Ω̃² = ρω²a²/C0
  const double r13 = s.c13 / s.c33, r23 = s.c23 / s.c33;
  const double q11 = (s.c11 - s.c13 * r13) / s.c55;  // plane-stress reduced stiffnesses / C55
  const double q22 = (s.c22 - s.c23 * r23) / s.c55;
  const double q12 = (s.c12 - s.c13 * r23) / s.c55;
  const double q66 = s.c66 / s.c55;

  // E' = B·O with E = (u_x, u_y, τ̃_zz), O = (u_z, τ̃_xz, τ̃_yz):
  //   u_x' = τ̃_xz·C0/C55 − i k_x u_z,  u_y' = τ̃_yz·C0/C44 − i k_y u_z,
  //   τ̃_zz' = −Ω̃² u_z − i k_x τ̃_xz − i k_y τ̃_yz.
  Eigen::Matrix3cd b;
  b << -i * x, 1.0, 0.0,  //
      -i * y, 0.0, s.c55 / s.c44,  //
      -inertia, -i * x, -i * y;
  // O' = C·E:
  //   u_z' = (τ̃_zz C0 − i k_x C13 u_x − i k_y C23 u_y)/C33,
  //   τ̃_xz' = (Q11 k_x² + C66 k_y² − Ω̃²) u_x + (Q12 + C66) k_x k_y u_y − i k_x (C13/C33) τ̃_zz,
  //   τ̃_yz' = (Q12 + C66) k_x k_y u_x + (C66 k_x² + Q22 k_y² − Ω̃²) u_y − i k_y (C23/C33) τ̃_zz.
  Eigen::Matrix3cd c;
  c << -i * x * r13, -i * y * r23, s.c55 / s.c33,  //
      q11 * x * x + q66 * y * y - inertia, (q12 + q66) * x * y, -i * x * r13,  //
      (q12 + q66) * x * y, q66 * x * x + q22 * y * y - inertia, -i * y * r23;

  // f(BC), and f(CB) from it: B·f(CB) = f(BC)·B exactly (B(CB)^j = (BC)^j B for every power,
  // and f(M) is a polynomial in M, the Hermite interpolant of f on the common spectrum of BC and
  // CB; Higham 2008, Cor. 1.34), so one matrix function serves both families. An isotropic
  // layer's roots are known: μ_P = k̃² − Ω̃²·C55/C11 and μ_S = k̃² − Ω̃² (twice), and its minimal
  // polynomial is (x − μ_P)(x − μ_S) at every ω, the static Jordan block included: the
  // two-point form is exact and needs no Schur form. Otherwise the general Schur–Parlett form.
  Eigen::Matrix3cd fe;
  if (isotropic(s)) {
    const cd mu_s = x * x + y * y - inertia;
    const cd mu_p = x * x + y * y - inertia * (s.c55 / s.c11);
    fe = tanh_sqrt(Eigen::Matrix3cd(b * c), mu_s, mu_p);
  } else {
    fe = tanh_sqrt(Eigen::Matrix3cd(b * c));
  }
  // Symmetric family at the top face: O = Q·E, Q = C·f(BC).
  const Eigen::Matrix3cd q = c * fe;
  // Solve u_z = Q00 u_x + Q01 u_y + Q02 τ̃_zz for τ̃_zz, then τ̃_xz, τ̃_yz follow.
  Eigen::Matrix3cd ks;  // rows (τ̃_xz, τ̃_yz, τ̃_zz), columns (u_x, u_y, u_z)
  {
    const cd inv = 1.0 / q(0, 2);
    const Eigen::RowVector3cd zz(-q(0, 0) * inv, -q(0, 1) * inv, inv);
    ks.row(2) = zz;
    for (int r = 0; r < 2; ++r) {
      ks.row(r) = q(r + 1, 2) * zz;
      ks(r, 0) += q(r + 1, 0);
      ks(r, 1) += q(r + 1, 1);
    }
  }
  // Antisymmetric family at the top face: E = R·O, R = B·f(CB) = f(BC)·B.
  const Eigen::Matrix3cd r = fe * b;
  // (u_x, u_y) = R[0:2,0] u_z + R_s (τ̃_xz, τ̃_yz): solve for the shear tractions.
  Eigen::Matrix3cd ka;
  {
    const Eigen::Matrix2cd w = r.block<2, 2>(0, 1).inverse();
    const Eigen::Vector2cd coupling = -w * r.block<2, 1>(0, 0);
    ka.block<2, 2>(0, 0) = w;
    ka.block<2, 1>(0, 2) = coupling;
    const Eigen::RowVector2cd row = r.block<1, 2>(2, 1);
    ka.block<1, 2>(2, 0) = row * w;
    ka(2, 2) = r(2, 0) + (row * coupling).value();
  }
  const cd scale = c0 / a;  // τ = (C0/a)·τ̃
  return {scale * ks, scale * ka};
}

}  // namespace rollnoise
