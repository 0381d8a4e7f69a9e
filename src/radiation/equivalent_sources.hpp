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

// The least-squares problem of one frequency, min ‖V q − v‖² + λ²‖q‖² (V: surface normal
// velocity per unit source strength), factorised once as the Householder QR of [V; λI] and
// reused for any number of velocity patterns or receivers. QR rather than the SVD: the tyre's
// systems are well conditioned (σ_max/σ_min ≈ 300 on the default mesh) and the QR is 3× faster;
// the λI rows keep the solve bounded on meshes where they are not.
class EquivalentSourceSolve {
 public:
  EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda);

  // Source strengths for surface velocities: M × K → Ns × K.
  Eigen::MatrixXcd strengths(const Eigen::MatrixXcd& normal_velocities) const;
  // The operator from surface velocities to what the rows measure: given K × Ns (a quantity
  // per unit source strength, such as receiver pressures), returns K × M, rows · V⁺.
  Eigen::MatrixXcd transfer(const Eigen::MatrixXcd& rows_per_source) const;

 private:
  Eigen::Index surface_points_ = 0;
  Eigen::Index source_count_ = 0;
  Eigen::HouseholderQR<Eigen::MatrixXcd> qr_;
};

class EquivalentSources {
 public:
  // sources: 3 × Ns positions inside the body; surface: 3 × M collocation points with unit
  // outward normals (3 × M). rigid_plane: the plane z = 0 reflects (all points must lie in z > 0).
  EquivalentSources(Eigen::Matrix3Xd sources, Eigen::Matrix3Xd surface, Eigen::Matrix3Xd normals, bool rigid_plane,
                    Medium medium = {});

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

 private:
  Eigen::MatrixXcd velocity_matrix(double k) const;  // M × Ns: −∂G/∂n

  Eigen::Matrix3Xd sources_, surface_, normals_;
  bool rigid_plane_;
  Medium medium_;
};

}  // namespace rollnoise
