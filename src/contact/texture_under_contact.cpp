#include "contact/texture_under_contact.hpp"

#include <cmath>
#include <stdexcept>

namespace rollnoise {

TextureUnderContact::TextureUnderContact(const TyreGrid& grid) : grid_(grid) {
  if (grid.lateral % 2 == 1) {
    centre_rows_ = {(grid.lateral - 1) / 2};
  } else {
    centre_rows_ = {grid.lateral / 2 - 1, grid.lateral / 2};
  }
  centre_.resize(centre_rows_.size());
}

void TextureUnderContact::push(const Eigen::Ref<const Eigen::VectorXd>& road) {
  if (road.size() != grid_.points()) throw std::invalid_argument("texture under contact: the road does not match the grid");
  const auto window = static_cast<Eigen::Index>(grid_.window);
  for (std::size_t k = 0; k < centre_rows_.size(); ++k) centre_[k].push_back(road(window / 2 + window * centre_rows_[k]));
  for (Eigen::Index i = 0; i < window; ++i) {
    double sum = 0.0;
    for (int j = 0; j < grid_.lateral; ++j) sum += road(i + window * j);
    column_means_.push_back(sum / grid_.lateral);
  }
}

std::vector<double> TextureUnderContact::patch_mean(double patch_length) const {
  std::vector<int> columns;
  for (int i = 0; i < grid_.window; ++i)
    if (std::abs(grid_.x(i)) <= 0.5 * patch_length) columns.push_back(i);
  if (columns.empty()) columns.push_back(grid_.window / 2);
  const auto window = static_cast<std::size_t>(grid_.window);
  const std::size_t steps = column_means_.size() / window;
  std::vector<double> mean(steps, 0.0);
  for (std::size_t n = 0; n < steps; ++n) {
    double sum = 0.0;
    for (int i : columns) sum += column_means_[n * window + static_cast<std::size_t>(i)];
    mean[n] = sum / static_cast<double>(columns.size());
  }
  return mean;
}

namespace {
TextureUnderContact from_trace(const TyreContactTrace& trace, const TyreGrid& grid) {
  if (trace.road.cols() != grid.points()) throw std::invalid_argument("texture under contact: the trace does not match the grid");
  TextureUnderContact texture(grid);
  for (Eigen::Index n = 0; n < trace.road.rows(); ++n) texture.push(trace.road.row(n).transpose());
  return texture;
}
}  // namespace

std::vector<std::vector<double>> centre_line_road(const TyreContactTrace& trace, const TyreGrid& grid) {
  return from_trace(trace, grid).centre_lines();
}

std::vector<double> patch_mean_road(const TyreContactTrace& trace, const TyreGrid& grid, double patch_length) {
  return from_trace(trace, grid).patch_mean(patch_length);
}

}  // namespace rollnoise
