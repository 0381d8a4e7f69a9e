#include "radiation/equivalent_sources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
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
// The other mirror, y → −y (the tyre's centre plane).
Eigen::Vector3d mirrored_across(const Eigen::Vector3d& s) { return {s.x(), -s.y(), s.z()}; }

// Mirror partners are matched this close, relative to the body's size: they are computed by the
// same formulas, so exact to rounding; a looser match would make the split solve that of a
// slightly different (symmetrised) body.
constexpr double kMirrorTolerance = 1e-10;
constexpr double kNormalTolerance = 1e-9;

}  // namespace

Eigen::MatrixXcd MirrorPairing::even(const Eigen::MatrixXcd& x) const {
  if (x.rows() != size()) throw std::invalid_argument("mirror pairing: one row per point");
  const double h = std::sqrt(0.5);
  Eigen::MatrixXcd out(even_size(), x.cols());
  Eigen::Index i = 0;
  for (const auto& [a, b] : pairs) out.row(i++) = h * (x.row(a) + x.row(b));
  for (Eigen::Index f : fixed) out.row(i++) = x.row(f);
  return out;
}

Eigen::MatrixXcd MirrorPairing::odd(const Eigen::MatrixXcd& x) const {
  if (x.rows() != size()) throw std::invalid_argument("mirror pairing: one row per point");
  const double h = std::sqrt(0.5);
  Eigen::MatrixXcd out(odd_size(), x.cols());
  Eigen::Index i = 0;
  for (const auto& [a, b] : pairs) out.row(i++) = h * (x.row(a) - x.row(b));
  return out;
}

Eigen::MatrixXcd MirrorPairing::combine(const Eigen::MatrixXcd& even_part, const Eigen::MatrixXcd& odd_part) const {
  if (even_part.rows() != even_size() || odd_part.rows() != odd_size() || even_part.cols() != odd_part.cols())
    throw std::invalid_argument("mirror pairing: even and odd parts do not match the pairing");
  const double h = std::sqrt(0.5);
  Eigen::MatrixXcd out(size(), even_part.cols());
  Eigen::Index i = 0;
  for (const auto& [a, b] : pairs) {
    out.row(a) = h * (even_part.row(i) + odd_part.row(i));
    out.row(b) = h * (even_part.row(i) - odd_part.row(i));
    ++i;
  }
  for (Eigen::Index f : fixed) out.row(f) = even_part.row(i++);
  return out;
}

// Partners share x (and z): the candidates of each point are found by binary search in the
// points sorted by x, O(N log N) but for columns of equal x (the tread's rows across).
std::optional<MirrorPairing> find_mirror_pairing(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                                 double tolerance) {
  const Eigen::Index n = points.cols();
  const bool with_normals = normals.cols() > 0;
  if (with_normals && normals.cols() != n) throw std::invalid_argument("mirror pairing: one normal per point");
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return points(0, a) < points(0, b); });
  std::vector<double> xs;
  xs.reserve(order.size());
  for (Eigen::Index i : order) xs.push_back(points(0, i));
  std::vector<Eigen::Index> partner(static_cast<std::size_t>(n), -1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d image = mirrored_across(points.col(i));
    const auto lo = std::lower_bound(xs.begin(), xs.end(), image.x() - tolerance) - xs.begin();
    const auto hi = std::upper_bound(xs.begin(), xs.end(), image.x() + tolerance) - xs.begin();
    double best = std::numeric_limits<double>::infinity();
    for (auto c = lo; c < hi; ++c) {
      const Eigen::Index j = order[static_cast<std::size_t>(c)];
      const double d = (points.col(j) - image).norm();
      if (d > tolerance || d >= best) continue;
      if (with_normals && (normals.col(j) - mirrored_across(normals.col(i))).norm() > kNormalTolerance) continue;
      best = d;
      partner[static_cast<std::size_t>(i)] = j;
    }
    if (partner[static_cast<std::size_t>(i)] < 0) return std::nullopt;
  }
  MirrorPairing out;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = partner[static_cast<std::size_t>(i)];
    if (partner[static_cast<std::size_t>(j)] != i) return std::nullopt;  // not one-to-one
    if (j == i)
      out.fixed.push_back(i);
    else if (i < j)
      out.pairs.push_back(points(1, i) > points(1, j) ? std::make_pair(i, j) : std::make_pair(j, i));
  }
  return out;
}

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
                                     bool rigid_plane, Medium medium, Symmetry symmetry)
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
  if (symmetry == Symmetry::none) return;
  // The body's size: the diagonal of the box around the collocation points (the sources are inside).
  const double size = (surface_.rowwise().maxCoeff() - surface_.rowwise().minCoeff()).norm();
  const double tolerance = kMirrorTolerance * size;
  auto points = find_mirror_pairing(surface_, normals_, tolerance);
  auto sources_paired = find_mirror_pairing(sources_, Eigen::Matrix3Xd(3, 0), tolerance);
  // Worth splitting (and both halves non-empty) only with pairs in both sets.
  if (points && sources_paired && points->odd_size() > 0 && sources_paired->odd_size() > 0) {
    point_pairing_ = std::move(points);
    source_pairing_ = std::move(sources_paired);
  }
}

