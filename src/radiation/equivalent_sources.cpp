#include "radiation/equivalent_sources.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>


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

EquivalentSourceSolve::EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda)
    : surface_points_(velocity_matrix.rows()), source_count_(velocity_matrix.cols()) {
  Eigen::MatrixXcd augmented(surface_points_ + source_count_, source_count_);
  augmented.topRows(surface_points_) = velocity_matrix;
  augmented.bottomRows(source_count_) = Eigen::MatrixXcd::Identity(source_count_, source_count_) * lambda;
  qr_.compute(augmented);
}

// q = R⁻¹ Qᴴ [v; 0]: the first Ns rows of Qᴴ[v; 0], then back substitution.
Eigen::MatrixXcd EquivalentSourceSolve::strengths(const Eigen::MatrixXcd& normal_velocities) const {
  if (normal_velocities.rows() != surface_points_)
    throw std::invalid_argument("equivalent sources: one velocity per surface point");
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(surface_points_ + source_count_, normal_velocities.cols());
  padded.topRows(surface_points_) = normal_velocities;
  padded.applyOnTheLeft(qr_.householderQ().adjoint());
  return qr_.matrixQR().topLeftCorner(source_count_, source_count_).triangularView<Eigen::Upper>().solve(
      padded.topRows(source_count_));
}

// X V⁺ = (X R⁻¹) Q₁ᴴ with Q₁ the first M rows of Q: (X V⁺)ᴴ = Q₁ (X R⁻¹)ᴴ, i.e. Q applied to
// (X R⁻¹)ᴴ padded with zeros, first M rows. Cost: K reflector sweeps instead of M.
Eigen::MatrixXcd EquivalentSourceSolve::transfer(const Eigen::MatrixXcd& rows_per_source) const {
  if (rows_per_source.cols() != source_count_)
    throw std::invalid_argument("equivalent sources: one column per source");
  const Eigen::MatrixXcd y = qr_.matrixQR()
                                 .topLeftCorner(source_count_, source_count_)
                                 .triangularView<Eigen::Upper>()
                                 .adjoint()
                                 .solve(rows_per_source.adjoint());  // (X R⁻¹)ᴴ = R⁻ᴴ Xᴴ
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(surface_points_ + source_count_, y.cols());
  padded.topRows(source_count_) = y;
  padded.applyOnTheLeft(qr_.householderQ());
  return padded.topRows(surface_points_).adjoint();
}

// λ is relative to the largest singular value, estimated by power iteration on VᴴV (a few
// per cent is plenty: it only sets the scale of a tiny regularisation).
EquivalentSourceSolve EquivalentSources::solve(double omega, double regularisation) const {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent sources: the frequency must be > 0");
  const Eigen::MatrixXcd v = velocity_matrix(omega / medium_.sound_speed);
  Eigen::VectorXcd x = Eigen::VectorXcd::Ones(v.cols());
  double sigma_max = 0.0;
  for (int i = 0; i < 30; ++i) {
    const Eigen::VectorXcd y = v.adjoint() * (v * x);
    const double norm = y.norm();
    if (!(norm > 0.0)) break;
    sigma_max = std::sqrt(norm / x.norm());
    x = y / norm;
  }
  return EquivalentSourceSolve(v, regularisation * sigma_max);
}

Eigen::MatrixXd EquivalentSources::power_matrix(double omega) const {
  const double k = omega / medium_.sound_speed;
  const double scale = omega * medium_.density * k / (4.0 * std::numbers::pi);
  const auto sinc = [](double x) { return x < 1e-8 ? 1.0 - x * x / 6.0 : std::sin(x) / x; };
  const Eigen::Index n = sources_.cols();
  Eigen::MatrixXd s(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Vector3d image = mirrored(sources_.col(j));
    for (Eigen::Index i = 0; i <= j; ++i) {
      double value = sinc(k * (sources_.col(i) - sources_.col(j)).norm());
      if (rigid_plane_) value += sinc(k * (sources_.col(i) - image).norm());
      s(i, j) = s(j, i) = scale * value;
    }
  }
  return s;
}

Eigen::MatrixXcd EquivalentSources::transfer(double omega, const Eigen::Matrix3Xd& receivers, double regularisation) const {
  return solve(omega, regularisation).transfer(pressure_matrix(omega, receivers));
}

Eigen::VectorXcd EquivalentSources::strengths(double omega, const Eigen::VectorXcd& normal_velocity,
                                              double regularisation) const {
  return solve(omega, regularisation).strengths(normal_velocity);
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
