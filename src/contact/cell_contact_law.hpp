#pragma once
// Per-cell contact laws (Andersson & Kropp, JSV 318 (2008) 296-312): for each cell of the contact
// grid over the road, the approach that the road's fine texture inside the cell adds, in series
// with the tyre, as a function of the cell's force.
//
// What is in series with what. The tyre's own contact compliance at the cell scale is in its
// Green's functions: the Winkler tread of the plate, or the two-layer tyre's rubber layer under
// a uniform pressure on the cell. Pressed onto a rough cell, the rubber (a half-space at these
// scales) moves by δ_hs(F) from the first touch of the cell's highest point
// (halfspace_load_path.hpp); pressed onto the same cell made flat, by c_punch·F, the rigid flat
// punch of the cell's size. Only the difference is below the cell:
//     δ_sub(F) = δ_hs(F) − c_punch·F   (≥ 0, increasing: halfspace_load_path.hpp),
// so the road height a cell meets is its highest point and the law adds δ_sub. A flat cell adds
// nothing (the rigid cells of before, with their first-touch heights), and the cell-scale
// deformation is not counted twice. Left out: the difference between the flat punch's pressure
// and the uniform pressure of the tyre's cell (a few per cent of the cell's compliance), and the
// coupling of neighbouring cells' roughness through the rubber (each cell's law is its own).
//
// Storage. δ_sub at `levels` forces F_k = cap·10^{(k − levels + 1)/4}, the same for every cell
// (cap: the force at which the law ends, extrapolated linearly beyond), as floats, with the
// cubic's slope at each node (float) and the energy ∫F dδ up to each node (double, so that the
// Newton step's energy has no jumps at the nodes), all fixed when the cell is set: a contact
// step evaluates each law several times per point and iteration. δ_sub is held
// at least `minimum_compliance` per newton steeper than flat (a cell fully in contact would
// otherwise be rigid at once; 1e-3 of the punch's compliance, a negligible softening), so F(δ)
// is a strictly increasing function. F(δ) between the nodes (0, 0), (δ_0, F_0), … is the monotone
// cubic of Fritsch & Carlson (SIAM J. Numer. Anal. 17 (1980) 238-246), continuous in slope, with
// the secant beyond the last node.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "contact/point_springs.hpp"

namespace rollnoise {

class CellContactLaws {
 public:
  static constexpr int levels = 21;  // five decades of force, four levels a decade

  CellContactLaws(std::size_t cells, double force_cap, double minimum_compliance);

  std::size_t cells() const noexcept { return top_.size(); }
  double force_cap() const noexcept { return cap_; }
  double minimum_compliance() const noexcept { return minimum_compliance_; }
  double force_level(int k) const noexcept { return forces_[static_cast<std::size_t>(k)]; }

  // Cell c: its first-touch height (m) and δ_sub at each force level (m, non-decreasing; made
  // strictly increasing by the minimum compliance).
  void set(std::size_t cell, double top, std::span<const double> approaches);
  double top(std::size_t cell) const noexcept { return top_[cell]; }
  std::span<const float> approaches(std::size_t cell) const noexcept {
    return {approach_.data() + cell * levels, static_cast<std::size_t>(levels)};
  }
  // Every cell's first-touch height, and δ_sub as cells × levels: what a file of the laws holds.
  Eigen::VectorXd tops() const;
  Eigen::MatrixXd approach_table() const;

  // F(δ) and dF/dδ of cell c for δ ≥ 0. `hint` (optional): the segment found last for this
  // cell, tried first and updated (a contact step evaluates each point's law many times with
  // nearby δ).
  void force(std::size_t cell, double delta, double& force, double& slope, int* hint = nullptr) const;
  // δ ≥ 0 with F(δ) = force ≥ 0.
  double approach_at(std::size_t cell, double force) const;
  // ∫₀^δ F, δ ≥ 0.
  double stored_energy(std::size_t cell, double delta, int* hint = nullptr) const;
  // δ ≥ 0 with δ + c·F(δ) = y ≥ 0; `guess` (optional, ≥ 0): a δ near the root, where the root
  // search starts if it lies on the root's segment.
  double compression_of(std::size_t cell, double y, double c, int* hint = nullptr, double guess = -1.0) const;
  // The same, and F(δ) and dF/dδ there (as force()) from the segment the search ended on.
  double compression_of(std::size_t cell, double y, double c, int* hint, double guess, double& force,
                        double& slope) const;

 private:
  // The node i of cell c (0: the origin), its slope, and the segment of δ.
  double node_delta(std::size_t cell, int i) const noexcept {
    return i == 0 ? 0.0 : static_cast<double>(approach_[cell * levels + static_cast<std::size_t>(i - 1)]);
  }
  double node_force(int i) const noexcept { return i == 0 ? 0.0 : forces_[static_cast<std::size_t>(i - 1)]; }
  double node_slope(std::size_t cell, int i) const noexcept {
    return static_cast<double>(slope_[cell * (levels + 1) + static_cast<std::size_t>(i)]);
  }
  double node_energy(std::size_t cell, int i) const noexcept {
    return i == 0 ? 0.0 : energy_[cell * levels + static_cast<std::size_t>(i - 1)];
  }
  // The Fritsch–Carlson slope at node i from the nodes (at set()).
  double monotone_slope(std::size_t cell, int i) const noexcept;
  int segment_of(std::size_t cell, double delta, int* hint = nullptr) const noexcept;
  // F(δ) and dF/dδ on segment i (levels: the line beyond the last node).
  void force_on_segment(std::size_t cell, int i, double delta, double& force, double& slope) const noexcept;
  // The segment i with node δ_i + c·F_i ≤ y < the next one's.
  int compression_segment(std::size_t cell, double y, double c, int* hint) const noexcept;
  // δ on segment i (nodes i, i + 1) with w·δ + c·F(δ) = target (w, c ≥ 0, not both 0), the
  // search started at `guess` if it lies inside the segment.
  double solve_on_segment(std::size_t cell, int i, double w, double c, double target, double guess = -1.0) const;

  double cap_, minimum_compliance_;
  std::vector<double> forces_;
  std::vector<double> top_;
  std::vector<float> approach_;  // levels a cell
  std::vector<float> slope_;     // levels + 1 a cell
  std::vector<double> energy_;   // levels a cell
};

// The laws as the springs of a contact step: point p follows the law of the cell that assign()
// put under it (the road moves under the points every step).
class CellLawSprings final : public PointSprings {
 public:
  CellLawSprings(std::shared_ptr<const CellContactLaws> laws, Eigen::Index points);
  void assign(Eigen::Index point, std::size_t cell) {
    if (cell_[static_cast<std::size_t>(point)] != cell) hint_[static_cast<std::size_t>(point)] = 0;
    cell_[static_cast<std::size_t>(point)] = cell;
  }

  Eigen::Index size() const override { return static_cast<Eigen::Index>(cell_.size()); }
  void evaluate(Eigen::Index p, double delta, double& force, double& slope) const override;
  double compression_of(Eigen::Index p, double y, double c, double guess) const override;
  void compress(Eigen::Index p, double y, double c, double guess, double& delta, double& force,
                double& slope) const override;
  double compression_at(Eigen::Index p, double force) const override;
  double stored_energy(Eigen::Index p, double delta) const override;

 private:
  std::shared_ptr<const CellContactLaws> laws_;
  std::vector<std::size_t> cell_;
  // Each point's last segment (CellContactLaws::force's hint): a cache of the lookups, not state
  // that changes a result.
  mutable std::vector<int> hint_;
};

}  // namespace rollnoise