Eigen::MatrixXcd EquivalentSources::velocity_matrix(double k) const {
  std::vector<Eigen::Index> all(static_cast<std::size_t>(surface_.cols()));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  return velocity_matrix(k, all);
}

Eigen::MatrixXcd EquivalentSources::velocity_matrix(double k, const std::vector<Eigen::Index>& rows) const {
  const auto count = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXcd v(count, sources_.cols());
  for (Eigen::Index s = 0; s < sources_.cols(); ++s)
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Index m = rows[static_cast<std::size_t>(i)];
      // n·∇G. (Eigen's a.dot(b) conjugates a: the real normal goes first.)
      v(i, s) = -normals_.col(m).cast<Complex>().dot(helmholtz_green_gradient(surface_.col(m), sources_.col(s), k, rigid_plane_));
    }
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

EquivalentSourceSolve::Factor::Factor(const Eigen::MatrixXcd& matrix, double lambda)
    : rows(matrix.rows()), columns(matrix.cols()) {
  Eigen::MatrixXcd augmented(rows + columns, columns);
  augmented.topRows(rows) = matrix;
  augmented.bottomRows(columns) = Eigen::MatrixXcd::Identity(columns, columns) * lambda;
  qr.compute(augmented);
}

// q = R⁻¹ Qᴴ [v; 0]: the first Ns rows of Qᴴ[v; 0], then back substitution.
Eigen::MatrixXcd EquivalentSourceSolve::Factor::strengths(const Eigen::MatrixXcd& velocities) const {
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(rows + columns, velocities.cols());
  padded.topRows(rows) = velocities;
  padded.applyOnTheLeft(qr.householderQ().adjoint());
  return qr.matrixQR().topLeftCorner(columns, columns).triangularView<Eigen::Upper>().solve(padded.topRows(columns));
}

// X V⁺ = (X R⁻¹) Q₁ᴴ with Q₁ the first M rows of Q: (X V⁺)ᴴ = Q₁ (X R⁻¹)ᴴ, i.e. Q applied to
// (X R⁻¹)ᴴ padded with zeros, first M rows. Cost: K reflector sweeps instead of M.
Eigen::MatrixXcd EquivalentSourceSolve::Factor::transfer(const Eigen::MatrixXcd& rows_per_source) const {
  const Eigen::MatrixXcd y = qr.matrixQR()
                                 .topLeftCorner(columns, columns)
                                 .triangularView<Eigen::Upper>()
                                 .adjoint()
                                 .solve(rows_per_source.adjoint());  // (X R⁻¹)ᴴ = R⁻ᴴ Xᴴ
  Eigen::MatrixXcd padded = Eigen::MatrixXcd::Zero(rows + columns, y.cols());
  padded.topRows(columns) = y;
  padded.applyOnTheLeft(qr.householderQ());
  return padded.topRows(rows).adjoint();
}

EquivalentSourceSolve::EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda)
    : surface_points_(velocity_matrix.rows()), source_count_(velocity_matrix.cols()) {
  factors_.emplace_back(velocity_matrix, lambda);
}

EquivalentSourceSolve::EquivalentSourceSolve(MirrorPairing points, MirrorPairing sources,
                                             const Eigen::MatrixXcd& even_matrix, const Eigen::MatrixXcd& odd_matrix,
                                             double lambda)
    : surface_points_(points.size()),
      source_count_(sources.size()),
      split_(true),
      point_pairing_(std::move(points)),
      source_pairing_(std::move(sources)) {
  if (even_matrix.rows() != point_pairing_.even_size() || even_matrix.cols() != source_pairing_.even_size() ||
      odd_matrix.rows() != point_pairing_.odd_size() || odd_matrix.cols() != source_pairing_.odd_size())
    throw std::invalid_argument("equivalent sources: the even and odd blocks do not match the pairings");
  factors_.emplace_back(even_matrix, lambda);
  factors_.emplace_back(odd_matrix, lambda);
}

