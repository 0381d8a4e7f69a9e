#include "radiation/equivalent_sources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <cblas.h>

#include "core/blas_threads.hpp"
#include "core/gauss_legendre.hpp"
#include "radiation/half_space_green.hpp"

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

// The field of one equivalent source of unit strength at s (normal n_s), per iωρ, and the normal
// velocity it makes at x (normal n_x). Monopole: Ψ = G. Combined: Ψ = ∂G/∂n_s + iηkG
// = −n_s·∇_x G + iηkG. With G = e^{−ikr}/(4πr), d = x − s, û = d/r:
//   ∇_x G = G′û,  G′ = (−ik − 1/r)G,  G″ = (−k² + 2ik/r + 2/r²)G,
//   Hessian H = (G′/r)(I − ûûᵀ) + G″ûûᵀ,
//   velocity −n_x·∇_x Ψ: monopole −G′(n_x·û); combined n_xᵀHn_s − iηkG′(n_x·û).
struct SourceKernel {
  double k = 0.0;
  double monopole = 0.0;  // combined: η_k = ηk + η₀, the monopole's weight (1/m)
  bool combined = false;

  Complex field(const double* x, const double* s, const double* ns) const {
    const double dx = x[0] - s[0], dy = x[1] - s[1], dz = x[2] - s[2];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inverse = 1.0 / r;
    const Complex g = std::polar(0.25 / std::numbers::pi * inverse, -k * r);
    if (!combined) return g;
    const Complex gp = Complex(-inverse, -k) * g;
    const double su = (ns[0] * dx + ns[1] * dy + ns[2] * dz) * inverse;
    return -su * gp + Complex(0.0, monopole) * g;
  }

  Complex velocity(const double* x, const double* nx, const double* s, const double* ns) const {
    const double dx = x[0] - s[0], dy = x[1] - s[1], dz = x[2] - s[2];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inverse = 1.0 / r;
    const Complex g = std::polar(0.25 / std::numbers::pi * inverse, -k * r);
    const double nu = (nx[0] * dx + nx[1] * dy + nx[2] * dz) * inverse;
    // −G′ = (ik + 1/r)G
    if (!combined) return g * Complex(inverse, k) * nu;
    const Complex gp = Complex(-inverse, -k) * g;
    const Complex gpp = Complex(-k * k + 2.0 * inverse * inverse, 2.0 * k * inverse) * g;
    const double su = (ns[0] * dx + ns[1] * dy + ns[2] * dz) * inverse;
    const double nn = nx[0] * ns[0] + nx[1] * ns[1] + nx[2] * ns[2];
    return gp * inverse * (nn - nu * su) + gpp * (nu * su) - Complex(0.0, monopole) * gp * nu;
  }
};

// The absorbing road's correction C(r, Z) to the image (half_space_green.hpp) as the field of
// one source and the normal velocity it makes, r = |x_h − s_h|, Z = x_z + s_z, e = (x_h − s_h)/r
// (0 at r = 0, where ∂C/∂r vanishes). Monopole: Ψ = C, velocity −n_x·∇_x C =
// −C_r(n_x·e) − C_Z n_xz. Combined: Ψ = n_s·∇_s C + iη_k C = −C_r(n_s·e) + C_Z n_sz + iη_k C,
// velocity −n_xᵀ(∇_x∇_sᵀC)n_s + iη_k·(the monopole's), with
//   n_xᵀ(∇_x∇_sᵀC)n_s = −C_rr(n_x·e)(n_s·e) − (C_r/r)(n_xh·n_sh − (n_x·e)(n_s·e))
//                        + C_rZ[(n_x·e)n_sz − n_xz(n_s·e)] + C_ZZ n_xz n_sz.
struct ReflectionKernel {
  const HalfSpaceGreen* green = nullptr;  // null: the rigid road (no correction)
  double monopole = 0.0;  // η_k
  bool combined = false;

  struct Pair {
    ReflectedField c;
    double ex = 0.0, ey = 0.0;
  };
  Pair pair(const double* x, const double* s, int derivatives) const {
    const double dx = x[0] - s[0], dy = x[1] - s[1];
    const double r = std::sqrt(dx * dx + dy * dy);
    Pair p{green->correction(r, x[2] + s[2], derivatives)};
    if (r > 0.0) {
      p.ex = dx / r;
      p.ey = dy / r;
    }
    return p;
  }

  Complex field(const double* x, const double* s, const double* ns) const {
    const Pair p = pair(x, s, combined ? 1 : 0);
    if (!combined) return p.c.value;
    const double se = ns[0] * p.ex + ns[1] * p.ey;
    return -p.c.dr * se + p.c.dz * ns[2] + Complex(0.0, monopole) * p.c.value;
  }

  Complex velocity(const double* x, const double* nx, const double* s, const double* ns) const {
    const Pair p = pair(x, s, combined ? 2 : 1);
    const double xe = nx[0] * p.ex + nx[1] * p.ey;
    const Complex single = -p.c.dr * xe - p.c.dz * nx[2];
    if (!combined) return single;
    const double se = ns[0] * p.ex + ns[1] * p.ey;
    const double horizontal = nx[0] * ns[0] + nx[1] * ns[1];
    const Complex mixed = -p.c.drr * (xe * se) - p.c.dr_over_r * (horizontal - xe * se) +
                          p.c.drz * (xe * ns[2] - nx[2] * se) + p.c.dzz * (nx[2] * ns[2]);
    return -mixed + Complex(0.0, monopole) * single;
  }
};

// Spherical Bessel functions j0, j1/x and j2 (series below x = 0.1, where the closed forms
// cancel).
struct Bessel {
  double j0, j1, j1_over_x, j2;
};
Bessel spherical_bessel(double x) {
  if (x < 0.1) {
    const double x2 = x * x;
    return {1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0)),
            x / 3.0 * (1.0 - x2 / 10.0 * (1.0 - x2 / 28.0 * (1.0 - x2 / 54.0))),
            1.0 / 3.0 * (1.0 - x2 / 10.0 * (1.0 - x2 / 28.0 * (1.0 - x2 / 54.0))),
            x2 / 15.0 * (1.0 - x2 / 14.0 * (1.0 - x2 / 36.0 * (1.0 - x2 / 66.0)))};
  }
  const double sn = std::sin(x), cs = std::cos(x);
  const double j0 = sn / x;
  const double j1 = (sn / x - cs) / x;
  return {j0, j1, j1 / x, 3.0 * j1 / x - j0};
}

