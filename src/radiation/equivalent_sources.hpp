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
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "radiation/least_squares.hpp"
#include "radiation/symmetry_basis.hpp"

namespace rollnoise {

struct Medium {
  double density = 1.204;        // ρ, kg/m³ (air at 20 °C)
  double sound_speed = 343.2;    // c, m/s
};

// The road's normalised surface admittance β = ρ₀c₀/Z_s at a frequency (Hz), Re β ≥ 0
// (road/road_absorption.hpp computes it; the radiation takes it as a plain function so that it
// does not depend on the road library). β = 0: the rigid road.
using PlaneAdmittance = std::function<std::complex<double>(double frequency_hz)>;

// The free-field Green's function and its image in the rigid plane z = 0.
std::complex<double> helmholtz_green(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k, bool rigid_plane);
// ∇_x G.
Eigen::Vector3cd helmholtz_green_gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k,
                                          bool rigid_plane);

// The mirror y → −y (the tyre's centre plane), as a permutation of a point set: the pairs it
// exchanges and the points it maps to themselves (on the plane y = 0). The solve itself splits
// by SymmetryBasis (symmetry_basis.hpp), which covers this mirror and x → −x with it; this is
// the mirror's description for callers that check a mesh's symmetry.
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
// velocity per unit source strength), factorised once (least_squares.hpp: the normal equations
// by Cholesky when they are well conditioned, else the Householder QR of [V; λI]) and reused for
// any number of velocity patterns or receivers.
//
// Symmetric bodies (SymmetryBasis: the mirror y → −y, and x → −x too when the body has it): the
// problems of the group's characters are factorised instead, 2 or 4 of them, each of 1/2 or
// 1/4 the rows and columns. The solve costs ∝ rows·columns², so the halves cost 1/4 of the full
// problem and the quarters 1/16, for the same answer.
class EquivalentSourceSolve {
 public:
  // The full problem: V is M × Ns.
  EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda);
  // The split problem: blocks[c] is V in character c's bases of the points and the sources
  // (points.size(c) × sources.size(c)); λ as for the full problem.
  EquivalentSourceSolve(std::shared_ptr<const SymmetryBasis> points, std::shared_ptr<const SymmetryBasis> sources,
                        std::vector<Eigen::MatrixXcd> blocks, double lambda);

  // Source strengths for surface velocities: M × K → Ns × K.
  Eigen::MatrixXcd strengths(const Eigen::MatrixXcd& velocities) const;
  // The operator from surface velocities to what the rows measure: given K × Ns (a quantity
  // per unit source strength, such as receiver pressures), returns K × M, rows · V⁺.
  Eigen::MatrixXcd transfer(const Eigen::MatrixXcd& rows_per_source) const;

  // Whether the problem is split by symmetry, and into how many blocks (1: the full solve).
  bool mirror_split() const noexcept { return factors_.size() > 1; }
  int blocks() const noexcept { return static_cast<int>(factors_.size()); }
  // Whether every block took the normal equations (least_squares.hpp), and the smallest of the
  // blocks' reciprocal condition estimates of VᴴV + λ²I.
  bool normal_equations() const noexcept;
  double reciprocal_condition() const noexcept;

 private:
  friend class EquivalentSources;
  EquivalentSourceSolve() = default;
  Eigen::MatrixXcd unweighted_transfer(const Eigen::MatrixXcd& rows_per_source) const;

  Eigen::Index surface_points_ = 0;
  Eigen::Index source_count_ = 0;
  std::shared_ptr<const SymmetryBasis> point_basis_, source_basis_;  // split only
  std::vector<std::optional<RegularisedLeastSquares>> factors_;      // per block; empty: no unknowns or no rows
  Eigen::VectorXd row_scale_;  // √w of the collocation weights (empty: unweighted)
};

// Equivalent sources as combined sources (Brakhage & Werner's combined potential as point
// sources: Colton & Kress, "Integral Equation Methods in Scattering Theory", 1983, §3.6):
// Ψ = ∂G/∂n_s + iηkG, a dipole along the outward normal of the surface point the source is
// under plus a monopole, whose far field ik(n_s·x̂ + η)G points outwards (a cardioid for η = 1).
// Why: monopoles alone on an interior surface cannot represent an exterior field near the
// Dirichlet eigenfrequencies of the volume they enclose (a single layer whose interior problem
// is resonant), and from 2–3 kHz the tyre's interior has one every few Hz: the field of a
// monopole near the axle was rebuilt 40–65 % wrong at 4 and 5 kHz on the default mesh, and
// 8–31 % on meshes twice as fine. The combined layer has no such frequencies (a combined layer
// whose exterior field vanishes is zero); with it, 1–4 %.
struct CombinedSources {
  Eigen::Matrix3Xd normals;  // 3 × Ns unit vectors n_s
  double coupling = 1.0;     // η: the monopole's weight is iη_k with η_k = ηk + η₀
  double floor = 0.0;        // η₀, 1/m
};

