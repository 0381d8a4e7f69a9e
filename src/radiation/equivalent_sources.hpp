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

  Eigen::Index source_count() const { return sources_.cols(); }
  Eigen::Index surface_count() const { return surface_.cols(); }

 private:
  Eigen::MatrixXcd velocity_matrix(double k) const;                               // M × Ns: −∂G/∂n
  Eigen::MatrixXcd pressure_matrix(double omega, const Eigen::Matrix3Xd& at) const;  // × Ns: iωρG
  Eigen::MatrixXcd pseudo_inverse(const Eigen::MatrixXcd& v, double regularisation) const;

  Eigen::Matrix3Xd sources_, surface_, normals_;
  bool rigid_plane_;
  Medium medium_;
};

}  // namespace rollnoise