// Mirror partners are matched this close, relative to the body's size: they are computed by the
// same formulas, so exact to rounding; a looser match would make the split solve that of a
// slightly different (symmetrised) body.
constexpr double kMirrorTolerance = 1e-10;

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

std::optional<MirrorPairing> find_mirror_pairing(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                                 double tolerance) {
  const auto partner = reflection_partners(points, normals, 1, tolerance);
  if (!partner) return std::nullopt;
  MirrorPairing out;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Index j = (*partner)[static_cast<std::size_t>(i)];
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
                                     bool rigid_plane, Medium medium, Symmetry symmetry,
                                     std::optional<CombinedSources> combined)
    : sources_(std::move(sources)),
      surface_(std::move(surface)),
      normals_(std::move(normals)),
      rigid_plane_(rigid_plane),
      medium_(medium) {
  if (normals_.cols() != surface_.cols()) throw std::invalid_argument("equivalent sources: one normal per surface point");
  if (combined) {
    if (combined->normals.cols() != sources_.cols())
      throw std::invalid_argument("equivalent sources: combined sources need one normal per source");
    if (!(combined->coupling > 0.0) || !std::isfinite(combined->coupling))
      throw std::invalid_argument("equivalent sources: the combined sources' coupling must be > 0");
    for (Eigen::Index j = 0; j < sources_.cols(); ++j)
      if (!(std::abs(combined->normals.col(j).norm() - 1.0) < 1e-9))
        throw std::invalid_argument("equivalent sources: the combined sources' normals must be unit vectors");
    source_normals_ = std::move(combined->normals);
    coupling_ = combined->coupling;
    coupling_floor_ = combined->floor;
    if (!(coupling_floor_ >= 0.0) || !std::isfinite(coupling_floor_))
      throw std::invalid_argument("equivalent sources: the combined sources' coupling floor must be >= 0");
  } else {
    source_normals_ = Eigen::Matrix3Xd::Zero(3, sources_.cols());
  }
  if (sources_.cols() == 0 || surface_.cols() < sources_.cols())
    throw std::invalid_argument("equivalent sources: need at least as many surface points as sources");
  if (rigid_plane_ && (sources_.row(2).minCoeff() <= 0.0 || surface_.row(2).minCoeff() <= 0.0))
    throw std::invalid_argument("equivalent sources: with a rigid plane every point must lie above it (z > 0)");
  if (symmetry == Symmetry::none) return;
  // The body's size: the diagonal of the box around the collocation points (the sources are inside).
  const double size = (surface_.rowwise().maxCoeff() - surface_.rowwise().minCoeff()).norm();
  const double tolerance = kMirrorTolerance * size;
  std::vector<std::vector<Eigen::Index>> point_generators, source_generators;
  for (int axis : {1, 0}) {
    if (axis == 0 && symmetry == Symmetry::centre_plane) continue;
    auto points = reflection_partners(surface_, normals_, axis, tolerance);
    auto paired = reflection_partners(sources_, coupling_ > 0.0 ? source_normals_ : Eigen::Matrix3Xd(3, 0), axis, tolerance);
    if (!points || !paired) continue;
    // Worth splitting (and every block non-empty) only if it moves some points and some sources.
    const auto moves = [](const std::vector<Eigen::Index>& p) {
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i] != static_cast<Eigen::Index>(i)) return true;
      return false;
    };
    if (!moves(*points) || !moves(*paired)) continue;
    point_generators.push_back(std::move(*points));
    source_generators.push_back(std::move(*paired));
    if (axis == 1) mirror_y_ = true;
  }
  if (point_generators.empty()) return;
  point_basis_ = std::make_shared<const SymmetryBasis>(std::move(point_generators));
  source_basis_ = std::make_shared<const SymmetryBasis>(std::move(source_generators));
}

void EquivalentSources::set_collocation_weights(const Eigen::VectorXd& weights) {
  if (weights.size() == 0) {
    row_scale_.resize(0);
    return;
  }
  if (weights.size() != surface_.cols() || !(weights.minCoeff() > 0.0) || !weights.allFinite())
    throw std::invalid_argument("equivalent sources: one positive weight per collocation point");
  if (point_basis_)
    for (const SymmetryBasis::Orbit& orbit : point_basis_->orbits())
      for (const SymmetryBasis::Member& m : orbit.members)
        if (std::abs(weights(m.point) - weights(orbit.members.front().point)) > 1e-9 * weights(orbit.members.front().point))
          throw std::invalid_argument("equivalent sources: the weights must be equal at mirror partners");
  row_scale_ = weights.cwiseSqrt();
}

Eigen::MatrixXcd EquivalentSources::velocity_matrix(double k) const {
  std::vector<Eigen::Index> all(static_cast<std::size_t>(surface_.cols()));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  return velocity_matrix(k, all);
}

// −n·∇Ψ for each row and source, and its image's (SourceKernel).
Eigen::MatrixXcd EquivalentSources::velocity_matrix(double k, const std::vector<Eigen::Index>& rows) const {
  const auto count = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXcd v(count, sources_.cols());
  Eigen::Matrix3Xd x(3, count), n(3, count);
  for (Eigen::Index i = 0; i < count; ++i) {
    x.col(i) = surface_.col(rows[static_cast<std::size_t>(i)]);
    n.col(i) = normals_.col(rows[static_cast<std::size_t>(i)]);
  }
  const SourceKernel kernel{k, coupling_ * k + coupling_floor_, coupling_ > 0.0};
  // Over an absorbing road, the correction to the image from a table over these pairs.
  const Complex beta = plane_admittance(k * medium_.sound_speed);
  std::optional<HalfSpaceGreen> road;
  if (beta != 0.0 && count > 0) road.emplace(k, beta, reflection_region(x, sources_));
  const ReflectionKernel reflection{road ? &*road : nullptr, kernel.monopole, kernel.combined};
  for (Eigen::Index j = 0; j < sources_.cols(); ++j) {
    const Eigen::Vector3d s = sources_.col(j), ns = source_normals_.col(j);
    const Eigen::Vector3d image = mirrored(s), image_normal = mirrored(ns);
    Complex* column = v.col(j).data();
    for (Eigen::Index i = 0; i < count; ++i) {
      Complex value = kernel.velocity(x.col(i).data(), n.col(i).data(), s.data(), ns.data());
      if (rigid_plane_) value += kernel.velocity(x.col(i).data(), n.col(i).data(), image.data(), image_normal.data());
      if (reflection.green) value += reflection.velocity(x.col(i).data(), n.col(i).data(), s.data(), ns.data());
      column[i] = row_scale_.size() ? row_scale_(rows[static_cast<std::size_t>(i)]) * value : value;
    }
  }
  return v;
}