// Stop the pivoted Cholesky factor of the power matrix when the largest pivot left is below this
// fraction of S's largest diagonal entry. What is dropped is then below the rounding error of
// qᴴSq itself, which is about ε·‖S‖·‖q‖² with ε = 2.2e-16 times the size: the factor's power
// equals the full matrix's to rounding (tests/radiation/test_radiation_cache.cpp checks 1e-10).
constexpr double kPowerFactorTolerance = 1e-15;

// The pivoted (diagonal pivoting) Cholesky factor L (n × r) of a Hermitian positive
// semidefinite S, S ≈ LLᴴ, stopped when the largest diagonal entry of the remainder falls to
// `tolerance` times S's largest diagonal entry (Harbrecht, Peters & Schneider, "On the low-rank
// approximation by the pivoted Cholesky decomposition", Appl. Numer. Math. 62, 2012: the
// remainder's trace is bounded by the pivots left). Costs O(n·r²): cheap when S has low rank.
Eigen::MatrixXcd pivoted_cholesky(const Eigen::MatrixXcd& s, double tolerance);

class EquivalentSources {
 public:
  // automatic: split the solve by the mirrors y → −y and x → −x, each when the sources and the
  // collocation points (with their normals) are symmetric under it within 1e-10 of the body's
  // size and it moves some of both (SymmetryBasis); centre_plane: by y → −y only; none, or no
  // symmetry found: the full solve. The answers agree to rounding.
  enum class Symmetry { automatic, centre_plane, none };

  // sources: 3 × Ns positions inside the body; surface: 3 × M collocation points with unit
  // outward normals (3 × M). rigid_plane: the plane z = 0 reflects (all points must lie in z > 0).
  // combined: combined sources (above) instead of monopoles.
  EquivalentSources(Eigen::Matrix3Xd sources, Eigen::Matrix3Xd surface, Eigen::Matrix3Xd normals, bool rigid_plane,
                    Medium medium = {}, Symmetry symmetry = Symmetry::automatic,
                    std::optional<CombinedSources> combined = std::nullopt);

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
  // Pressures (Pa) at the points `at` (3 × K) per unit source strength: K × Ns, iωρΨ (Ψ = G
  // for monopoles).
  Eigen::MatrixXcd pressure_matrix(double omega, const Eigen::Matrix3Xd& at) const;
  // The power matrix S (Ns × Ns, Hermitian) with radiated power W = ½ qᴴ S q for source
  // strengths q. Monopoles: S_ij = Re(iωρ G(s_i, s_j)) = (ωρk/4π)·[sinc(k r_ij) + sinc(k r_ij′)]
  // (real), the second term (image of s_j) only with the rigid plane; combined sources: the same
  // from their far fields (equivalent_sources.cpp). This is the power that crosses a surface
  // enclosing the sources (and, with the plane, the half-space above it), exact for the field
  // the sources make: no surface quadrature is involved.
  Eigen::MatrixXcd power_matrix(double omega) const;
  // ½ Re qᴴSq for each column of `strengths` (Ns × K), W; by the symmetry blocks when split.
  Eigen::VectorXd radiated_power(double omega, const Eigen::MatrixXcd& strengths) const;
  // A factor F (r × Ns) of the power matrix, S ≈ FᴴF, so that W = ½‖Fq‖²: the pivoted Cholesky
  // factor (pivoted_cholesky below) of S, or of each symmetry block S_c when split (its rows
  // then act on character c only). r is S's numerical rank at `tolerance`: few rows at low
  // frequency, where few source patterns radiate. With the solve's transfer() it makes the
  // power an operator on the surface velocities, W = ½‖(F·V⁺)v‖², that does not depend on them;
  // power_operator() gives the same by symmetry blocks (what the radiation cache stores).
  Eigen::MatrixXcd power_factor(double omega, double tolerance = kPowerFactorTolerance) const;
  // The power operator of `solve` (this model's solve at ω) on velocities of the first
  // `columns` collocation points (the others at rest), in the symmetry-adapted coordinates of
  // the points (point_coordinates): one block Q_c (r_c × t_c) per character of the split, so
  // that W = ½ Σ_c ‖Q_c x_c‖² with x = point_coordinates(v). Q_c = L_cᴴ·V_c⁺ with L_c the
  // pivoted Cholesky factor of the power matrix's block S_c: the blocks hold a quarter of the
  // numbers of the operator on the points (power_factor through transfer()), since V⁺ and S
  // do not couple the characters. Unsplit: one block, x = v. `columns` must be a union of the
  // points' orbits (the tread, or all points); std::invalid_argument otherwise.
  std::vector<Eigen::MatrixXcd> power_operator(const EquivalentSourceSolve& solve, double omega, Eigen::Index columns,
                                               double tolerance = kPowerFactorTolerance) const;
  // The coordinates of velocities v (columns × K, of the first `columns` points, the others at
  // rest) per character: t_c × K each (unsplit: v itself, weighted as the solve weighs rows).
  std::vector<Eigen::MatrixXcd> point_coordinates(const Eigen::MatrixXcd& v) const;
  // t_c for `columns` (the blocks' column counts, for checking a stored operator).
  std::vector<Eigen::Index> point_coordinate_counts(Eigen::Index columns) const;

