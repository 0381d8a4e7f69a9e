#pragma once
// The Green's function of the half-space above the road, as the radiation uses it at one
// frequency: the free field, the rigid road's image, and over an absorbing road (normalised
// admittance β ≠ 0) the correction C(r, Z) of the impedance plane (impedance_plane_green.hpp),
//   G(x, s) = e^{−ikR₁}/(4πR₁) + e^{−ikR₂}/(4πR₂) + C(r, Z),
// r = |x_h − s_h| the horizontal distance, Z = x_z + s_z, time dependence e^{+iωt}.
//
// β = 0 is the rigid road and gives exactly the direct + image of equivalent_sources.hpp
// (helmholtz_green with the rigid plane): C is then not evaluated at all. Otherwise C comes from
// a table (reflected_field_table.hpp) over the region the caller names, the pairs of points that
// are many (collocation points and sources); outside it, from the exact line integral, with its
// derivatives by central differences (for the few far receivers: the pass-by microphone).
#include <complex>
#include <optional>

#include <Eigen/Core>

#include "radiation/reflected_field_table.hpp"

namespace rollnoise {

// The pairs a table should cover: r ≤ r_max, z_min ≤ Z ≤ z_max.
struct ReflectionRegion {
  double r_max = 0.0, z_min = 0.0, z_max = 0.0;
};

// The region of every pair (x, s) of `points` (3 × M) and `sources` (3 × N), all above the road.
ReflectionRegion reflection_region(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& sources);

class HalfSpaceGreen {
 public:
  // k > 0 (1/m); β with Re β ≥ 0, finite (0: the rigid road); a table over `region` when given
  // (and β ≠ 0), unless `evaluations` (> 0: about how many exact evaluations the caller's pairs
  // would take without one) is fewer than the table's nodes. Bad arguments: std::invalid_argument.
  HalfSpaceGreen(double k, std::complex<double> admittance, std::optional<ReflectionRegion> region = std::nullopt,
                 std::size_t evaluations = 0);

  bool rigid() const noexcept { return admittance_ == 0.0; }
  double wavenumber() const noexcept { return k_; }
  std::complex<double> admittance() const noexcept { return admittance_; }
  // How many exact evaluations the table took (0: no table).
  std::size_t table_nodes() const noexcept { return table_ ? table_->nodes() : 0; }

  // C and its derivatives in r and Z up to the order `derivatives` (0, 1 or 2; zero when
  // rigid): from the table where it covers (r, Z), else exact.
  ReflectedField correction(double r, double z, int derivatives = 2) const;
  // The exact C with derivatives by central differences (steps 1e-4 of Z and of R₂; their
  // truncation and the quadrature's rounding are below 1e-7 of the image's field).
  ReflectedField exact_correction(double r, double z, int derivatives = 2) const;

  // G(x, s) and ∇_x G (x and s above the road, x ≠ s).
  std::complex<double> operator()(const Eigen::Vector3d& x, const Eigen::Vector3d& s) const;
  Eigen::Vector3cd gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s) const;

 private:
  double k_;
  std::complex<double> admittance_;
  std::optional<ReflectedFieldTable> table_;
};

}  // namespace rollnoise