Eigen::MatrixXcd EquivalentSources::pressure_matrix(double omega, const Eigen::Matrix3Xd& at) const {
  const double k = omega / medium_.sound_speed;
  const Complex factor(0.0, omega * medium_.density);
  const SourceKernel kernel{k, coupling_ * k + coupling_floor_, coupling_ > 0.0};
  Eigen::MatrixXcd p(at.cols(), sources_.cols());
  for (Eigen::Index j = 0; j < sources_.cols(); ++j) {
    const Eigen::Vector3d s = sources_.col(j), ns = source_normals_.col(j);
    const Eigen::Vector3d image = mirrored(s), image_normal = mirrored(ns);
    for (Eigen::Index r = 0; r < at.cols(); ++r) {
      const Eigen::Vector3d x = at.col(r);
      Complex value = kernel.field(x.data(), s.data(), ns.data());
      if (rigid_plane_) value += kernel.field(x.data(), image.data(), image_normal.data());
      p(r, j) = factor * value;
    }
  }
  const Complex beta = plane_admittance(omega);
  if (beta == 0.0 || at.cols() == 0) return p;
  // The absorbing road's correction. A few receivers far apart (the CPX and pass-by
  // microphones) each get a table over their own pairs, which is small where they are far and
  // cheaper than the exact function for every source; many points (the surface) share one.
  const auto add = [&](const Eigen::Matrix3Xd& points, Eigen::Index first) {
    // The exact function for few pairs (1 evaluation each for monopoles, 5 for combined sources'
    // first derivatives), a table when that is cheaper.
    const auto evaluations = static_cast<std::size_t>(points.cols() * sources_.cols() * (kernel.combined ? 5 : 1));
    const HalfSpaceGreen road(k, beta, reflection_region(points, sources_), evaluations);
    const ReflectionKernel reflection{&road, kernel.monopole, kernel.combined};
    for (Eigen::Index j = 0; j < sources_.cols(); ++j)
      for (Eigen::Index r = 0; r < points.cols(); ++r)
        p(first + r, j) += factor * reflection.field(points.col(r).data(), sources_.col(j).data(), source_normals_.col(j).data());
  };
  constexpr Eigen::Index kShared = 8;
  if (at.cols() > kShared)
    add(at, 0);
  else
    for (Eigen::Index r = 0; r < at.cols(); ++r) add(at.col(r), r);
  return p;
}

void EquivalentSources::set_plane_admittance(PlaneAdmittance admittance) {
  if (admittance && !rigid_plane_) throw std::invalid_argument("equivalent sources: an admittance needs the plane z = 0");
  admittance_ = std::move(admittance);
}

std::complex<double> EquivalentSources::plane_admittance(double omega) const {
  if (!admittance_) return 0.0;
  const Complex beta = admittance_(omega / (2.0 * std::numbers::pi));
  if (!std::isfinite(beta.real()) || !std::isfinite(beta.imag()) || beta.real() < 0.0)
    throw std::invalid_argument("equivalent sources: the road's admittance must be finite with Re β >= 0 (a passive road)");
  return beta;
}

EquivalentSourceSolve::EquivalentSourceSolve(const Eigen::MatrixXcd& velocity_matrix, double lambda)
    : surface_points_(velocity_matrix.rows()), source_count_(velocity_matrix.cols()) {
  factors_.emplace_back(std::in_place, velocity_matrix);
  factors_.back()->factorise(lambda);
}

EquivalentSourceSolve::EquivalentSourceSolve(std::shared_ptr<const SymmetryBasis> points,
                                             std::shared_ptr<const SymmetryBasis> sources,
                                             std::vector<Eigen::MatrixXcd> blocks, double lambda)
    : surface_points_(points ? points->size() : 0),
      source_count_(sources ? sources->size() : 0),
      point_basis_(std::move(points)),
      source_basis_(std::move(sources)) {
  if (!point_basis_ || !source_basis_ || point_basis_->characters() != source_basis_->characters() ||
      static_cast<int>(blocks.size()) != point_basis_->characters())
    throw std::invalid_argument("equivalent sources: one block per character of matching symmetry bases");
  for (int c = 0; c < point_basis_->characters(); ++c) {
    Eigen::MatrixXcd& block = blocks[static_cast<std::size_t>(c)];
    if (block.rows() != point_basis_->size(c) || block.cols() != source_basis_->size(c))
      throw std::invalid_argument("equivalent sources: a block does not match the symmetry bases");
    if (block.rows() == 0 || block.cols() == 0) {
      factors_.emplace_back();
      continue;
    }
    factors_.emplace_back(std::in_place, std::move(block));
    factors_.back()->factorise(lambda);
  }
}

bool EquivalentSourceSolve::normal_equations() const noexcept {
  for (const auto& f : factors_)
    if (f && !f->normal_equations()) return false;
  return true;
}

double EquivalentSourceSolve::reciprocal_condition() const noexcept {
  double smallest = 1.0;
  for (const auto& f : factors_)
    if (f) smallest = std::min(smallest, f->reciprocal_condition());
  return smallest;
}

// Split: q = Σ_c W_c q_c with q_c the block's solution for U_cᵀv.
Eigen::MatrixXcd EquivalentSourceSolve::strengths(const Eigen::MatrixXcd& velocities) const {
  if (velocities.rows() != surface_points_)
    throw std::invalid_argument("equivalent sources: one velocity per surface point");
  const Eigen::MatrixXcd normal_velocities = row_scale_.size() ? Eigen::MatrixXcd(row_scale_.asDiagonal() * velocities) : velocities;
  if (!point_basis_) return factors_[0]->solve(normal_velocities);
  std::vector<Eigen::MatrixXcd> parts;
  for (int c = 0; c < point_basis_->characters(); ++c) {
    const auto& f = factors_[static_cast<std::size_t>(c)];
    parts.push_back(f ? f->solve(point_basis_->reduce(normal_velocities, c))
                      : Eigen::MatrixXcd::Zero(source_basis_->size(c), normal_velocities.cols()));
  }
  return source_basis_->expand(parts);
}

