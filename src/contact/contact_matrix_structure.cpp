#include "contact/contact_matrix_structure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rollnoise {

ContactMatrixStructure measure_contact_matrix(const Eigen::MatrixXd& g0, const TyreGrid& grid,
                                              const Eigen::VectorXd& force) {
  const Eigen::Index points = grid.points();
  if (g0.rows() != points || g0.cols() != points || force.size() != points)
    throw std::invalid_argument("contact matrix structure: one row, column and force per point");
  ContactMatrixStructure s;
  const auto index = [&grid](int i, int j) { return i + static_cast<Eigen::Index>(grid.window) * j; };
  std::vector<Eigen::Index> contact;
  for (Eigen::Index p = 0; p < points; ++p)
    if (force(p) > 0.0) contact.push_back(p);
  std::vector<double> dominance;
  for (const Eigen::Index a : contact) {
    double off = 0.0;
    for (const Eigen::Index b : contact)
      if (b != a) off += std::abs(g0(a, b));
    dominance.push_back(off > 0.0 ? g0(a, a) / off : INFINITY);
  }
  if (!dominance.empty()) {
    std::sort(dominance.begin(), dominance.end());
    s.diagonal_dominance_min = dominance.front();
    s.diagonal_dominance_median = dominance[dominance.size() / 2];
  }
  // The centre: the force-weighted mean cell of the contact.
  double fx = 0.0, fy = 0.0, total = 0.0;
  for (const Eigen::Index p : contact) {
    fx += force(p) * static_cast<double>(p % grid.window);
    fy += force(p) * static_cast<double>(p / grid.window);
    total += force(p);
  }
  const int ci = total > 0.0 ? static_cast<int>(std::lround(fx / total)) : grid.window / 2;
  const int cj = total > 0.0 ? static_cast<int>(std::lround(fy / total)) : grid.lateral / 2;
  const double own = g0(index(ci, cj), index(ci, cj));
  for (const int d : {1, 2, 4, 8, 16}) {
    s.offsets.push_back(d);
    s.decay_x.push_back(ci + d < grid.window ? g0(index(ci + d, cj), index(ci, cj)) / own : NAN);
    s.decay_y.push_back(cj + d < grid.lateral ? g0(index(ci, cj + d), index(ci, cj)) / own : NAN);
  }
  const double largest = g0.cwiseAbs().maxCoeff();
  double variance = 0.0;
  for (int jb = 0; jb < grid.lateral; ++jb)
    for (int ib = 0; ib + 1 < grid.window; ++ib)
      for (int ja = 0; ja < grid.lateral; ++ja)
        for (int ia = 0; ia + 1 < grid.window; ++ia)
          variance = std::max(variance, std::abs(g0(index(ia + 1, ja), index(ib + 1, jb)) - g0(index(ia, ja), index(ib, jb))));
  s.translation_variance = variance / largest;
  s.skewness = 0.5 * (g0 - g0.transpose()).cwiseAbs().maxCoeff() / largest;
  return s;
}

}  // namespace rollnoise
