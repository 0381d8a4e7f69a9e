// The contact-matrix measurements of the summary (contact_matrix_structure.hpp) on matrices whose
// structure is known by construction.
#include <cmath>

#include <gtest/gtest.h>

#include "contact/contact_matrix_structure.hpp"

namespace rollnoise {
namespace {

TyreGrid small_grid() {
  TyreGrid g;
  g.radius = 0.3;
  g.width = 0.2;
  g.circumferential = 64;
  g.lateral = 3;
  g.window = 20;
  return g;
}

// G(p, q) = a^{|Δi|}·b^{|Δj|} (+ a lag c·sign(Δi) when skewed): translation invariant, with a
// known decay and diagonal dominance.
Eigen::MatrixXd geometric(const TyreGrid& g, double a, double b, double c) {
  const Eigen::Index n = g.points();
  Eigen::MatrixXd m(n, n);
  for (Eigen::Index p = 0; p < n; ++p)
    for (Eigen::Index q = 0; q < n; ++q) {
      const long di = p % g.window - q % g.window, dj = p / g.window - q / g.window;
      m(p, q) = std::pow(a, std::abs(di)) * std::pow(b, std::abs(dj)) * (1.0 + c * (di > 0) - c * (di < 0));
    }
  return m;
}

TEST(ContactMatrixStructure, MeasuresDecayDominanceInvarianceAndSkewOfKnownMatrices) {
  const TyreGrid g = small_grid();
  Eigen::VectorXd force = Eigen::VectorXd::Zero(g.points());
  for (int j = 0; j < g.lateral; ++j)
    for (int i = 8; i <= 12; ++i) force(i + g.window * j) = 1.0;  // a 5 × 3 patch centred at i = 10
  const ContactMatrixStructure s = measure_contact_matrix(geometric(g, 0.1, 0.01, 0.0), g, force);
  EXPECT_NEAR(s.decay_x[0], 0.1, 1e-15);
  EXPECT_NEAR(s.decay_x[1], 0.01, 1e-15);
  EXPECT_NEAR(s.decay_y[0], 0.01, 1e-15);
  EXPECT_TRUE(std::isnan(s.decay_y[2]));  // beyond the 3 lateral rows
  EXPECT_EQ(s.translation_variance, 0.0);
  EXPECT_EQ(s.skewness, 0.0);
  // The patch's corner sees the least coupling, its centre the most.
  const double row_centre = 2 * (0.1 + 0.01) * (1 + 2 * 0.01) + 2 * 0.01;
  EXPECT_NEAR(s.diagonal_dominance_min, 1.0 / row_centre, 1e-12);
  EXPECT_GT(s.diagonal_dominance_median, s.diagonal_dominance_min);

  const ContactMatrixStructure skewed = measure_contact_matrix(geometric(g, 0.1, 0.01, 0.2), g, force);
  EXPECT_NEAR(skewed.skewness, 0.2 * 0.1, 1e-15);
  Eigen::MatrixXd varying = geometric(g, 0.1, 0.01, 0.0);
  varying(5, 5) += 0.5;
  EXPECT_NEAR(measure_contact_matrix(varying, g, force).translation_variance, 0.5 / 1.5, 1e-15);
}

}  // namespace
}  // namespace rollnoise
