#pragma once
// The whole force–approach law of one contact cell, exactly: an elastic half-space (the tread
// rubber) pressed onto the rigid fine texture inside the cell, followed as the approach grows.
//
// The cell is an nx × ny grid of pixels px × py, force uniform over each pixel; K (n × n) holds
// the surface displacement at each pixel's centre per newton on another (Love's rectangle,
// greens/tread_compliance.hpp; E* = E/(1 − ν²) for a rigid road). With the rubber's face at
// z = max h − δ (δ: the approach from the first touch of the highest pixel) the pixels in contact
// S carry forces p_S with K_SS·p_S = h_S − max h + δ, the others none and a gap ≥ 0. On a fixed
// S the forces are linear in δ,
//     p_S(δ) = b + δ·a,   a = K_SS⁻¹·1,   b = K_SS⁻¹·(h_S − max h),
// and so is every other pixel's gap: the law F(δ) = Σp is piecewise linear, its slope 1ᵀK_SS⁻¹1
// (> 0: it never falls) changing only where a pixel's gap closes (it joins S) or its force
// reaches zero (it leaves). The path follows those events one by one from δ = 0 (a parametric
// complementarity problem, solved exactly rather than at sampled approaches), with K_SS's
// Cholesky factor grown by a row as a pixel joins and refactored when one leaves. Cost per
// event O(n·|S|): a cell of 4 × 15 pixels takes about 60 events to full contact.
//
// Used for the per-cell contact laws (texture_contact_laws.hpp); checked against the iterative
// boundary-element contact (halfspace_texture_contact.hpp) and against Hertz.
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

struct LoadPathPoint {
  double approach = 0.0;  // δ, m
  double force = 0.0;     // F, N
  int contacts = 0;       // pixels in contact beyond this point (until the next)
};

// On a path: δ at force F, and F and the pixels in contact at approach δ (linear between the
// events; beyond the last point, on along the last segment).
double approach_at_force(const std::vector<LoadPathPoint>& path, double force);
struct PathState {
  double force = 0.0;
  int contacts = 0;
};
PathState state_at_approach(const std::vector<LoadPathPoint>& path, double approach);

class HalfspaceLoadPath {
 public:
  // An nx × ny grid of pixels px × py (m); the rubber's E (Pa) and ν.
  HalfspaceLoadPath(std::size_t nx, std::size_t ny, double px, double py, double youngs_modulus, double poisson_ratio);

  // The path for `heights` (m, upward, nx·ny row-major: i along x, j across, i·ny + j), from
  // δ = 0 until the force reaches `force_cap` (its last point has F = force_cap exactly) or every
  // pixel touches (then the law goes on linearly with the flat punch's stiffness). The points
  // are the events; F is linear in δ between them. Not thread-safe (it keeps its work arrays).
  const std::vector<LoadPathPoint>& trace(std::span<const double> heights, double force_cap);

  // The compliance δ/F of the whole cell pressed flat (every pixel in contact: a rigid flat
  // punch of the cell's size), 1/(1ᵀK⁻¹1), m/N. Any texture's law has δ ≥ this·F.
  double punch_compliance() const noexcept { return punch_compliance_; }
  std::size_t pixels() const noexcept { return static_cast<std::size_t>(k_.rows()); }
  // The force on each pixel at the path's end (N).
  const Eigen::VectorXd& last_forces() const noexcept { return forces_; }

 private:
  // a = K_SS⁻¹·1 and b = K_SS⁻¹·(h_S − max h) from the factor; ka, kb = K_{:,S}·(a, b).
  void solve_on_set(std::span<const double> heights, double top);
  void refactor();

  Eigen::MatrixXd k_;
  double punch_compliance_ = 0.0;
  // The set S (pixel indices in the order the factor holds them) and K_SS = L·Lᵀ in the leading
  // |S| × |S| block of l_.
  std::vector<Eigen::Index> set_;
  std::vector<char> in_set_;
  Eigen::MatrixXd l_;
  Eigen::VectorXd a_, b_, ka_, kb_, column_, forces_;
  std::vector<LoadPathPoint> path_;
};

}  // namespace rollnoise