// Split: q = A q_e + B q_o with q_e, q_o the half problems' solutions for U_eᵀv, U_oᵀv.
Eigen::MatrixXcd EquivalentSourceSolve::strengths(const Eigen::MatrixXcd& normal_velocities) const {
  if (normal_velocities.rows() != surface_points_)
    throw std::invalid_argument("equivalent sources: one velocity per surface point");
  if (!split_) return factors_[0].strengths(normal_velocities);
  return source_pairing_.combine(factors_[0].strengths(point_pairing_.even(normal_velocities)),
                                 factors_[1].strengths(point_pairing_.odd(normal_velocities)));
}

// Split: V⁺ = A V_e⁺ U_eᵀ + B V_o⁺ U_oᵀ, so X V⁺ = ((XA) V_e⁺) U_eᵀ + ((XB) V_o⁺) U_oᵀ, the
// bases applied to the transposes (XA = (AᵀXᵀ)ᵀ).
Eigen::MatrixXcd EquivalentSourceSolve::transfer(const Eigen::MatrixXcd& rows_per_source) const {
  if (rows_per_source.cols() != source_count_)
    throw std::invalid_argument("equivalent sources: one column per source");
  if (!split_) return factors_[0].transfer(rows_per_source);
  const Eigen::MatrixXcd xt = rows_per_source.transpose();
  const Eigen::MatrixXcd even = factors_[0].transfer(source_pairing_.even(xt).transpose());
  const Eigen::MatrixXcd odd = factors_[1].transfer(source_pairing_.odd(xt).transpose());
  return point_pairing_.combine(even.transpose(), odd.transpose()).transpose();
}

// λ is relative to the largest singular value, estimated by power iteration on VᴴV (a few
// per cent is plenty: it only sets the scale of a tiny regularisation).
//
// Split: V_e and V_o from the rows of V at one point of each pair and the fixed ones (half the
// Green's functions), by V(m′, s) = V(m, s′):
//   V_e(m, s) = V(m, s) + V(m, s′), V_e(m, g) = √2·V(m, g), V_o(m, s) = V(m, s) − V(m, s′)
// for pairs m, s and sources g on the plane, and the rows of points f on the plane divided by √2
// (there U_eᵀ has 1, not 1/√2 + 1/√2). The full iteration starts from ones, an even vector,
// and stays even (V commutes with the mirror): the same iteration on V_e from Aᵀ·1 (√2 per
// pair, 1 per fixed source) gives the same λ to rounding.
EquivalentSourceSolve EquivalentSources::solve(double omega, double regularisation) const {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent sources: the frequency must be > 0");
  const double k = omega / medium_.sound_speed;
  const auto largest_singular_value = [](const Eigen::MatrixXcd& v, Eigen::VectorXcd x) {
    double sigma_max = 0.0;
    for (int i = 0; i < 30; ++i) {
      const Eigen::VectorXcd y = v.adjoint() * (v * x);
      const double norm = y.norm();
      if (!(norm > 0.0)) break;
      sigma_max = std::sqrt(norm / x.norm());
      x = y / norm;
    }
    return sigma_max;
  };
  if (!point_pairing_) {
    const Eigen::MatrixXcd v = velocity_matrix(k);
    return EquivalentSourceSolve(v, regularisation * largest_singular_value(v, Eigen::VectorXcd::Ones(v.cols())));
  }
  const MirrorPairing& points = *point_pairing_;
  const MirrorPairing& sources = *source_pairing_;
  std::vector<Eigen::Index> rows;
  for (const auto& pair : points.pairs) rows.push_back(pair.first);
  rows.insert(rows.end(), points.fixed.begin(), points.fixed.end());
  const Eigen::MatrixXcd half = velocity_matrix(k, rows);  // even_size × Ns
  const double root2 = std::sqrt(2.0);
  Eigen::MatrixXcd even(points.even_size(), sources.even_size());
  Eigen::MatrixXcd odd(points.odd_size(), sources.odd_size());
  Eigen::Index j = 0;
  for (const auto& [s, mirror] : sources.pairs) {
    even.col(j) = half.col(s) + half.col(mirror);
    odd.col(j) = half.col(s).head(points.odd_size()) - half.col(mirror).head(points.odd_size());
    ++j;
  }
  for (Eigen::Index g : sources.fixed) even.col(j++) = root2 * half.col(g);
  even.bottomRows(static_cast<Eigen::Index>(points.fixed.size())) /= root2;
  Eigen::VectorXcd start = Eigen::VectorXcd::Ones(sources.even_size());
  start.head(sources.odd_size()) *= root2;
  const double lambda = regularisation * largest_singular_value(even, std::move(start));
  return EquivalentSourceSolve(points, sources, even, odd, lambda);
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
