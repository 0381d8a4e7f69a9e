#include "road/height_map_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/hdf5_reader.hpp"
#include "road/height_map_hdf5.hpp"
#include "road/line_cleaning.hpp"

namespace rollnoise {
namespace {

// Relative tolerance on the uniformity of the grid spacing.
constexpr double spacing_tolerance = 1e-9;

std::string point_text(double x, double y) {
  return "(x, y) = (" + format_number(x) + ", " + format_number(y) + ")";
}

// The distinct values of `values`, increasing, checked to be at least 2 and evenly spaced.
std::vector<double> grid_lines(const std::vector<double>& values, const char* name,
                               const std::string& source) {
  std::vector<double> lines(values);
  std::sort(lines.begin(), lines.end());
  lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
  if (lines.size() < 2) {
    throw InputError(source, "",
                     std::string("needs at least 2 distinct ") + name +
                         " values for bilinear interpolation (has " + std::to_string(lines.size()) + ")");
  }
  if (!std::isfinite(lines.back() - lines.front())) {
    throw InputError(source, "", std::string("the ") + name + " values span more than the largest number");
  }
  const double step = (lines.back() - lines.front()) / static_cast<double>(lines.size() - 1);
  for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
    const double d = lines[k + 1] - lines[k];
    if (!(std::abs(d - step) <= spacing_tolerance * step)) {
      throw InputError(source, "",
                       std::string("the ") + name + " values do not form an evenly spaced grid: " +
                           name + " = " + format_number(lines[k]) + " is followed by " + name +
                           " = " + format_number(lines[k + 1]) + " (step " + format_number(d) +
                           "), but the mean step over the " + std::to_string(lines.size()) +
                           " distinct values is " + format_number(step) +
                           " (each step must match it to 1e-9 relative; is a point missing, or "
                           "one grid line written with two different values?)");
    }
  }
  return lines;
}

// Index of the cell [lines[i], lines[i+1]] that holds v (lines evenly spaced, v within them).
std::size_t locate(const std::vector<double>& lines, double v) {
  const std::size_t n = lines.size();
  const double step = (lines.back() - lines.front()) / static_cast<double>(n - 1);
  const double t = (v - lines.front()) / step;
  std::size_t i = t <= 0.0 ? 0 : std::min(static_cast<std::size_t>(t), n - 2);
  // The lines are even only to 1e-9: correct the estimate against the lines themselves.
  while (i > 0 && v < lines[i]) --i;
  while (i + 2 < n && v >= lines[i + 1]) ++i;
  return i;
}

NumericCsv read_map(const std::filesystem::path& path) {
  return read_numeric_csv(path);  // its errors name the file already
}

}  // namespace

HeightMapSurface::HeightMapSurface(const std::filesystem::path& path, double x_min, double x_max,
                                   double half_width)
    : source_(path.string()) {
  check_run_range(x_min, x_max, half_width);
  if (has_hdf5_signature(path)) {
    HeightMapGrid grid = read_height_map_hdf5(path);
    x_ = grid_lines(grid.x, "x", source_);
    y_ = grid_lines(grid.y, "y", source_);
    // Dropouts (NaN) filled and spikes replaced along each y line (ISO 13473-1 works along the
    // direction of travel).
    const std::size_t nx = x_.size();
    const std::size_t ny = y_.size();
    const double spacing = (x_.back() - x_.front()) / static_cast<double>(nx - 1);
    std::vector<double> line(nx);
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) line[i] = grid.z[i * ny + j];
      const LineCleaning cleaning =
          clean_measured_line(line, spacing, source_ + " (y = " + format_number(y_[j]) + " m)");
      dropouts_ += cleaning.dropouts;
      spikes_ += cleaning.spikes;
      for (std::size_t i = 0; i < nx; ++i) grid.z[i * ny + j] = line[i];
    }
    z_ = std::move(grid.z);
  } else {
    read_long_form(read_map(path));
  }
  check_covers(x_min, x_max, half_width);
}

HeightMapSurface::HeightMapSurface(const NumericCsv& csv, const std::string& source, double x_min,
                                   double x_max, double half_width)
    : source_(source) {
  check_run_range(x_min, x_max, half_width);
  read_long_form(csv);
  check_covers(x_min, x_max, half_width);
}

void HeightMapSurface::check_run_range(double x_min, double x_max, double half_width) {
  if (std::isnan(x_min) || std::isnan(x_max) || !(half_width >= 0.0)) {
    throw std::invalid_argument("HeightMapSurface: the run's range must be numbers, half_width >= 0");
  }
}

