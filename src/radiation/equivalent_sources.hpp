#pragma once
// Sound radiation by the equivalent-source method (MODEL.md §5): the field outside a vibrating
// body is represented by monopoles placed inside it, whose strengths make the normal velocity
// match the body's on collocation points of its surface, in the least-squares sense with
// Tikhonov regularisation. With the road as a rigid plane z = 0, every source carries its image,
// so the road's boundary condition holds exactly and the horn between tyre and road is part of
// the geometry.
//
// Time dependence e^{iωt}. A monopole of volume velocity q at s gives
//   p(x) = iωρ·q·G(x, s),   G = e^{−ikr}/(4πr) (+ the image term),   k = ω/c,
// and by Euler's equation iωρ·v = −∇p the normal velocity v_n = −q·∂G/∂n.
#include <complex>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/QR>

namespace rollnoise {

struct Medium {
  double density = 1.204;        // ρ, kg/m³ (air at 20 °C)
  double sound_speed = 343.2;    // c, m/s
};

// The free-field Green's function and its image in the rigid plane z = 0.
std::complex<double> helmholtz_green(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k, bool rigid_plane);
// ∇_x G.
Eigen::Vector3cd helmholtz_green_gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k,
                                          bool rigid_plane);

// The mirror y → −y (the tyre's centre plane), as a permutation of a point set: the pairs it
// exchanges and the points it maps to themselves (on the plane y = 0).
//
// Why: when the collocation points and the sources are both mirror-symmetric (positions and
// normals), and the Green's function is too (free field, or with the road z = 0), the velocity
// matrix commutes with the mirror, V(m′, s′) = V(m, s). In the orthonormal bases of even and odd
// combinations, (x_m + x_m′)/√2 and x_f (on the plane) for the even part, (x_m − x_m′)/√2 for the
// odd, V is block diagonal: the problem splits into two independent half-size problems, the
// decomposition of symmetric boundary-value problems by the irreducible representations of their
// symmetry group (here Z₂; Allgower, Böhmer, Georg & Miranda, "Exploiting symmetry in boundary element
// methods", SIAM J. Numer. Anal. 29, 1992).
// The bases are orthonormal, so both ‖V q − v‖² and ‖q‖² are sums over the two parts and the
// Tikhonov-regularised solution with the same λ is exactly the full one.
struct MirrorPairing {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;  // (y > 0, its mirror at y < 0)
  std::vector<Eigen::Index> fixed;                            // on the plane

  Eigen::Index size() const { return static_cast<Eigen::Index>(2 * pairs.size() + fixed.size()); }
  Eigen::Index even_size() const { return static_cast<Eigen::Index>(pairs.size() + fixed.size()); }
  Eigen::Index odd_size() const { return static_cast<Eigen::Index>(pairs.size()); }
  // The coordinates of x (rows indexed by the set, any columns) in the even basis (pairs, then
  // the fixed points) and in the odd basis (pairs): x_e = U_eᵀx, x_o = U_oᵀx.
  Eigen::MatrixXcd even(const Eigen::MatrixXcd& x) const;
  Eigen::MatrixXcd odd(const Eigen::MatrixXcd& x) const;
  // The inverse: U_e·x_e + U_o·x_o.
  Eigen::MatrixXcd combine(const Eigen::MatrixXcd& even_part, const Eigen::MatrixXcd& odd_part) const;
};

// The mirror pairing of `points` (3 × N) with optional `normals` (3 × N, mirrored with the
// points; empty: positions only), positions matched within `tolerance` (m), normals within 1e-9.
// Empty optional if some point has no mirror partner (or not a unique one).
std::optional<MirrorPairing> find_mirror_pairing(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                                 double tolerance);

