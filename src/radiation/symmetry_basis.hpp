#pragma once
// A point set invariant under one or two commuting reflections (y → −y, the tyre's centre plane;
// x → −x, the plane across the road through the axle, when the loaded tyre's patch is centred
// under it), split into the symmetry-adapted orthonormal bases of the group's characters.
//
// Why: when the collocation points (with their normals) and the sources are both invariant, and
// the Green's function is too (free field, or with the rigid road z = 0, which both reflections
// keep), the velocity matrix commutes with the group, V(g·m, g·s) = V(m, s). In the bases of the
// group's irreducible representations V is block diagonal (Allgower, Böhmer, Georg & Miranda,
// "Exploiting symmetry in boundary element methods", SIAM J. Numer. Anal. 29, 1992). The groups
// here are Z₂ (one reflection) and Z₂ × Z₂ (two); all their representations are one-dimensional,
// characters χ_c(g) = (−1)^{popcount(c & g)} with c and g bit masks over the generators. The
// problem then splits into 2 or 4 independent problems of 1/2 or 1/4 the size: as the dense
// solve costs ∝ rows·columns², the 4 quarter problems cost 1/16 of the full one, 1/4 of the two
// halves.
//
// Basis. Each orbit O (the images of a representative r) carries, for each character trivial on
// r's stabiliser, the unit vector u(x) = χ(g_x)/√|O| for x = g_x·r ∈ O (well defined: two
// elements mapping r to x differ by a stabiliser element). These are orthonormal and complete,
// so ‖Vq − v‖² and ‖q‖² are sums over the characters and a Tikhonov-regularised solve with the
// same λ is exactly the full one. The blocks need V only at the representatives' rows:
//   V_c(a, b) = √(|O_a|/|O_b|) Σ_{y ∈ O_b} χ_c(g_y) V(r_a, y).
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class SymmetryBasis {
 public:
  struct Member {
    Eigen::Index point;
    int element;  // a group element (bit mask over the generators) mapping the representative here
  };
  struct Orbit {
    std::vector<Member> members;  // the representative first (element 0)
    unsigned characters = 0;      // bit c set: the orbit carries a basis vector of character c
  };

  // generators[j][i]: the image of point i under reflection j (involutions that commute); one or
  // two generators.
  explicit SymmetryBasis(std::vector<std::vector<Eigen::Index>> generators);

  int generators() const noexcept { return generators_; }
  int characters() const noexcept { return 1 << generators_; }
  Eigen::Index size() const noexcept { return points_; }
  // The dimension of character c's basis.
  Eigen::Index size(int character) const { return static_cast<Eigen::Index>(blocks_.at(static_cast<std::size_t>(character)).size()); }
  const std::vector<Orbit>& orbits() const noexcept { return orbits_; }
  // The orbits of character c's basis vectors, in order.
  const std::vector<Eigen::Index>& block(int character) const { return blocks_.at(static_cast<std::size_t>(character)); }
  static double character(int c, int element) { return __builtin_popcount(static_cast<unsigned>(c & element)) % 2 ? -1.0 : 1.0; }

  // The coordinates of x (one row per point, any columns) in character c's basis: U_cᵀx.
  Eigen::MatrixXcd reduce(const Eigen::MatrixXcd& x, int character) const;
  // The inverse: Σ_c U_c parts[c].
  Eigen::MatrixXcd expand(const std::vector<Eigen::MatrixXcd>& parts) const;

 private:
  int generators_ = 0;
  Eigen::Index points_ = 0;
  std::vector<Orbit> orbits_;
  std::vector<std::vector<Eigen::Index>> blocks_;  // per character: orbit indices
};

// The partner of each point under the reflection of coordinate `axis` (0: x → −x, 1: y → −y),
// positions matched within `tolerance` (m) and, when `normals` (3 × N) are given, normals
// mirrored within 1e-9. Empty if some point has no partner, or not a unique one.
std::optional<std::vector<Eigen::Index>> reflection_partners(const Eigen::Matrix3Xd& points,
                                                             const Eigen::Matrix3Xd& normals, int axis,
                                                             double tolerance);

}  // namespace rollnoise
