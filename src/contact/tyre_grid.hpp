#pragma once
// The tyre surface grid and the fixed contact window (MODEL.md §4). The belt is a grid of
// Nθ points around (spacing dx = 2πR/Nθ) by Ny points across the tread, which is centred on the
// belt: cell centres y_j = (b − b_t)/2 + (j + ½)·b_t/Ny for a tread width b_t ≤ b.
// Rolling advances the tyre one cell per step, Δt = dx/v. The contact window is Nw fixed
// positions x_i = (i − Nw/2)·dx around the bottom (x along the direction of travel, 0 under
// the axle), by all Ny lateral points. Contact point p = i + Nw·j.
#include <Eigen/Core>

namespace rollnoise {

struct TyreGrid {
  double radius = 0.0;            // R, m
  double width = 0.0;             // b, m (the belt: the plate's width)
  double tread_width = 0.0;       // b_t, m; 0 = the whole belt width
  int circumferential = 512;      // Nθ
  int lateral = 16;               // Ny
  int window = 48;                // Nw
  double crown_radius = 0.0;      // m; 0 = flat across the width

  double circumference() const;
  double dx() const;                      // 2πR/Nθ
  double dy() const;                      // b_t/Ny
  double contact_width() const;           // b_t
  Eigen::Index points() const { return static_cast<Eigen::Index>(window) * lateral; }
  double x(int i) const;                  // fixed position of window column i
  double y(int j) const;                  // lateral position of row j, in [0, b]
  int grid_index(int i) const;            // material grid index under window column i at step 0
  Eigen::MatrixX2d positions() const;     // (x, y) of every contact point
  // Undeformed height of each contact point above the lowest point of the tyre (m):
  // R − √(R² − x²) around, plus (y − b/2)²/(2·crown_radius) across.
  Eigen::VectorXd undeformed_gap() const;
  // Throws std::invalid_argument if the sizes are not usable.
  void validate() const;
};

// The points in contact (force > 0) of a window field, and their extent: columns i_min..i_max
// along x, rows j_min..j_max across (all −1 without contact).
struct ContactExtent {
  int points = 0;
  int i_min = -1, i_max = -1, j_min = -1, j_max = -1;
  double length(const TyreGrid& grid) const { return points ? (i_max - i_min + 1) * grid.dx() : 0.0; }
  double width(const TyreGrid& grid) const { return points ? (j_max - j_min + 1) * grid.dy() : 0.0; }
};
ContactExtent contact_extent(const TyreGrid& grid, const Eigen::Ref<const Eigen::VectorXd>& force);

}  // namespace rollnoise
