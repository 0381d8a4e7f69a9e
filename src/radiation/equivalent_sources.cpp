#include "radiation/equivalent_sources.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/SVD>

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

Complex free_green(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k) {
  const double r = (x - s).norm();
  return std::exp(Complex(0.0, -k * r)) / (4.0 * std::numbers::pi * r);
}

// ∇_x of e^{−ikr}/(4πr): −(1 + ikr)/r² · G₀ · (x − s)/r … written as G₀·(−ik − 1/r)·(x − s)/r.
Eigen::Vector3cd free_gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k) {
  const Eigen::Vector3d d = x - s;
  const double r = d.norm();
  const Complex g = std::exp(Complex(0.0, -k * r)) / (4.0 * std::numbers::pi * r);
  return (g * (Complex(0.0, -k) - 1.0 / r) / r) * d.cast<Complex>();
}

Eigen::Vector3d mirrored(const Eigen::Vector3d& s) { return {s.x(), s.y(), -s.z()}; }

}  // namespace

Complex helmholtz_green(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k, bool rigid_plane) {
  Complex g = free_green(x, s, k);
  if (rigid_plane) g += free_green(x, mirrored(s), k);
  return g;
}

Eigen::Vector3cd helmholtz_green_gradient(const Eigen::Vector3d& x, const Eigen::Vector3d& s, double k,
                                          bool rigid_plane) {
  Eigen::Vector3cd g = free_gradient(x, s, k);
  if (rigid_plane) g += free_gradient(x, mirrored(s), k);
  return g;
}

EquivalentSources::EquivalentSources(Eigen::Matrix3Xd sources, Eigen::Matrix3Xd surface, Eigen::Matrix3Xd normals,
                                     bool rigid_plane, Medium medium)
    : sources_(std::move(sources)),
      surface_(std::move(surface)),
      normals_(std::move(normals)),
      rigid_plane_(rigid_plane),
      medium_(medium) {
  if (normals_.cols() != surface_.cols()) throw std::invalid_argument("equivalent sources: one normal per surface point");
  if (sources_.cols() == 0 || surface_.cols() < sources_.cols())
    throw std::invalid_argument("equivalent sources: need at least as many surface points as sources");
  if (rigid_plane_ && (sources_.row(2).minCoeff() <= 0.0 || surface_.row(2).minCoeff() <= 0.0))
    throw std::invalid_argument("equivalent sources: with a rigid plane every point must lie above it (z > 0)");
}

Eigen::MatrixXcd EquivalentSources::velocity_matrix(double k) const {
  Eigen::MatrixXcd v(surface_.cols(), sources_.cols());
  for (Eigen::Index s = 0; s < sources_.cols(); ++s)
    for (Eigen::Index m = 0; m < surface_.cols(); ++m)
      // n·∇G. (Eigen's a.dot(b) conjugates a: the real normal goes first.)
      v(m, s) = -normals_.col(m).cast<Complex>().dot(helmholtz_green_gradient(surface_.col(m), sources_.col(s), k, rigid_plane_));
  return v;
}

Eigen::MatrixXcd EquivalentSources::pressure_matrix(double omega, const Eigen::Matrix3Xd& at) const {
  const double k = omega / medium_.sound_speed;
  const Complex factor(0.0, omega * medium_.density);
  Eigen::MatrixXcd p(at.cols(), sources_.cols());
  for (Eigen::Index s = 0; s < sources_.cols(); ++s)
    for (Eigen::Index r = 0; r < at.cols(); ++r) p(r, s) = factor * helmholtz_green(at.col(r), sources_.col(s), k, rigid_plane_);
  return p;
}

// Tikhonov-regularised pseudo-inverse by the SVD: Σ σ/(σ² + λ²σ_max²) v uᴴ. Equivalent-source
// systems are ill-conditioned by nature (sources deep inside radiate nearly alike); the
// regularisation keeps the strengths bounded without changing a well-resolved field.
Eigen::MatrixXcd EquivalentSources::pseudo_inverse(const Eigen::MatrixXcd& v, double regularisation) const {
  const Eigen::BDCSVD<Eigen::MatrixXcd> svd(v, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const double lambda = regularisation * sigma(0);
  const Eigen::VectorXd filtered = sigma.array() / (sigma.array().square() + lambda * lambda);
  return svd.matrixV() * filtered.asDiagonal() * svd.matrixU().adjoint();
}

Eigen::MatrixXcd EquivalentSources::transfer(double omega, const Eigen::Matrix3Xd& receivers, double regularisation) const {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent sources: the frequency must be > 0");
  const double k = omega / medium_.sound_speed;
  return pressure_matrix(omega, receivers) * pseudo_inverse(velocity_matrix(k), regularisation);
}

Eigen::VectorXcd EquivalentSources::strengths(double omega, const Eigen::VectorXcd& normal_velocity,
                                              double regularisation) const {
  const double k = omega / medium_.sound_speed;
  return pseudo_inverse(velocity_matrix(k), regularisation) * normal_velocity;
}

double EquivalentSources::sound_power(double omega, const Eigen::VectorXcd& normal_velocity, const Eigen::VectorXd& areas,
                                      double regularisation) const {
  const Eigen::VectorXcd q = strengths(omega, normal_velocity, regularisation);
  const Eigen::VectorXcd p = pressure_matrix(omega, surface_) * q;
  double power = 0.0;
  for (Eigen::Index m = 0; m < surface_.cols(); ++m) power += 0.5 * (p(m) * std::conj(normal_velocity(m))).real() * areas(m);
  return power;
}

}  // namespace rollnoise
