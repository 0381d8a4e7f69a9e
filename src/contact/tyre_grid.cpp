#include "contact/tyre_grid.hpp"

#include <algorithm>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

double TyreGrid::circumference() const { return 2.0 * std::numbers::pi * radius; }
double TyreGrid::dx() const { return circumference() / circumferential; }
double TyreGrid::contact_width() const { return tread_width > 0.0 ? tread_width : width; }
double TyreGrid::dy() const { return contact_width() / lateral; }
double TyreGrid::x(int i) const { return (i - window / 2) * dx(); }
double TyreGrid::y(int j) const { return 0.5 * (width - contact_width()) + (j + 0.5) * dy(); }

int TyreGrid::grid_index(int i) const {
  const int g = (i - window / 2) % circumferential;
  return g < 0 ? g + circumferential : g;
}

Eigen::MatrixX2d TyreGrid::positions() const {
  Eigen::MatrixX2d xy(points(), 2);
  for (int j = 0; j < lateral; ++j)
    for (int i = 0; i < window; ++i) {
      const Eigen::Index p = i + static_cast<Eigen::Index>(window) * j;
      xy(p, 0) = x(i);
      xy(p, 1) = y(j);
    }
  return xy;
}

Eigen::VectorXd TyreGrid::undeformed_gap() const {
  Eigen::VectorXd h(points());
  for (int j = 0; j < lateral; ++j)
    for (int i = 0; i < window; ++i) {
      const double xi = x(i);
      const double around = radius - std::sqrt(radius * radius - xi * xi);
      const double yc = y(j) - 0.5 * width;
      const double across = crown_radius > 0.0 ? yc * yc / (2.0 * crown_radius) : 0.0;
      h(i + static_cast<Eigen::Index>(window) * j) = around + across;
    }
  return h;
}

void TyreGrid::validate() const {
  if (!(radius > 0.0) || !(width > 0.0)) throw std::invalid_argument("tyre radius and width must be > 0");
  if (circumferential < 8 || circumferential % 2 != 0)
    throw std::invalid_argument("points_circumferential must be an even number >= 8");
  if (lateral < 1) throw std::invalid_argument("points_lateral must be >= 1");
  if (window < 2 || window > circumferential / 2)
    throw std::invalid_argument("contact_window must be from 2 to half of points_circumferential");
  if (std::abs(x(window - 1)) >= radius || std::abs(x(0)) >= radius)
    throw std::invalid_argument("contact window longer than the tyre diameter");
  if (crown_radius < 0.0) throw std::invalid_argument("crown_radius must be >= 0");
  if (tread_width < 0.0 || tread_width > width)
    throw std::invalid_argument("tread_width must lie between 0 and the belt width");
}

ContactExtent contact_extent(const TyreGrid& grid, const Eigen::Ref<const Eigen::VectorXd>& force) {
  ContactExtent e;
  int i_min = grid.window, i_max = -1, j_min = grid.lateral, j_max = -1;
  for (int j = 0; j < grid.lateral; ++j)
    for (int i = 0; i < grid.window; ++i)
      if (force(i + static_cast<Eigen::Index>(grid.window) * j) > 0.0) {
        ++e.points;
        i_min = std::min(i_min, i);
        i_max = std::max(i_max, i);
        j_min = std::min(j_min, j);
        j_max = std::max(j_max, j);
      }
  if (e.points) {
    e.i_min = i_min;
    e.i_max = i_max;
    e.j_min = j_min;
    e.j_max = j_max;
  }
  return e;
}

}  // namespace rollnoise
