#include "greens/orthotropic_material.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>

namespace rollnoise {
namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

Eigen::Matrix3d normal_compliance(const OrthotropicConstants& c) {
  Eigen::Matrix3d s;
  s << 1.0 / c.youngs_x, -c.poisson_xy / c.youngs_x, -c.poisson_xz / c.youngs_x,  //
      -c.poisson_xy / c.youngs_x, 1.0 / c.youngs_y, -c.poisson_yz / c.youngs_y,   //
      -c.poisson_xz / c.youngs_x, -c.poisson_yz / c.youngs_y, 1.0 / c.youngs_z;
  return s;
}

}  // namespace

OrthotropicConstants OrthotropicConstants::isotropic(double youngs_modulus, double poisson_ratio) {
  if (!positive(youngs_modulus)) throw std::invalid_argument("Young's modulus must be finite and > 0");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) {
    throw std::invalid_argument("Poisson's ratio must lie in (-1, 0.5)");
  }
  const double g = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  return {youngs_modulus, youngs_modulus, youngs_modulus, g, g, g, poisson_ratio, poisson_ratio, poisson_ratio};
}

std::string orthotropic_problem(const OrthotropicConstants& c, const std::string& prefix) {
  const auto need_positive = [&](double v, const char* name) -> std::string {
    return positive(v) ? "" : prefix + name + " must be finite and > 0";
  };
  for (const auto& [value, name] :
       {std::pair{c.youngs_x, "youngs_modulus_x"}, {c.youngs_y, "youngs_modulus_y"}, {c.youngs_z, "youngs_modulus_z"},
        {c.shear_xy, "shear_modulus_xy"}, {c.shear_xz, "shear_modulus_xz"}, {c.shear_yz, "shear_modulus_yz"}}) {
    if (std::string p = need_positive(value, name); !p.empty()) return p;
  }
  for (const auto& [value, name] :
       {std::pair{c.poisson_xy, "poisson_xy"}, {c.poisson_xz, "poisson_xz"}, {c.poisson_yz, "poisson_yz"}}) {
    if (!std::isfinite(value)) return prefix + name + " must be finite";
  }
  // |ν_ij| < √(E_i/E_j) for each pair; named, since it is the usual slip (ν_ij given for the
  // wrong direction of a strongly orthotropic ply).
  const auto bound = [&](double nu, double ei, double ej, const char* name) -> std::string {
    const double limit = std::sqrt(ei / ej);
    if (std::abs(nu) < limit) return "";
    return prefix + name + " = " + std::to_string(nu) + " must satisfy |ν| < √(E_i/E_j) = " + std::to_string(limit) +
           " (ν_ij is the contraction along j under a stress along i)";
  };
  if (std::string p = bound(c.poisson_xy, c.youngs_x, c.youngs_y, "poisson_xy"); !p.empty()) return p;
  if (std::string p = bound(c.poisson_xz, c.youngs_x, c.youngs_z, "poisson_xz"); !p.empty()) return p;
  if (std::string p = bound(c.poisson_yz, c.youngs_y, c.youngs_z, "poisson_yz"); !p.empty()) return p;
  // Positive definiteness of the whole normal block, scaled to unit diagonal so that the test
  // does not depend on the units' spread.
  Eigen::Matrix3d s = normal_compliance(c);
  const Eigen::Vector3d d = s.diagonal().cwiseSqrt().cwiseInverse();
  s = d.asDiagonal() * s * d.asDiagonal();
  Eigen::LLT<Eigen::Matrix3d> llt(s);
  if (llt.info() != Eigen::Success || llt.matrixL().toDenseMatrix().diagonal().minCoeff() < 1e-6) {
    return prefix + "poisson_xy, " + prefix + "poisson_xz, " + prefix +
           "poisson_yz give a compliance that is not positive definite (need 1 − ν_xy ν_yx − ν_yz ν_zy − ν_xz ν_zx "
           "− 2 ν_yx ν_zy ν_xz > 0): the strain energy would not be positive";
  }
  return "";
}

OrthotropicStiffness orthotropic_stiffness(const OrthotropicConstants& c) {
  if (const std::string p = orthotropic_problem(c); !p.empty()) throw std::invalid_argument(p);
  const Eigen::Matrix3d s = normal_compliance(c);
  const Eigen::Matrix3d k = s.inverse();
  OrthotropicStiffness r;
  r.c11 = k(0, 0);
  r.c22 = k(1, 1);
  r.c33 = k(2, 2);
  // The inverse of a symmetric matrix is symmetric up to round-off; average to make it exact.
  r.c12 = 0.5 * (k(0, 1) + k(1, 0));
  r.c13 = 0.5 * (k(0, 2) + k(2, 0));
  r.c23 = 0.5 * (k(1, 2) + k(2, 1));
  r.c44 = c.shear_yz;
  r.c55 = c.shear_xz;
  r.c66 = c.shear_xy;
  return r;
}

}  // namespace rollnoise
