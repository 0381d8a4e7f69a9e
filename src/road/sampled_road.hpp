#pragma once
// Roads stored as samples on a regular grid from x = 0, the storage of the generated texture,
// ISO 8608 and aggregate roads: a profile (linear interpolation) and a surface (bilinear). As
// for every road, r = 0 for x < 0 (road_profile.hpp); beyond the stored grid (x >= 0) is a
// std::logic_error, since the generator was told the range the run needs.
#include <cstddef>
#include <string>
#include <vector>

#include "road/road_profile.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {

// r(x) from samples at x = j·spacing, j = 0 .. samples.size()-1 (at least two).
class SampledProfile final : public RoadProfile {
 public:
  SampledProfile(std::string type, double spacing, std::vector<double> samples);

  std::string type() const override { return type_; }
  double height(double x) const override;

  double spacing() const noexcept { return spacing_; }
  double end() const noexcept { return spacing_ * static_cast<double>(samples_.size() - 1); }
  const std::vector<double>& samples() const noexcept { return samples_; }

 private:
  std::string type_;
  double spacing_;
  std::vector<double> samples_;
};

// r(x, y) from samples at x = i·spacing (i = 0 .. x_count-1) and y = (j - (y_count-1)/2)·spacing
// (j = 0 .. y_count-1, y_count odd, so y = 0 is a grid line), stored row-major in x:
// samples[i·y_count + j].
// Bilinear interpolation on such a grid, with rows `stride` apart (stride >= y_count), for every
// surface stored this way (SampledSurface, RandomSurface). r = 0 for x < 0; a point outside the
// grid (beyond rounding) is a std::logic_error naming `type`. A grid may hold only the columns
// first_column .. first_column + columns − 1 (columns = 0: all), samples[i·stride + j − first_column]
// (a rolling road's strip under the tyre); a point between columns it does not hold is a logic_error.
double grid_height(const double* samples, std::size_t stride, std::size_t x_count, std::size_t y_count,
                   double spacing, double x, double y, const std::string& type, std::size_t first_column = 0,
                   std::size_t columns = 0);

class SampledSurface final : public RoadSurface {
 public:
  SampledSurface(std::string type, double spacing, std::size_t x_count, std::size_t y_count,
                 std::vector<double> samples);

  std::string type() const override { return type_; }
  double height(double x, double y) const override;

  double spacing() const noexcept { return spacing_; }
  std::size_t x_count() const noexcept { return x_count_; }
  std::size_t y_count() const noexcept { return y_count_; }
  double end_x() const noexcept { return spacing_ * static_cast<double>(x_count_ - 1); }
  double half_extent_y() const noexcept { return spacing_ * static_cast<double>((y_count_ - 1) / 2); }
  double sample(std::size_t i, std::size_t j) const noexcept { return samples_[i * y_count_ + j]; }
  // The line x = i·spacing across the road, and the line y = (j - (y_count-1)/2)·spacing along it.
  std::vector<double> row(std::size_t i) const;
  std::vector<double> column(std::size_t j) const;

 private:
  std::string type_;
  double spacing_;
  std::size_t x_count_;
  std::size_t y_count_;
  std::vector<double> samples_;
};

}  // namespace rollnoise
