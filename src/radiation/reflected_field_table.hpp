#pragma once
// The absorbing road's part of the half-space Green's function, tabulated for one frequency.
//
// Over the plane z = 0 of normalised admittance β the field of a point source is the free field,
// the rigid road's image and a correction C (impedance_plane_green.hpp):
//   G = e^{−ikR₁}/(4πR₁) + e^{−ikR₂}/(4πR₂) + C(r, Z),
// and C depends on the source and the receiver only through the horizontal distance r and the
// sum of the heights Z = z + z_s. The exact C costs 20–105 µs a point, too much for the
// equivalent sources' velocity matrix (10⁶–10⁷ pairs an anchor), so it is tabulated here.
//
// Coordinates: log-polar in the (r, Z) half-plane, ξ = ln R₂ and ψ = atan2(Z, r) (the elevation
// of the image seen from the receiver), ln(r + iZ) = ξ + iψ. The map is conformal, so a square
// grid in (ξ, ψ) is as fine in r as in Z everywhere, and fine in metres where R₂ is small (the
// sources millimetres above the road). What is tabulated is F = C/E with E = e^{−ikR₂}/(4πR₂),
// the correction relative to the image: F is the spherical reflection coefficient less one,
// which varies slowly in ξ (no e^{−ikR₂} oscillation left) and in ψ on the scale of |β| and
// 1/√(kR₂) near grazing incidence (the numerical distance). C is even in r, so F is even
// about ψ = π/2 and the grid may run past it.
//
// Interpolation: tensor-product Lagrange polynomials on `order` nodes per axis (4: cubic,
// 6: quintic) centred on the point, with their first and second derivatives, which the
// gradient and the combined sources' Hessian need (chain rule through E and the log-polar map).
// The accuracy is checked against the exact function (tests/radiation/test_half_space_green.cpp).
#include <complex>
#include <cstddef>
#include <vector>

namespace rollnoise {

// C and its derivatives in r and Z at one (r, Z).
struct ReflectedField {
  std::complex<double> value, dr, dz, drr, drz, dzz;
  // ∂C/∂r divided by r (→ ∂²C/∂r² as r → 0, where C is even in r).
  std::complex<double> dr_over_r;
};

class ReflectedFieldTable {
 public:
  // The region r ∈ [0, r_max], Z ∈ [z_min, z_max] (z_min > 0), for wavenumber k (> 0) and
  // admittance β (Re β ≥ 0, finite, non-zero), nodes `spacing` apart in ξ and ψ (radians),
  // `order` nodes per axis (4 or 6). Evaluates the exact C at every node (the cost).
  ReflectedFieldTable(double k, std::complex<double> admittance, double r_max, double z_min, double z_max,
                      double spacing, int order = 6);

  // Whether (r, Z) lies in the tabulated region.
  bool covers(double r, double z) const noexcept;
  // C and its derivatives at (r, Z) (covers(r, Z) must hold), up to the order `derivatives`
  // (0, 1 or 2; the higher ones are left zero: a monopole's velocity needs the first, a
  // combined source's the second).
  ReflectedField operator()(double r, double z, int derivatives = 2) const;

  std::size_t nodes() const noexcept { return values_.size(); }
  // About how many nodes (exact evaluations) a table of this region would take: a caller with
  // fewer pairs than that evaluates them exactly instead.
  static std::size_t estimated_nodes(double k, std::complex<double> admittance, double r_max, double z_min, double z_max,
                                     int order = 6);
  // The spacing of the table's nodes that interpolates C to about 1e-5 of the image's field
  // e^{−ikR₂}/(4πR₂) (with order 6; 1.3e-5 at worst in the tests): finer near grazing incidence
  // when |β| is small and kR₂ large, where F turns on the angular scale max(|β|, 1/√(kR₂)).
  static double spacing_for(double k, std::complex<double> admittance, double r_max, double z_max);

 private:
  template <int P>
  ReflectedField evaluate(double r, double z, int derivatives) const;

  double k_;
  double xi0_ = 0.0, psi0_ = 0.0, h_, hpsi_ = 0.0;  // the first node and the spacings in ξ and ψ
  int nxi_ = 0, npsi_ = 0, order_;
  double xi0_region_ = 0.0, psi0_region_ = 0.0, xi_max_ = 0.0, psi_max_ = 0.0;  // the region covered
  double r_max_ = 0.0, z_min_ = 0.0, z_max_ = 0.0;                              // and the box inside it
  std::vector<std::complex<double>> values_;  // F at (i, j): values_[i * npsi_ + j]
};

}  // namespace rollnoise