void HeightMapSurface::read_long_form(const NumericCsv& csv) {
  const std::vector<double>& xs = csv.columns.at(csv.column("x", source_));
  const std::vector<double>& ys = csv.columns.at(csv.column("y", source_));
  const std::vector<double>& zs = csv.columns.at(csv.column("z", source_));
  const std::size_t rows = xs.size();
  if (ys.size() != rows || zs.size() != rows) {
    throw InputError(source_, "", "the x, y and z columns have different lengths");
  }
  // Rows are counted from 1 over the data rows (comments and the header not counted).
  for (std::size_t r = 0; r < rows; ++r) {
    if (!std::isfinite(xs[r]) || !std::isfinite(ys[r]) || !std::isfinite(zs[r])) {
      throw InputError(source_, "data row " + std::to_string(r + 1), "x, y and z must be finite numbers");
    }
  }
  if (rows < 4) {
    throw InputError(source_, "",
                     "needs at least 4 data rows (a 2 x 2 grid) for bilinear interpolation (has " +
                         std::to_string(rows) + ")");
  }
  x_ = grid_lines(xs, "x", source_);
  y_ = grid_lines(ys, "y", source_);
  const std::size_t nx = x_.size();
  const std::size_t ny = y_.size();

  // Every (x_i, y_j) exactly once: sort the rows by grid point; neighbours with the same point
  // are duplicates, and with none of those the k-th point must be point k.
  std::vector<std::pair<std::size_t, std::size_t>> order(rows);  // (point index, row)
  for (std::size_t r = 0; r < rows; ++r) {
    const auto i = static_cast<std::size_t>(std::lower_bound(x_.begin(), x_.end(), xs[r]) - x_.begin());
    const auto j = static_cast<std::size_t>(std::lower_bound(y_.begin(), y_.end(), ys[r]) - y_.begin());
    order[r] = {i * ny + j, r};
  }
  std::sort(order.begin(), order.end());
  for (std::size_t k = 0; k + 1 < rows; ++k) {
    if (order[k].first == order[k + 1].first) {
      const std::size_t p = order[k].first;
      throw InputError(source_, "data row " + std::to_string(order[k + 1].second + 1),
                       "repeats the grid point " + point_text(x_[p / ny], y_[p % ny]) +
                           " of data row " + std::to_string(order[k].second + 1) +
                           "; each point of the grid must appear exactly once");
    }
  }
  const std::string grid_size = std::to_string(nx) + " x values by " + std::to_string(ny) +
                                " y values need " + std::to_string(nx) + " * " + std::to_string(ny) +
                                " rows; the file has " + std::to_string(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    if (order[k].first != k) {
      throw InputError(source_, "", "the points do not form a full rectangular grid: " +
                                        point_text(x_[k / ny], y_[k % ny]) + " is missing (" +
                                        grid_size + ")");
    }
  }
  if (rows != nx * ny) {  // all rows matched points 0 .. rows-1; the rest are missing
    throw InputError(source_, "", "the points do not form a full rectangular grid: " +
                                      point_text(x_[rows / ny], y_[rows % ny]) + " is missing (" +
                                      grid_size + ")");
  }
  z_.resize(rows);
  for (const auto& [point, row] : order) z_[point] = zs[row];
}

std::string HeightMapSurface::type() const { return "surface"; }

void HeightMapSurface::check_covers(double x_min, double x_max, double half_width) const {
  const double lo = std::max(0.0, x_min);
  if (x_max < lo) return;  // the run stays on the lead-in (x < 0), where r = 0 anyway
  if (x_.front() > lo || x_.back() < x_max || y_.front() > -half_width || y_.back() < half_width) {
    throw InputError(source_, "",
                     "the height map covers x from " + format_number(x_.front()) + " to " +
                         format_number(x_.back()) + " m and y from " + format_number(y_.front()) +
                         " to " + format_number(y_.back()) + " m, but the run needs x from " +
                         format_number(lo) + " to " + format_number(x_max) + " m and y from " +
                         format_number(-half_width) + " to " + format_number(half_width) + " m");
  }
}

double HeightMapSurface::height(double x, double y) const {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  if (!(x >= x_.front() && x <= x_.back() && y >= y_.front() && y <= y_.back())) {  // also NaN
    throw std::logic_error("HeightMapSurface::height: " + point_text(x, y) +
                           " m is outside the data of " + source_ + ", x in [" +
                           format_number(x_.front()) + ", " + format_number(x_.back()) + "], y in [" +
                           format_number(y_.front()) + ", " + format_number(y_.back()) + "]");
  }
  const std::size_t i = locate(x_, x);
  const std::size_t j = locate(y_, y);
  const std::size_t ny = y_.size();
  const double fx = (x - x_[i]) / (x_[i + 1] - x_[i]);
  const double fy = (y - y_[j]) / (y_[j + 1] - y_[j]);
  const double* row0 = z_.data() + i * ny + j;
  const double* row1 = row0 + ny;
  return (1.0 - fx) * ((1.0 - fy) * row0[0] + fy * row0[1]) + fx * ((1.0 - fy) * row1[0] + fy * row1[1]);
}

}  // namespace rollnoise
