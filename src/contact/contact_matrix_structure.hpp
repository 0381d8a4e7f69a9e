#pragma once
// The structure of a rolling contact step's matrix G0 (issue 13: measured before choosing how to
// solve the step): how much of each point's compliance is its own, how fast the coupling decays
// along x and y, whether it depends on x_p − x_q only, and how far from symmetric it is.
#include <vector>

#include <Eigen/Core>

#include "contact/tyre_grid.hpp"

namespace rollnoise {

struct ContactMatrixStructure {
  // Over the points in contact (force > 0): G_ii / Σ_{j in contact, j ≠ i} |G_ij|, the smallest
  // and the median (> 1: diagonally dominant on the contact).
  double diagonal_dominance_min = 0.0;
  double diagonal_dominance_median = 0.0;
  // G(c, c + d)/G(c, c) at the contact's centre c, for the offsets below (cells), along x
  // (ahead, +x) and across (y).
  std::vector<int> offsets;
  std::vector<double> decay_x;
  std::vector<double> decay_y;
  // max |G(a + 1, b + 1) − G(a, b)| along x over max |G|: 0 for a translation-invariant tyre.
  double translation_variance = 0.0;
  // max |G − Gᵀ|/2 over max |G|.
  double skewness = 0.0;
};

ContactMatrixStructure measure_contact_matrix(const Eigen::MatrixXd& g0, const TyreGrid& grid,
                                              const Eigen::VectorXd& force);

}  // namespace rollnoise
