#include "contact/texture_under_contact.hpp"

#include <cmath>
#include <stdexcept>

namespace rollnoise {

std::vector<std::vector<double>> centre_line_road(const TyreContactTrace& trace, const TyreGrid& grid) {
  const int i = grid.window / 2;
  std::vector<int> rows;
  if (grid.lateral % 2 == 1) {
    rows = {(grid.lateral - 1) / 2};
  } else {
    rows = {grid.lateral / 2 - 1, grid.lateral / 2};
  }
  std::vector<std::vector<double>> lines;
  for (int j : rows) {
    const Eigen::Index p = i + static_cast<Eigen::Index>(grid.window) * j;
    if (p >= trace.road.cols()) throw std::invalid_argument("centre_line_road: the trace does not match the grid");
    std::vector<double> line(static_cast<std::size_t>(trace.road.rows()));
    for (Eigen::Index n = 0; n < trace.road.rows(); ++n) line[static_cast<std::size_t>(n)] = trace.road(n, p);
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<double> patch_mean_road(const TyreContactTrace& trace, const TyreGrid& grid, double patch_length) {
  if (trace.road.cols() != grid.points()) throw std::invalid_argument("patch_mean_road: the trace does not match the grid");
  std::vector<int> columns;
  for (int i = 0; i < grid.window; ++i)
    if (std::abs(grid.x(i)) <= 0.5 * patch_length) columns.push_back(i);
  if (columns.empty()) columns.push_back(grid.window / 2);
  const double count = static_cast<double>(columns.size()) * grid.lateral;
  std::vector<double> mean(static_cast<std::size_t>(trace.road.rows()), 0.0);
  for (Eigen::Index n = 0; n < trace.road.rows(); ++n) {
    double sum = 0.0;
    for (int j = 0; j < grid.lateral; ++j)
      for (int i : columns) sum += trace.road(n, i + static_cast<Eigen::Index>(grid.window) * j);
    mean[static_cast<std::size_t>(n)] = sum / count;
  }
  return mean;
}

}  // namespace rollnoise