// The least-squares problem of one frequency, min ‖V q − v‖² + λ²‖q‖² (V: surface normal
// velocity per unit source strength), factorised once as the Householder QR of [V; λI] and
// reused for any number of velocity patterns or receivers. QR rather than the SVD: the tyre's
// systems are well conditioned (σ_max/σ_min ≈ 300 on the default mesh) and the QR is 3× faster;
// the λI rows keep the solve bounded on meshes where they are not.
//
// Mirror-symmetric bodies (MirrorPairing): the even and the odd half problems are factorised
// instead, each [V_e; λI] and [V_o; λI] of about half the rows and columns. The Householder QR
// costs ∝ rows·columns², so the two cost a quarter of the full one, for the same answer.
class EquivalentSourceSolve {
 public:
  // The full problem: V is M × Ns.
  EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda);
  // The split problem: V_e (points.even_size() × sources.even_size()) and V_o (odd sizes), the
  // blocks of V in the even and odd bases of the points' and the sources' pairings.
  EquivalentSourceSolve(MirrorPairing points, MirrorPairing sources, const Eigen::MatrixXcd& even_matrix,
                        const Eigen::MatrixXcd& odd_matrix, double lambda);

  // Source strengths for surface velocities: M × K → Ns × K.
  Eigen::MatrixXcd strengths(const Eigen::MatrixXcd& normal_velocities) const;
  // The operator from surface velocities to what the rows measure: given K × Ns (a quantity
  // per unit source strength, such as receiver pressures), returns K × M, rows · V⁺.
  Eigen::MatrixXcd transfer(const Eigen::MatrixXcd& rows_per_source) const;

  // Whether the split (mirror-symmetric) factorisation is used.
  bool mirror_split() const noexcept { return split_; }

 private:
  // One factorised problem [A; λI] = QR.
  struct Factor {
    Factor(const Eigen::MatrixXcd& matrix, double lambda);
    Eigen::MatrixXcd strengths(const Eigen::MatrixXcd& velocities) const;
    Eigen::MatrixXcd transfer(const Eigen::MatrixXcd& rows_per_source) const;
    Eigen::Index rows = 0, columns = 0;
    Eigen::HouseholderQR<Eigen::MatrixXcd> qr;
  };

  Eigen::Index surface_points_ = 0;
  Eigen::Index source_count_ = 0;
  bool split_ = false;
  MirrorPairing point_pairing_, source_pairing_;  // split only
  std::vector<Factor> factors_;                   // the full problem, or the even and the odd
};

class EquivalentSources {
 public:
  // automatic: split the solve by the mirror y → −y when the sources and the collocation points
  // (with their normals) are mirror-symmetric within 1e-10 of the body's size (MirrorPairing);
  // otherwise, or with `none`, the full solve. The answers agree to rounding.
  enum class Symmetry { automatic, none };

  // sources: 3 × Ns positions inside the body; surface: 3 × M collocation points with unit
  // outward normals (3 × M). rigid_plane: the plane z = 0 reflects (all points must lie in z > 0).
  EquivalentSources(Eigen::Matrix3Xd sources, Eigen::Matrix3Xd surface, Eigen::Matrix3Xd normals, bool rigid_plane,
                    Medium medium = {}, Symmetry symmetry = Symmetry::automatic);

  // The transfer matrix at angular frequency ω from the surface normal velocities (m/s, at the
  // M collocation points) to the pressures (Pa) at the receivers (3 × R): R × M. Tikhonov
  // regularisation λ relative to the largest singular value (e.g. 1e-8).
  Eigen::MatrixXcd transfer(double omega, const Eigen::Matrix3Xd& receivers, double regularisation = 1e-10) const;

  // The source strengths (volume velocities, m³/s) for given surface velocities.
  Eigen::VectorXcd strengths(double omega, const Eigen::VectorXcd& normal_velocity, double regularisation = 1e-10) const;

  // Radiated sound power (W) of the given surface velocities: ½ Re Σ p·v* ΔS over the surface,
  // with p from the sources at the collocation points and `areas` the surface element of each.
  double sound_power(double omega, const Eigen::VectorXcd& normal_velocity, const Eigen::VectorXd& areas,
                     double regularisation = 1e-10) const;

  // The factorised least-squares problem at ω (regularisation as for transfer()).
  EquivalentSourceSolve solve(double omega, double regularisation = 1e-10) const;
  // Pressures (Pa) at the points `at` (3 × K) per unit source strength: K × Ns, iωρG.
  Eigen::MatrixXcd pressure_matrix(double omega, const Eigen::Matrix3Xd& at) const;
  // The power matrix S (Ns × Ns, real symmetric) with radiated power W = ½ qᴴ S q for
  // source strengths q: S_ij = Re(iωρ G(s_i, s_j)) = (ωρk/4π)·[sinc(k r_ij) + sinc(k r_ij′)],
  // the second term (image of s_j) only with the rigid plane. This is the power that crosses a
  // surface enclosing the sources (and, with the plane, the half-space above it), exact for
  // the field the sources make: no surface quadrature is involved.
  Eigen::MatrixXd power_matrix(double omega) const;

  Eigen::Index source_count() const { return sources_.cols(); }
  Eigen::Index surface_count() const { return surface_.cols(); }
  const Medium& medium() const noexcept { return medium_; }
  // Whether solve() splits the problem by the mirror y → −y.
  bool mirror_symmetric() const noexcept { return point_pairing_.has_value(); }

 private:
  // −∂G/∂n at the collocation points `rows` (all: M × Ns).
  Eigen::MatrixXcd velocity_matrix(double k) const;
  Eigen::MatrixXcd velocity_matrix(double k, const std::vector<Eigen::Index>& rows) const;

  Eigen::Matrix3Xd sources_, surface_, normals_;
  bool rigid_plane_;
  Medium medium_;
  std::optional<MirrorPairing> point_pairing_, source_pairing_;  // both set, or neither
};

}  // namespace rollnoise