  Eigen::Index source_count() const { return sources_.cols(); }
  bool combined_sources() const noexcept { return coupling_ > 0.0; }
  Eigen::Index surface_count() const { return surface_.cols(); }
  const Medium& medium() const noexcept { return medium_; }
  // Whether solve() splits the problem by the mirror y → −y (the centre plane).
  bool mirror_symmetric() const noexcept { return mirror_y_; }
  // The number of blocks solve() splits the problem into: 1, 2 (one mirror) or 4 (both).
  int symmetry_blocks() const noexcept { return point_basis_ ? point_basis_->characters() : 1; }
  // The plane z = 0 as an absorbing road (needs rigid_plane): at each ω the sources' field is
  // that of the half-space over the impedance plane of admittance β(ω/2π)
  // (half_space_green.hpp): the velocity matrix, the pressures and the power all use it. Where
  // β is 0 everything is exactly the rigid plane's. The power over an absorbing road is the
  // far-field intensity, with the plane-wave reflection coefficient, integrated over the
  // hemisphere (power_matrix); what the road absorbs is not radiated. An empty function: rigid.
  void set_plane_admittance(PlaneAdmittance admittance);
  // β at ω (0 when rigid or no admittance is set).
  std::complex<double> plane_admittance(double omega) const;
  // How solve() solves the least-squares problems (least_squares.hpp; default automatic).
  void set_least_squares_method(LeastSquaresMethod method) noexcept { method_ = method; }
  // Weights of the collocation points in the least squares, min Σ w_m |(Vq − v)_m|² (default:
  // all 1). With the points' areas the fit is that of the velocity over the surface, not over
  // the points: on a mesh graded towards the contact, unweighted, the 2 mm cells there count as
  // much as the 2 cm ones. Must be positive and, on a split solve, equal at mirror partners.
  void set_collocation_weights(const Eigen::VectorXd& weights);

 private:
  // −∂G/∂n at the collocation points `rows` (all: M × Ns).
  Eigen::MatrixXcd velocity_matrix(double k) const;
  Eigen::MatrixXcd velocity_matrix(double k, const std::vector<Eigen::Index>& rows) const;
  // S_ij/(ωρk³/4π) (power_matrix).
  std::complex<double> power_entry(Eigen::Index i, Eigen::Index j, double k) const;
  // S_c per character of the source basis (split only).
  std::vector<Eigen::MatrixXcd> power_blocks(double omega) const;
  // Over an absorbing road (β ≠ 0): S_c per character of the source basis when `split`, else
  // S alone, by quadrature of the far field over the hemisphere.
  std::vector<Eigen::MatrixXcd> far_field_power_blocks(double omega, std::complex<double> admittance, bool split) const;
  // Per character, the positions in its block of the point basis whose orbits lie in the first
  // `columns` points (split only; std::invalid_argument when an orbit straddles `columns`).
  std::vector<std::vector<Eigen::Index>> leading_coordinates(Eigen::Index columns) const;

  Eigen::Matrix3Xd sources_, surface_, normals_;
  Eigen::Matrix3Xd source_normals_;  // combined sources (zero for monopoles)
  double coupling_ = 0.0;            // η; 0: monopoles
  double coupling_floor_ = 0.0;      // η₀
  bool rigid_plane_;
  Medium medium_;
  std::shared_ptr<const SymmetryBasis> point_basis_, source_basis_;  // both set, or neither
  bool mirror_y_ = false;
  LeastSquaresMethod method_ = LeastSquaresMethod::automatic;
  Eigen::VectorXd row_scale_;  // √w (empty: unweighted)
  PlaneAdmittance admittance_;  // empty: the rigid plane
};

}  // namespace rollnoise
