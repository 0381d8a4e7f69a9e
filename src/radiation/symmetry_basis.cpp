#include "radiation/symmetry_basis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace rollnoise {

namespace {
constexpr double kNormalTolerance = 1e-9;
}  // namespace

SymmetryBasis::SymmetryBasis(std::vector<std::vector<Eigen::Index>> generators)
    : generators_(static_cast<int>(generators.size())) {
  if (generators_ < 1 || generators_ > 2) throw std::invalid_argument("symmetry basis: one or two reflections");
  points_ = static_cast<Eigen::Index>(generators.front().size());
  for (const auto& g : generators) {
    if (static_cast<Eigen::Index>(g.size()) != points_) throw std::invalid_argument("symmetry basis: one image per point");
    for (Eigen::Index i = 0; i < points_; ++i) {
      const Eigen::Index j = g[static_cast<std::size_t>(i)];
      if (j < 0 || j >= points_ || g[static_cast<std::size_t>(j)] != i)
        throw std::invalid_argument("symmetry basis: a reflection must be an involution of the points");
    }
  }
  const int elements = 1 << generators_;
  const auto image = [&](Eigen::Index i, int element) {
    for (int j = 0; j < generators_; ++j)
      if (element & (1 << j)) i = generators[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
    return i;
  };
  if (generators_ == 2)
    for (Eigen::Index i = 0; i < points_; ++i)
      if (image(image(i, 1), 2) != image(image(i, 2), 1)) throw std::invalid_argument("symmetry basis: the reflections must commute");
  std::vector<bool> seen(static_cast<std::size_t>(points_), false);
  blocks_.assign(static_cast<std::size_t>(elements), {});
  for (Eigen::Index r = 0; r < points_; ++r) {
    if (seen[static_cast<std::size_t>(r)]) continue;
    Orbit orbit;
    unsigned stabiliser = 0;  // bit g set: g fixes r
    for (int g = 0; g < elements; ++g) {
      const Eigen::Index x = image(r, g);
      if (x == r) stabiliser |= 1u << g;
      const bool known = std::any_of(orbit.members.begin(), orbit.members.end(), [&](const Member& m) { return m.point == x; });
      if (!known) {
        orbit.members.push_back({x, g});
        seen[static_cast<std::size_t>(x)] = true;
      }
    }
    for (int c = 0; c < elements; ++c) {
      bool trivial = true;
      for (int h = 0; h < elements; ++h)
        if ((stabiliser & (1u << h)) && character(c, h) < 0.0) trivial = false;
      if (trivial) {
        orbit.characters |= 1u << c;
        blocks_[static_cast<std::size_t>(c)].push_back(static_cast<Eigen::Index>(orbits_.size()));
      }
    }
    orbits_.push_back(std::move(orbit));
  }
}

Eigen::MatrixXcd SymmetryBasis::reduce(const Eigen::MatrixXcd& x, int c) const {
  if (x.rows() != points_) throw std::invalid_argument("symmetry basis: one row per point");
  const std::vector<Eigen::Index>& block = blocks_.at(static_cast<std::size_t>(c));
  Eigen::MatrixXcd out(static_cast<Eigen::Index>(block.size()), x.cols());
  for (std::size_t j = 0; j < block.size(); ++j) {
    const Orbit& orbit = orbits_[static_cast<std::size_t>(block[j])];
    const double scale = 1.0 / std::sqrt(static_cast<double>(orbit.members.size()));
    auto row = out.row(static_cast<Eigen::Index>(j));
    row.setZero();
    for (const Member& m : orbit.members) row += (character(c, m.element) * scale) * x.row(m.point);
  }
  return out;
}

Eigen::MatrixXcd SymmetryBasis::expand(const std::vector<Eigen::MatrixXcd>& parts) const {
  if (static_cast<int>(parts.size()) != characters()) throw std::invalid_argument("symmetry basis: one part per character");
  const Eigen::Index columns = parts.front().cols();
  for (int c = 0; c < characters(); ++c)
    if (parts[static_cast<std::size_t>(c)].rows() != size(c) || parts[static_cast<std::size_t>(c)].cols() != columns)
      throw std::invalid_argument("symmetry basis: the parts do not match the basis");
  Eigen::MatrixXcd out = Eigen::MatrixXcd::Zero(points_, columns);
  for (int c = 0; c < characters(); ++c) {
    const std::vector<Eigen::Index>& block = blocks_[static_cast<std::size_t>(c)];
    for (std::size_t j = 0; j < block.size(); ++j) {
      const Orbit& orbit = orbits_[static_cast<std::size_t>(block[j])];
      const double scale = 1.0 / std::sqrt(static_cast<double>(orbit.members.size()));
      for (const Member& m : orbit.members)
        out.row(m.point) += (character(c, m.element) * scale) * parts[static_cast<std::size_t>(c)].row(static_cast<Eigen::Index>(j));
    }
  }
  return out;
}

// Partners share the reflection's other coordinates, z among them: the candidates of each point
// are found by binary search in the points sorted by z, O(N log N) but for runs of equal z (the
// flat patch's cells).
std::optional<std::vector<Eigen::Index>> reflection_partners(const Eigen::Matrix3Xd& points,
                                                             const Eigen::Matrix3Xd& normals, int axis,
                                                             double tolerance) {
  if (axis < 0 || axis > 1) throw std::invalid_argument("reflection partners: axis 0 (x) or 1 (y)");
  const Eigen::Index n = points.cols();
  const bool with_normals = normals.cols() > 0;
  if (with_normals && normals.cols() != n) throw std::invalid_argument("reflection partners: one normal per point");
  const auto reflect = [axis](Eigen::Vector3d v) {
    v(axis) = -v(axis);
    return v;
  };
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return points(2, a) < points(2, b); });
  std::vector<double> zs;
  zs.reserve(order.size());
  for (Eigen::Index i : order) zs.push_back(points(2, i));
  std::vector<Eigen::Index> partner(static_cast<std::size_t>(n), -1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d image = reflect(points.col(i));
    const auto lo = std::lower_bound(zs.begin(), zs.end(), image.z() - tolerance) - zs.begin();
    const auto hi = std::upper_bound(zs.begin(), zs.end(), image.z() + tolerance) - zs.begin();
    double best = std::numeric_limits<double>::infinity();
    for (auto c = lo; c < hi; ++c) {
      const Eigen::Index j = order[static_cast<std::size_t>(c)];
      const double d = (points.col(j) - image).norm();
      if (d > tolerance || d >= best) continue;
      if (with_normals && (normals.col(j) - reflect(normals.col(i))).norm() > kNormalTolerance) continue;
      best = d;
      partner[static_cast<std::size_t>(i)] = j;
    }
    if (partner[static_cast<std::size_t>(i)] < 0) return std::nullopt;
  }
  for (Eigen::Index i = 0; i < n; ++i)
    if (partner[static_cast<std::size_t>(partner[static_cast<std::size_t>(i)])] != i) return std::nullopt;  // not one-to-one
  return partner;
}

}  // namespace rollnoise