// Split: V⁺ = Σ_c W_c V_c⁺ U_cᵀ, so X V⁺ = Σ_c ((X W_c) V_c⁺) U_cᵀ, the bases applied to the
// transposes (X W_c = (W_cᵀXᵀ)ᵀ).
Eigen::MatrixXcd EquivalentSourceSolve::transfer(const Eigen::MatrixXcd& rows_per_source) const {
  Eigen::MatrixXcd t = unweighted_transfer(rows_per_source);
  if (row_scale_.size()) t = t * row_scale_.asDiagonal();
  return t;
}

Eigen::MatrixXcd EquivalentSourceSolve::unweighted_transfer(const Eigen::MatrixXcd& rows_per_source) const {
  if (rows_per_source.cols() != source_count_)
    throw std::invalid_argument("equivalent sources: one column per source");
  if (!point_basis_) return factors_[0]->apply_pseudo_inverse_right(rows_per_source);
  const Eigen::MatrixXcd xt = rows_per_source.transpose();
  std::vector<Eigen::MatrixXcd> parts;
  for (int c = 0; c < point_basis_->characters(); ++c) {
    const auto& f = factors_[static_cast<std::size_t>(c)];
    parts.push_back(f ? Eigen::MatrixXcd(f->apply_pseudo_inverse_right(source_basis_->reduce(xt, c).transpose()).transpose())
                      : Eigen::MatrixXcd::Zero(point_basis_->size(c), rows_per_source.rows()));
  }
  return point_basis_->expand(parts).transpose();
}

// λ is relative to the largest singular value, estimated by power iteration on VᴴV from ones
// (a few per cent is plenty: it only sets the scale of a tiny regularisation).
//
// Split: the blocks from the rows of V at each point orbit's representative (1/2 or 1/4 of the
// Green's functions), V_c(a, b) = √(|O_a|/|O_b|) Σ_{y ∈ O_b} χ_c(g_y) V(r_a, y)
// (symmetry_basis.hpp). The full iteration starts from ones, an invariant vector, and stays in
// the trivial character's subspace (V commutes with the group): the same iteration on that
// block from U_0ᵀ·1 (√|O| per orbit) gives the same λ to rounding.
EquivalentSourceSolve EquivalentSources::solve(double omega, double regularisation) const {
  if (!(omega > 0.0)) throw std::invalid_argument("equivalent sources: the frequency must be > 0");
  if (!(regularisation >= 0.0)) throw std::invalid_argument("equivalent sources: the regularisation must be >= 0");
  const double k = omega / medium_.sound_speed;
  if (!point_basis_) {
    EquivalentSourceSolve out;
    out.surface_points_ = surface_.cols();
    out.source_count_ = sources_.cols();
    out.row_scale_ = row_scale_;
    out.factors_.emplace_back(std::in_place, velocity_matrix(k), method_);
    RegularisedLeastSquares& f = *out.factors_.back();
    f.factorise(regularisation * std::sqrt(f.largest_singular_value_squared(Eigen::VectorXcd::Ones(sources_.cols()))));
    return out;
  }
  const SymmetryBasis& points = *point_basis_;
  const SymmetryBasis& sources = *source_basis_;
  std::vector<Eigen::Index> rows;
  for (const SymmetryBasis::Orbit& o : points.orbits()) rows.push_back(o.members.front().point);
  const Eigen::MatrixXcd reduced = velocity_matrix(k, rows);  // orbits × Ns
  EquivalentSourceSolve out;
  out.surface_points_ = points.size();
  out.source_count_ = sources.size();
  out.point_basis_ = point_basis_;
  out.source_basis_ = source_basis_;
  out.row_scale_ = row_scale_;
  for (int c = 0; c < points.characters(); ++c) {
    const std::vector<Eigen::Index>& row_orbits = points.block(c);
    const std::vector<Eigen::Index>& column_orbits = sources.block(c);
    if (row_orbits.empty() || column_orbits.empty()) {
      out.factors_.emplace_back();
      continue;
    }
    Eigen::VectorXd row_scale(static_cast<Eigen::Index>(row_orbits.size()));
    for (std::size_t i = 0; i < row_orbits.size(); ++i)
      row_scale(static_cast<Eigen::Index>(i)) =
          std::sqrt(static_cast<double>(points.orbits()[static_cast<std::size_t>(row_orbits[i])].members.size()));
    Eigen::MatrixXcd block(static_cast<Eigen::Index>(row_orbits.size()), static_cast<Eigen::Index>(column_orbits.size()));
    Eigen::VectorXcd column(reduced.rows());
    for (std::size_t j = 0; j < column_orbits.size(); ++j) {
      const SymmetryBasis::Orbit& orbit = sources.orbits()[static_cast<std::size_t>(column_orbits[j])];
      column.setZero();
      for (const SymmetryBasis::Member& m : orbit.members) column += SymmetryBasis::character(c, m.element) * reduced.col(m.point);
      const double scale = 1.0 / std::sqrt(static_cast<double>(orbit.members.size()));
      auto target = block.col(static_cast<Eigen::Index>(j));
      for (std::size_t i = 0; i < row_orbits.size(); ++i)
        target(static_cast<Eigen::Index>(i)) = (row_scale(static_cast<Eigen::Index>(i)) * scale) * column(row_orbits[i]);
    }
    out.factors_.emplace_back(std::in_place, std::move(block), method_);
  }
  // The trivial character's block holds every orbit of both sets.
  Eigen::VectorXcd start(sources.size(0));
  for (Eigen::Index j = 0; j < start.size(); ++j)
    start(j) = std::sqrt(static_cast<double>(sources.orbits()[static_cast<std::size_t>(sources.block(0)[static_cast<std::size_t>(j)])].members.size()));
  const double lambda = regularisation * std::sqrt(out.factors_[0]->largest_singular_value_squared(std::move(start)));
  for (auto& f : out.factors_)
    if (f) f->factorise(lambda);
  return out;
}

