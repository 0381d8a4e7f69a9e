#include "contact/halfspace_load_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "greens/tread_compliance.hpp"

namespace rollnoise {

double approach_at_force(const std::vector<LoadPathPoint>& path, double force) {
  for (std::size_t e = 1; e < path.size(); ++e)
    if (force <= path[e].force) {
      const LoadPathPoint& a = path[e - 1];
      const LoadPathPoint& b = path[e];
      return b.force > a.force ? a.approach + (b.approach - a.approach) * (force - a.force) / (b.force - a.force)
                               : b.approach;
    }
  const LoadPathPoint& a = path[path.size() - 2];
  const LoadPathPoint& b = path.back();
  return b.approach + (b.approach - a.approach) * (force - b.force) / (b.force - a.force);
}

PathState state_at_approach(const std::vector<LoadPathPoint>& path, double approach) {
  for (std::size_t e = 1; e < path.size(); ++e)
    if (approach <= path[e].approach) {
      const LoadPathPoint& a = path[e - 1];
      const LoadPathPoint& b = path[e];
      const double f = b.approach > a.approach
                           ? a.force + (b.force - a.force) * (approach - a.approach) / (b.approach - a.approach)
                           : b.force;
      return {f, a.contacts};
    }
  const LoadPathPoint& a = path[path.size() - 2];
  const LoadPathPoint& b = path.back();
  return {b.force + (b.force - a.force) * (approach - b.approach) / (b.approach - a.approach), b.contacts};
}

HalfspaceLoadPath::HalfspaceLoadPath(std::size_t nx, std::size_t ny, double px, double py, double youngs_modulus,
                                     double poisson_ratio) {
  if (nx < 1 || ny < 1 || !(px > 0.0) || !(py > 0.0))
    throw std::invalid_argument("HalfspaceLoadPath: a grid of at least one pixel of positive size");
  const auto n = static_cast<Eigen::Index>(nx * ny);
  k_.resize(n, n);
  const double area = px * py;
  for (Eigen::Index p = 0; p < n; ++p)
    for (Eigen::Index q = 0; q < n; ++q) {
      const auto ip = static_cast<double>(static_cast<std::size_t>(p) / ny), jp = static_cast<double>(static_cast<std::size_t>(p) % ny);
      const auto iq = static_cast<double>(static_cast<std::size_t>(q) / ny), jq = static_cast<double>(static_cast<std::size_t>(q) % ny);
      k_(p, q) = love_rectangle_displacement((ip - iq) * px, (jp - jq) * py, 0.5 * px, 0.5 * py, youngs_modulus,
                                             poisson_ratio) / area;
    }
  const Eigen::LLT<Eigen::MatrixXd> full(k_);
  if (full.info() != Eigen::Success) throw std::runtime_error("HalfspaceLoadPath: the influence matrix is not positive definite");
  punch_compliance_ = 1.0 / full.solve(Eigen::VectorXd::Ones(n)).sum();
  l_.resize(n, n);
  a_.resize(n);
  b_.resize(n);
  ka_.resize(n);
  kb_.resize(n);
  column_.resize(n);
  forces_.resize(n);
  set_.reserve(static_cast<std::size_t>(n));
  in_set_.assign(static_cast<std::size_t>(n), 0);
}

void HalfspaceLoadPath::refactor() {
  const auto s = static_cast<Eigen::Index>(set_.size());
  for (Eigen::Index r = 0; r < s; ++r)
    for (Eigen::Index c = 0; c <= r; ++c) l_(r, c) = k_(set_[static_cast<std::size_t>(r)], set_[static_cast<std::size_t>(c)]);
  Eigen::Ref<Eigen::MatrixXd> block = l_.topLeftCorner(s, s);
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> factor(block);  // in place, lower
  if (factor.info() != Eigen::Success) throw std::runtime_error("HalfspaceLoadPath: K_SS is not positive definite");
}

void HalfspaceLoadPath::solve_on_set(std::span<const double> heights, double top) {
  const auto s = static_cast<Eigen::Index>(set_.size());
  const auto lower = l_.topLeftCorner(s, s).triangularView<Eigen::Lower>();
  auto a = a_.head(s);
  auto b = b_.head(s);
  a.setOnes();
  for (Eigen::Index t = 0; t < s; ++t) b(t) = heights[static_cast<std::size_t>(set_[static_cast<std::size_t>(t)])] - top;
  lower.solveInPlace(a);
  lower.transpose().solveInPlace(a);
  lower.solveInPlace(b);
  lower.transpose().solveInPlace(b);
  ka_.setZero();
  kb_.setZero();
  for (Eigen::Index t = 0; t < s; ++t) {
    const auto column = k_.col(set_[static_cast<std::size_t>(t)]);  // K is symmetric: K_{:,S}
    ka_.noalias() += a(t) * column;
    kb_.noalias() += b(t) * column;
  }
}

const std::vector<LoadPathPoint>& HalfspaceLoadPath::trace(std::span<const double> heights, double force_cap) {
  const Eigen::Index n = k_.rows();
  if (static_cast<Eigen::Index>(heights.size()) != n)
    throw std::invalid_argument("HalfspaceLoadPath::trace: " + std::to_string(n) + " heights expected, got " +
                                std::to_string(heights.size()));
  if (!(force_cap > 0.0) || !std::isfinite(force_cap))
    throw std::invalid_argument("HalfspaceLoadPath::trace: the force cap must be finite and > 0");
  double top = -std::numeric_limits<double>::infinity(), bottom = std::numeric_limits<double>::infinity();
  for (const double h : heights) {
    if (!std::isfinite(h)) throw std::invalid_argument("HalfspaceLoadPath::trace: a height is not finite");
    top = std::max(top, h);
    bottom = std::min(bottom, h);
  }
  // Lengths below this are round-off of the heights' scale (events at one δ, ties).
  const double noise = 64.0 * std::numeric_limits<double>::epsilon() * std::max({std::abs(top), std::abs(bottom), top - bottom});
  set_.clear();
  std::fill(in_set_.begin(), in_set_.end(), 0);
  for (Eigen::Index p = 0; p < n; ++p)
    if (heights[static_cast<std::size_t>(p)] >= top) {  // the highest pixels (ties: all of them) touch first
      set_.push_back(p);
      in_set_[static_cast<std::size_t>(p)] = 1;
    }
  refactor();
  solve_on_set(heights, top);
  path_.assign(1, LoadPathPoint{0.0, 0.0, static_cast<int>(set_.size())});
  double delta = 0.0;
  Eigen::Index last_changed = -1;
  const Eigen::Index max_events = 4 * n + 16;
  for (Eigen::Index event = 0;; ++event) {
    if (event > max_events) throw std::runtime_error("HalfspaceLoadPath: the contact set did not settle");
    const auto s = static_cast<Eigen::Index>(set_.size());
    const double sum_a = a_.head(s).sum(), sum_b = b_.head(s).sum();
    // The next event: a pixel off S whose gap closes, (kb − (h − top)) + δ·(ka − 1) = 0 with
    // ka < 1, or one on S whose force b + δ·a reaches 0 with a < 0. The pixel that just changed
    // state cannot change back at the same δ (a tie, not an event).
    double next = std::numeric_limits<double>::infinity();
    Eigen::Index which = -1, position = -1;
    for (Eigen::Index p = 0; p < n; ++p) {
      if (in_set_[static_cast<std::size_t>(p)]) continue;
      const double closing = 1.0 - ka_(p);
      if (!(closing > 0.0)) continue;
      const double at = (kb_(p) - (heights[static_cast<std::size_t>(p)] - top)) / closing;
      if (p == last_changed && at <= delta + noise) continue;
      if (at < next) {
        next = at;
        which = p;
        position = -1;
      }
    }
    for (Eigen::Index t = 0; t < s; ++t) {
      if (!(a_(t) < 0.0)) continue;
      const double at = -b_(t) / a_(t);
      if (set_[static_cast<std::size_t>(t)] == last_changed && at <= delta + noise) continue;
      if (at < next) {
        next = at;
        which = set_[static_cast<std::size_t>(t)];
        position = t;
      }
    }
    next = std::max(next, delta);
    const double force_next = sum_b + next * sum_a;
    if (which < 0 || force_next >= force_cap) {
      // The cap is reached on this set (or every pixel touches and the law is linear on).
      const double at = (force_cap - sum_b) / sum_a;
      path_.push_back(LoadPathPoint{at, force_cap, static_cast<int>(s)});
      forces_.setZero();
      for (Eigen::Index t = 0; t < s; ++t) forces_(set_[static_cast<std::size_t>(t)]) = b_(t) + at * a_(t);
      return path_;
    }
    delta = next;
    last_changed = which;
    if (position < 0) {
      // Joins: K_SS's factor grows by a row, l = L⁻¹·K_{S,i}, d = √(K_ii − l·l).
      for (Eigen::Index t = 0; t < s; ++t) column_(t) = k_(set_[static_cast<std::size_t>(t)], which);
      auto l = column_.head(s);
      l_.topLeftCorner(s, s).triangularView<Eigen::Lower>().solveInPlace(l);
      const double pivot = k_(which, which) - l.squaredNorm();
      set_.push_back(which);
      in_set_[static_cast<std::size_t>(which)] = 1;
      if (pivot > 1e-10 * k_(which, which)) {
        l_.row(s).head(s) = l.transpose();
        l_(s, s) = std::sqrt(pivot);
      } else {
        refactor();
      }
    } else {
      set_.erase(set_.begin() + position);
      in_set_[static_cast<std::size_t>(which)] = 0;
      refactor();
    }
    solve_on_set(heights, top);
    path_.push_back(LoadPathPoint{delta, force_next, static_cast<int>(set_.size())});
  }
}

}  // namespace rollnoise
