#include "road/sampled_road.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/csv.hpp"

namespace rollnoise {
namespace {

// Points within this fraction of a sample spacing outside the grid are taken as on its edge, so
// that rounding in x / spacing does not reject the grid's own end points.
constexpr double edge_slack = 1e-9;

}  // namespace

SampledProfile::SampledProfile(std::string type, double spacing, std::vector<double> samples)
    : type_(std::move(type)), spacing_(spacing), samples_(std::move(samples)) {
  if (!(spacing_ > 0.0) || samples_.size() < 2) {
    throw std::invalid_argument("SampledProfile: needs a spacing > 0 and at least two samples");
  }
}

double SampledProfile::height(double x) const {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  const double t = x / spacing_;
  const auto last = samples_.size() - 1;
  if (!(t <= static_cast<double>(last) + edge_slack)) {  // also NaN
    throw std::logic_error(type_ + " road: x = " + format_number(x) + " m is beyond the generated range [0, " +
                           format_number(end()) + "]");
  }
  const std::size_t i = std::min(static_cast<std::size_t>(t), last - 1);
  const double f = std::min(t - static_cast<double>(i), 1.0);
  return (1.0 - f) * samples_[i] + f * samples_[i + 1];
}

SampledSurface::SampledSurface(std::string type, double spacing, std::size_t x_count, std::size_t y_count,
                               std::vector<double> samples)
    : type_(std::move(type)), spacing_(spacing), x_count_(x_count), y_count_(y_count), samples_(std::move(samples)) {
  if (!(spacing_ > 0.0) || x_count_ < 2 || y_count_ < 3 || y_count_ % 2 == 0 ||
      samples_.size() != x_count_ * y_count_) {
    throw std::invalid_argument("SampledSurface: needs a spacing > 0, x_count >= 2, an odd y_count >= 3 and "
                                "x_count * y_count samples");
  }
}

double grid_height(const double* samples, std::size_t stride, std::size_t x_count, std::size_t y_count,
                   double spacing, double x, double y, const std::string& type, std::size_t first_column,
                   std::size_t columns) {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  const auto last_x = static_cast<double>(x_count - 1);
  const auto last_y = static_cast<double>(y_count - 1);
  const double t = x / spacing;
  const double u = y / spacing + 0.5 * last_y;
  if (!(t <= last_x + edge_slack) || !(u >= -edge_slack && u <= last_y + edge_slack)) {  // also NaN
    throw std::logic_error(type + " road: (x, y) = (" + format_number(x) + ", " + format_number(y) +
                           ") m is outside the generated surface, x in [0, " + format_number(spacing * last_x) +
                           "], |y| <= " + format_number(spacing * static_cast<double>((y_count - 1) / 2)));
  }
  const std::size_t i = std::min(static_cast<std::size_t>(std::max(t, 0.0)), x_count - 2);
  const std::size_t j = std::min(static_cast<std::size_t>(std::max(u, 0.0)), y_count - 2);
  if (columns != 0 && (j < first_column || j + 2 > first_column + columns)) {
    throw std::logic_error(type + " road: y = " + format_number(y) + " m is outside the strip of columns " +
                           std::to_string(first_column) + " to " + std::to_string(first_column + columns - 1) +
                           " generated under the tyre");
  }
  const double fx = std::clamp(t - static_cast<double>(i), 0.0, 1.0);
  const double fy = std::clamp(u - static_cast<double>(j), 0.0, 1.0);
  const double* row0 = samples + i * stride + (j - first_column);
  const double* row1 = row0 + stride;
  // Exact at the grid points (weights 1 and 0).
  return (1.0 - fx) * ((1.0 - fy) * row0[0] + fy * row0[1]) + fx * ((1.0 - fy) * row1[0] + fy * row1[1]);
}

double SampledSurface::height(double x, double y) const {
  return grid_height(samples_.data(), y_count_, x_count_, y_count_, spacing_, x, y, type_);
}

std::vector<double> SampledSurface::row(std::size_t i) const {
  const auto first = samples_.begin() + static_cast<std::ptrdiff_t>(i * y_count_);
  return std::vector<double>(first, first + static_cast<std::ptrdiff_t>(y_count_));
}

std::vector<double> SampledSurface::column(std::size_t j) const {
  std::vector<double> line(x_count_);
  for (std::size_t i = 0; i < x_count_; ++i) line[i] = samples_[i * y_count_ + j];
  return line;
}

}  // namespace rollnoise