// The power of the sources' field from its far field: with Ψ_j → ik·a_j(x̂)·e^{ik x̂·s_j}
// e^{−ik|x|}/(4π|x|) far away (monopole a = 1/(ik); combined a = n_j·x̂ + η), the power into the
// whole space is ½qᴴSq with S_ij = (ωρk³/4π)·(1/4π)∮ a_i* a_j e^{ik x̂·(s_j − s_i)} dΩ; over the
// rigid plane, half that of the sources with their images, which by the mirror symmetry of the
// pairs is S_ij = (·)(C(i, j) + C(i, j′)). With u = k(s_j − s_i), ρ = |u|, û = u/ρ:
//   (1/4π)∮ e^{i x̂·u} = j₀(ρ),  (1/4π)∮ x̂ e^{i x̂·u} = i j₁(ρ) û,
//   (1/4π)∮ x̂x̂ᵀ e^{i x̂·u} = (j₁(ρ)/ρ) I − j₂(ρ) ûûᵀ,
// so C = η² j₀ + iη j₁ (n_i + n_j)·û + (j₁/ρ) n_i·n_j − j₂ (n_i·û)(n_j·û) for combined
// sources, and C = j₀/k² for monopoles.
Complex EquivalentSources::power_entry(Eigen::Index i, Eigen::Index j, double k) const {
  const auto coupling = [&](const Eigen::Vector3d& sj, const Eigen::Vector3d& nj) -> Complex {
    const Eigen::Vector3d u = k * (sj - sources_.col(i));
    const double rho = u.norm();
    const Bessel b = spherical_bessel(rho);
    if (!(coupling_ > 0.0)) return b.j0 / (k * k);
    const Eigen::Vector3d ni = source_normals_.col(i);
    const double eta = coupling_ + coupling_floor_ / k;
    if (rho == 0.0) return eta * eta + ni.dot(nj) / 3.0;
    const Eigen::Vector3d unit = u / rho;
    return Complex(eta * eta * b.j0 + b.j1_over_x * ni.dot(nj) - b.j2 * ni.dot(unit) * nj.dot(unit),
                   eta * b.j1 * (ni + nj).dot(unit));
  };
  Complex value = coupling(sources_.col(j), source_normals_.col(j));
  if (rigid_plane_) value += coupling(mirrored(sources_.col(j)), mirrored(source_normals_.col(j)));
  return value;
}

Eigen::MatrixXcd EquivalentSources::power_matrix(double omega) const {
  // Over an absorbing road: the one block of the unsplit quadrature, S itself.
  if (const Complex beta = plane_admittance(omega); beta != 0.0) return std::move(far_field_power_blocks(omega, beta, false).front());
  const double k = omega / medium_.sound_speed;
  const double scale = omega * medium_.density * k * k * k / (4.0 * std::numbers::pi);
  const Eigen::Index n = sources_.cols();
  Eigen::MatrixXcd s(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i <= j; ++i) {
      s(i, j) = scale * power_entry(i, j, k);
      s(j, i) = std::conj(s(i, j));
    }
  return s;
}

// Split: S commutes with the group like V, so qᴴSq = Σ_c q_cᴴ S_c q_c with q_c = W_cᵀq and
// S_c(a, b) = √(|O_a|/|O_b|) Σ_{y ∈ O_b} χ_c(g_y) S(r_a, y): the rows at the orbits'
// representatives only. Each S_c = W_cᵀSW_c is Hermitian (W_c real), and the blocks list their
// orbits in increasing order, so only the entries with b ≥ a are summed, from the S(r_a, y) with
// y in an orbit at or after a's (half of the representatives' rows: power_entry's Bessel
// functions were 9 % of a cold anchor on the split mesh), and S_c(b, a) = conj(S_c(a, b)).
std::vector<Eigen::MatrixXcd> EquivalentSources::power_blocks(double omega) const {
  if (const Complex beta = plane_admittance(omega); beta != 0.0) return far_field_power_blocks(omega, beta, true);
  const double k = omega / medium_.sound_speed;
  const double scale = omega * medium_.density * k * k * k / (4.0 * std::numbers::pi);
  const SymmetryBasis& basis = *source_basis_;
  const auto orbits = static_cast<Eigen::Index>(basis.orbits().size());
  std::vector<Eigen::Index> orbit_of(static_cast<std::size_t>(sources_.cols()), 0);
  for (Eigen::Index a = 0; a < orbits; ++a)
    for (const SymmetryBasis::Member& m : basis.orbits()[static_cast<std::size_t>(a)].members)
      orbit_of[static_cast<std::size_t>(m.point)] = a;
  Eigen::MatrixXcd rows(orbits, sources_.cols());  // S at the representatives' rows (those read below)
  for (Eigen::Index j = 0; j < sources_.cols(); ++j)
    for (Eigen::Index a = 0; a <= orbit_of[static_cast<std::size_t>(j)]; ++a)
      rows(a, j) = scale * power_entry(basis.orbits()[static_cast<std::size_t>(a)].members.front().point, j, k);
  std::vector<Eigen::MatrixXcd> blocks;
  for (int c = 0; c < basis.characters(); ++c) {
    const std::vector<Eigen::Index>& block = basis.block(c);
    const auto size = static_cast<Eigen::Index>(block.size());
    Eigen::MatrixXcd s(size, size);
    for (Eigen::Index b = 0; b < size; ++b) {
      const SymmetryBasis::Orbit& orbit = basis.orbits()[static_cast<std::size_t>(block[static_cast<std::size_t>(b)])];
      for (Eigen::Index a = 0; a <= b; ++a) {
        const Eigen::Index row = block[static_cast<std::size_t>(a)];
        Complex sum = 0.0;
        for (const SymmetryBasis::Member& m : orbit.members) sum += SymmetryBasis::character(c, m.element) * rows(row, m.point);
        const double size_a = static_cast<double>(basis.orbits()[static_cast<std::size_t>(row)].members.size());
        s(a, b) = std::sqrt(size_a / static_cast<double>(orbit.members.size())) * sum;
        if (a < b) s(b, a) = std::conj(s(a, b));
      }
    }
    blocks.push_back(std::move(s));
  }
  return blocks;
}

Eigen::VectorXd EquivalentSources::radiated_power(double omega, const Eigen::MatrixXcd& strengths) const {
  if (strengths.rows() != sources_.cols()) throw std::invalid_argument("equivalent sources: one strength per source");
  Eigen::VectorXd power = Eigen::VectorXd::Zero(strengths.cols());
  if (!source_basis_) {
    const Eigen::MatrixXcd sq = power_matrix(omega) * strengths;
    for (Eigen::Index c = 0; c < strengths.cols(); ++c) power(c) = 0.5 * strengths.col(c).dot(sq.col(c)).real();
    return power;
  }
  const std::vector<Eigen::MatrixXcd> blocks = power_blocks(omega);
  for (int c = 0; c < source_basis_->characters(); ++c) {
    const Eigen::MatrixXcd& s = blocks[static_cast<std::size_t>(c)];
    if (s.size() == 0) continue;
    const Eigen::MatrixXcd q = source_basis_->reduce(strengths, c);
    const Eigen::MatrixXcd sq = s * q;
    for (Eigen::Index col = 0; col < strengths.cols(); ++col) power(col) += 0.5 * q.col(col).dot(sq.col(col)).real();
  }
  return power;
}

// The power over an absorbing road. Far from the sources the field of source y in the
// direction x̂ (polar angle θ from the vertical, azimuth φ) is, per iωρ·e^{−ik|x|}/(4π|x|),
//   f_y(x̂) = ik[a_y(x̂)e^{ik x̂·s_y} + R_p(θ)·a_y′(x̂)e^{ik x̂·s_y′}],
// the direct wave and the plane wave that left the source downwards and reflected off the road
// with R_p = (cos θ − β)/(cos θ + β): the image s′ with the mirrored normal n′, a = 1/(ik) for a
// monopole and a = n·x̂ + η for a combined source. The exact field differs from this by terms
// that fall faster than 1/|x| (the surface wave, attenuated as Re β > 0, and the ground wave,
// which cancels the reflection at grazing incidence), so the power crossing a far hemisphere is
//   W = ½qᴴSq,  S_ij = (ωρk/16π²)·∫_{hemisphere} f_i* f_j dΩ,
// which for β = 0 is the closed form of the rigid plane (power_entry). It is the power that
// leaves through the air; what the road absorbs is not in it.
//
// Split by symmetry: R_p depends on θ only, so a mirror of the sources is a mirror of the
// directions, and the symmetrised patterns φ_b = Σ_{y ∈ O_b} χ_c(g_y) f_y/√|O_b| of one
// character make a product φ_a*φ_b invariant under the group: S_c(a, b) = W_cᵀSW_c is |G|
// times the integral over the fundamental domain of the azimuth (y ≥ 0 for the mirror y → −y,
// x ≥ 0 for x → −x).
//
// Quadrature: Gauss–Legendre in θ and φ, sin θ dθ dφ. The phase k x̂·(s_j − s_i) turns at most
// at kD per radian (D: the diameter of the sources with their images; in φ, kD_h with D_h their
// horizontal diameter), and Gauss–Legendre integrates e^{iαt} on [−1, 1] to rounding from about
// eα/4 ≈ 0.7α nodes: 0.7·kD·L/2 + 12 per panel of length L. R_p has its pole at cos θ = −β, a
// distance of about |β| below the horizon, so the last b = 4|β| (0.02 … 0.5 rad) of θ is a panel
// of its own. Checked against a quadrature twice as fine and against the rigid closed form
// (tests/radiation/test_half_space_green.cpp, test_sound_power_far_field.cpp).
std::vector<Eigen::MatrixXcd> EquivalentSources::far_field_power_blocks(double omega, std::complex<double> admittance,
                                                                        bool split) const {
  const double k = omega / medium_.sound_speed;
  const Eigen::Index n = sources_.cols();
  const bool combined = coupling_ > 0.0;
  const double eta = coupling_ + coupling_floor_ / k;
  // The group: which mirrors (SymmetryBasis's generators: y → −y first when the model has it).
  const SymmetryBasis* basis = split ? source_basis_.get() : nullptr;
  bool mirror_x = false, mirror_y = false;
  if (basis) {
    mirror_y = mirror_y_;
    mirror_x = basis->generators() == 2 || !mirror_y_;
  }
  const int order = basis ? basis->characters() : 1;
  const double pi = std::numbers::pi;
  const double phi_lo = mirror_y ? 0.0 : (mirror_x ? -0.5 * pi : 0.0);
  const double phi_hi = mirror_y ? (mirror_x ? 0.5 * pi : pi) : (mirror_x ? 0.5 * pi : 2.0 * pi);
  // Diameters of the sources with their images.
  const Eigen::Vector3d lo = sources_.rowwise().minCoeff(), hi = sources_.rowwise().maxCoeff();
  const double horizontal = std::hypot(hi.x() - lo.x(), hi.y() - lo.y());
  const double diameter = std::hypot(horizontal, 2.0 * hi.z());
  const auto nodes = [&](double extent, double length) { return static_cast<int>(std::ceil(0.35 * k * extent * length)) + 12; };
  const double edge = std::clamp(4.0 * std::abs(admittance), 0.02, 0.5);
  std::vector<double> theta, theta_weight;
  const auto add_panel = [](std::vector<double>& x, std::vector<double>& w, double a, double b, int count) {
    const GaussRule rule = gauss_legendre_rule(count);
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
      x.push_back(0.5 * (a + b) + 0.5 * (b - a) * rule.nodes[q]);
      w.push_back(0.5 * (b - a) * rule.weights[q]);
    }
  };
  add_panel(theta, theta_weight, 0.0, 0.5 * pi - edge, nodes(diameter, 0.5 * pi - edge));
  add_panel(theta, theta_weight, 0.5 * pi - edge, 0.5 * pi, nodes(diameter, edge) + 4);
  // Each ring of θ its own azimuths: the phase turns at k·sin θ·D_h per radian of φ.
  struct Direction {
    std::size_t ring;
    double x, y, weight;
  };
  std::vector<Direction> directions;
  for (std::size_t t = 0; t < theta.size(); ++t) {
    std::vector<double> phi, phi_weight;
    const double st = std::sin(theta[t]);
    add_panel(phi, phi_weight, phi_lo, phi_hi, nodes(horizontal * st, phi_hi - phi_lo));
    for (std::size_t a = 0; a < phi.size(); ++a)
      directions.push_back({t, st * std::cos(phi[a]), st * std::sin(phi[a]), std::sqrt(theta_weight[t] * st * phi_weight[a])});
  }
  const auto count = static_cast<Eigen::Index>(directions.size());
  // The blocks' orbits (unsplit: every source its own orbit of the trivial group).
  std::vector<std::vector<Eigen::Index>> block_orbits;
  if (basis)
    for (int c = 0; c < order; ++c) block_orbits.push_back(basis->block(c));
  else {
    block_orbits.emplace_back(static_cast<std::size_t>(n));
    std::iota(block_orbits.front().begin(), block_orbits.front().end(), Eigen::Index{0});
  }
  std::vector<Eigen::MatrixXcd> out;
  for (const auto& orbits : block_orbits) {
    const auto size = static_cast<Eigen::Index>(orbits.size());
    out.push_back(Eigen::MatrixXcd::Zero(size, size));
  }
  // Chunks of directions: f for every source there, the blocks' symmetrised patterns, and
  // S_c += F_cᴴF_c (zherk, lower triangle). e^{ik cos θ·s_z} once per ring.
  constexpr Eigen::Index kChunk = 256;
  const Complex ik(0.0, k);
  Eigen::MatrixXcd f(kChunk, n);
  std::vector<Eigen::MatrixXcd> patterns(out.size());
  std::vector<Complex> up(static_cast<std::size_t>(n));
  std::size_t ring = theta.size();  // none yet
  for (Eigen::Index first = 0; first < count; first += kChunk) {
    const Eigen::Index rows = std::min(kChunk, count - first);
    for (Eigen::Index d = 0; d < rows; ++d) {
      const Direction& direction = directions[static_cast<std::size_t>(first + d)];
      const double ct = std::cos(theta[direction.ring]);
      if (direction.ring != ring) {
        ring = direction.ring;
        for (Eigen::Index j = 0; j < n; ++j) up[static_cast<std::size_t>(j)] = std::polar(1.0, k * ct * sources_(2, j));
      }
      const Complex reflection = (ct - admittance) / (ct + admittance);
      for (Eigen::Index j = 0; j < n; ++j) {
        const double* s = sources_.col(j).data();
        const Complex horizontal_phase = std::polar(direction.weight, k * (direction.x * s[0] + direction.y * s[1]));
        const Complex u = up[static_cast<std::size_t>(j)];
        const Complex direct = horizontal_phase * u, image = horizontal_phase * std::conj(u);
        if (!combined) {
          f(d, j) = direct + reflection * image;
        } else {
          const double* ns = source_normals_.col(j).data();
          const double across = direction.x * ns[0] + direction.y * ns[1];
          f(d, j) = ik * ((across + ct * ns[2] + eta) * direct + reflection * (across - ct * ns[2] + eta) * image);
        }
      }
    }
    for (std::size_t c = 0; c < out.size(); ++c) {
      const std::vector<Eigen::Index>& orbits = block_orbits[c];
      Eigen::MatrixXcd& pattern = patterns[c];
      pattern.resize(rows, static_cast<Eigen::Index>(orbits.size()));
      for (std::size_t b = 0; b < orbits.size(); ++b) {
        auto column = pattern.col(static_cast<Eigen::Index>(b));
        if (!basis) {
          column = f.col(orbits[b]).head(rows);
          continue;
        }
        const SymmetryBasis::Orbit& orbit = basis->orbits()[static_cast<std::size_t>(orbits[b])];
        column.setZero();
        for (const SymmetryBasis::Member& m : orbit.members)
          column += SymmetryBasis::character(static_cast<int>(c), m.element) * f.col(m.point).head(rows);
        column /= std::sqrt(static_cast<double>(orbit.members.size()));
      }
      if (pattern.cols() == 0) continue;
      cblas_zherk(CblasColMajor, CblasLower, CblasConjTrans, static_cast<int>(pattern.cols()), static_cast<int>(rows), 1.0,
                  pattern.data(), static_cast<int>(rows), 1.0, out[c].data(), static_cast<int>(out[c].rows()));
    }
  }
  // Monopoles: f was e + R_p·e′ for ik·a = 1; combined: ik·(a e + R_p a′ e′). Scale ωρk/16π²
  // and |G| for the fundamental domain; fill the upper triangle.
  const double scale = omega * medium_.density * k / (16.0 * pi * pi) * order;
  for (Eigen::MatrixXcd& block : out) {
    for (Eigen::Index j = 0; j < block.cols(); ++j)
      for (Eigen::Index i = j; i < block.rows(); ++i) {
        block(i, j) *= scale;
        if (i == j) block(i, j) = block(i, j).real();
        else block(j, i) = std::conj(block(i, j));
      }
  }
  return out;
}

Eigen::MatrixXcd pivoted_cholesky(const Eigen::MatrixXcd& s, double tolerance) {
  const Eigen::Index n = s.rows();
  if (s.cols() != n) throw std::invalid_argument("pivoted Cholesky: the matrix must be square");
  Eigen::VectorXd diagonal = s.diagonal().real();
  const double largest = n > 0 ? diagonal.maxCoeff() : 0.0;
  Eigen::MatrixXcd l = Eigen::MatrixXcd::Zero(n, n);
  std::vector<bool> taken(static_cast<std::size_t>(n), false);
  Eigen::Index rank = 0;
  while (rank < n) {
    Eigen::Index pivot = -1;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!taken[static_cast<std::size_t>(i)] && (pivot < 0 || diagonal(i) > diagonal(pivot))) pivot = i;
    // What is left is below the tolerance (or rounding made it negative): S is PSD, so the
    // remainder's largest entry is on its diagonal and bounds the rest.
    if (!(largest > 0.0) || !(diagonal(pivot) > tolerance * largest)) break;
    const double root = std::sqrt(diagonal(pivot));
    Eigen::VectorXcd column = s.col(pivot);
    // column −= L·conj(l_p) by the BLAS (zgemv, single-threaded): Eigen's product, compiled for
    // the baseline instruction set, was 7 % of a cold anchor on the split mesh.
    if (rank > 0) {
      use_single_threaded_blas();
      const Eigen::VectorXcd pivot_row = l.row(pivot).head(rank).adjoint();
      const Complex minus_one(-1.0, 0.0), one(1.0, 0.0);
      cblas_zgemv(CblasColMajor, CblasNoTrans, static_cast<int>(n), static_cast<int>(rank), &minus_one, l.data(),
                  static_cast<int>(n), pivot_row.data(), 1, &one, column.data(), 1);
    }
    column /= root;
    for (Eigen::Index i = 0; i < n; ++i)
      if (taken[static_cast<std::size_t>(i)]) column(i) = 0.0;  // exact zeros above the pivots
    column(pivot) = root;
    l.col(rank) = column;
    diagonal -= column.cwiseAbs2();
    taken[static_cast<std::size_t>(pivot)] = true;
    diagonal(pivot) = 0.0;
    ++rank;
  }
  return l.leftCols(rank);
}

Eigen::MatrixXcd EquivalentSources::power_factor(double omega, double tolerance) const {
  if (!source_basis_) return pivoted_cholesky(power_matrix(omega), tolerance).adjoint();
  const std::vector<Eigen::MatrixXcd> blocks = power_blocks(omega);
  const int characters = source_basis_->characters();
  std::vector<Eigen::MatrixXcd> factors;
  Eigen::Index rank = 0;
  for (const Eigen::MatrixXcd& s : blocks) {
    factors.push_back(pivoted_cholesky(s, tolerance));
    rank += factors.back().cols();
  }
  // Character c's rows L_cᴴ·W_cᵀ (W_c the orthonormal basis, real): their transposes are
  // W_c·conj(L_c), which expand() makes.
  Eigen::MatrixXcd out(rank, sources_.cols());
  Eigen::Index row = 0;
  for (int c = 0; c < characters; ++c) {
    const Eigen::MatrixXcd& l = factors[static_cast<std::size_t>(c)];
    if (l.cols() == 0) continue;
    std::vector<Eigen::MatrixXcd> parts;
    for (int d = 0; d < characters; ++d)
      parts.push_back(d == c ? Eigen::MatrixXcd(l.conjugate()) : Eigen::MatrixXcd::Zero(source_basis_->size(d), l.cols()));
    out.middleRows(row, l.cols()) = source_basis_->expand(parts).transpose();
    row += l.cols();
  }
  return out;
}

std::vector<std::vector<Eigen::Index>> EquivalentSources::leading_coordinates(Eigen::Index columns) const {
  const SymmetryBasis& basis = *point_basis_;
  std::vector<std::vector<Eigen::Index>> out(static_cast<std::size_t>(basis.characters()));
  for (int c = 0; c < basis.characters(); ++c) {
    const std::vector<Eigen::Index>& block = basis.block(c);
    for (std::size_t i = 0; i < block.size(); ++i) {
      const SymmetryBasis::Orbit& orbit = basis.orbits()[static_cast<std::size_t>(block[i])];
      std::size_t inside = 0;
      for (const SymmetryBasis::Member& m : orbit.members) inside += m.point < columns ? 1 : 0;
      if (inside != 0 && inside != orbit.members.size())
        throw std::invalid_argument("equivalent sources: the leading points are not a union of the symmetry's orbits");
      if (inside) out[static_cast<std::size_t>(c)].push_back(static_cast<Eigen::Index>(i));
    }
  }
  return out;
}

std::vector<Eigen::Index> EquivalentSources::point_coordinate_counts(Eigen::Index columns) const {
  if (columns < 0 || columns > surface_.cols()) throw std::invalid_argument("equivalent sources: columns out of range");
  if (!point_basis_) return {columns};
  std::vector<Eigen::Index> out;
  for (const auto& positions : leading_coordinates(columns)) out.push_back(static_cast<Eigen::Index>(positions.size()));
  return out;
}

std::vector<Eigen::MatrixXcd> EquivalentSources::point_coordinates(const Eigen::MatrixXcd& v) const {
  const Eigen::Index columns = v.rows();
  if (columns > surface_.cols()) throw std::invalid_argument("equivalent sources: more velocities than points");
  Eigen::MatrixXcd full = Eigen::MatrixXcd::Zero(surface_.cols(), v.cols());
  full.topRows(columns) = v;
  if (row_scale_.size()) full = row_scale_.asDiagonal() * full;
  if (!point_basis_) return {full.topRows(columns)};
  const std::vector<std::vector<Eigen::Index>> positions = leading_coordinates(columns);
  std::vector<Eigen::MatrixXcd> out;
  for (int c = 0; c < point_basis_->characters(); ++c) {
    const Eigen::MatrixXcd reduced = point_basis_->reduce(full, c);
    const std::vector<Eigen::Index>& keep = positions[static_cast<std::size_t>(c)];
    Eigen::MatrixXcd x(static_cast<Eigen::Index>(keep.size()), v.cols());
    for (std::size_t i = 0; i < keep.size(); ++i) x.row(static_cast<Eigen::Index>(i)) = reduced.row(keep[i]);
    out.push_back(std::move(x));
  }
  return out;
}

std::vector<Eigen::MatrixXcd> EquivalentSources::power_operator(const EquivalentSourceSolve& solve, double omega,
                                                                Eigen::Index columns, double tolerance) const {
  if (solve.source_count_ != sources_.cols() || solve.surface_points_ != surface_.cols() ||
      static_cast<int>(solve.factors_.size()) != symmetry_blocks())
    throw std::invalid_argument("equivalent sources: the solve is not this model's");
  if (columns < 0 || columns > surface_.cols()) throw std::invalid_argument("equivalent sources: columns out of range");
  // L_cᴴ·V_c⁺ from the block's own factor: V⁺ = Σ_c U_c V_c⁺ W_cᵀ and W_cᵀW_d = δ_cd, so
  // F·V⁺ = Σ_c L_cᴴ V_c⁺ U_cᵀ (the weights, when set, act on v in point_coordinates).
  // Only the kept coordinates' columns are formed (apply_pseudo_inverse_right with `keep`).
  const auto block_operator = [&](const std::optional<RegularisedLeastSquares>& factor, const Eigen::MatrixXcd& l,
                                  const std::vector<Eigen::Index>& keep) -> Eigen::MatrixXcd {
    if (!factor || l.cols() == 0) return Eigen::MatrixXcd::Zero(l.cols(), static_cast<Eigen::Index>(keep.size()));
    return factor->apply_pseudo_inverse_right(l.adjoint(), keep);
  };
  if (!point_basis_) {
    const Eigen::MatrixXcd l = pivoted_cholesky(power_matrix(omega), tolerance);
    std::vector<Eigen::Index> leading(static_cast<std::size_t>(columns));
    std::iota(leading.begin(), leading.end(), Eigen::Index{0});
    return {block_operator(solve.factors_[0], l, leading)};
  }
  const std::vector<Eigen::MatrixXcd> blocks = power_blocks(omega);
  const std::vector<std::vector<Eigen::Index>> positions = leading_coordinates(columns);
  std::vector<Eigen::MatrixXcd> out;
  for (int c = 0; c < point_basis_->characters(); ++c) {
    const auto k = static_cast<std::size_t>(c);
    out.push_back(block_operator(solve.factors_[k], pivoted_cholesky(blocks[k], tolerance), positions[k]));
  }
  return out;
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
