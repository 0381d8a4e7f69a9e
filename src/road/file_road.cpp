#include "road/file_road.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

std::pair<std::vector<double>, std::vector<double>> read_profile(const std::filesystem::path& path) {
  NumericCsv csv = read_numeric_csv(path);  // its errors name the file already
  const std::string source = path.string();
  const std::size_t cx = csv.column("x", source);
  const std::size_t cz = csv.column("z", source);
  return {std::move(csv.columns[cx]), std::move(csv.columns[cz])};
}

}  // namespace

FileRoad::FileRoad(std::vector<double> x, std::vector<double> z, std::string source)
    : x_(std::move(x)), z_(std::move(z)), source_(std::move(source)) {
  if (x_.size() != z_.size()) {
    throw InputError(source_, "", "the x and z columns have different lengths");
  }
  if (x_.size() < 2) {
    throw InputError(source_, "",
                     "needs at least 2 data rows to interpolate (has " + std::to_string(x_.size()) + ")");
  }
  // Rows are counted from 1 over the data rows (comments and the header not counted).
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const std::string row = "data row " + std::to_string(i + 1);
    if (!std::isfinite(x_[i]) || !std::isfinite(z_[i])) {
      throw InputError(source_, row, "x and z must be finite numbers");
    }
    if (i > 0 && !(x_[i] > x_[i - 1])) {
      throw InputError(source_, row,
                       "x = " + format_number(x_[i]) + " is not greater than x = " +
                           format_number(x_[i - 1]) + " of the row before; x must be strictly increasing");
    }
  }
}

FileRoad::FileRoad(const std::filesystem::path& path, double x_min, double x_max)
    : FileRoad(read_profile(path), path.string()) {
  check_covers(x_min, x_max);
}

FileRoad::FileRoad(std::pair<std::vector<double>, std::vector<double>> xz, std::string source)
    : FileRoad(std::move(xz.first), std::move(xz.second), std::move(source)) {}

std::string FileRoad::type() const { return "file"; }

void FileRoad::check_covers(double x_min, double x_max) const {
  const double lo = std::max(0.0, x_min);
  if (x_max < lo) return;  // the run stays on the lead-in (x < 0), where r = 0 anyway
  if (x_.front() > lo || x_.back() < x_max) {
    throw InputError(source_, "",
                     "the profile covers x from " + format_number(x_.front()) + " to " +
                         format_number(x_.back()) + " m, but the run needs x from " +
                         format_number(lo) + " to " + format_number(x_max) + " m");
  }
}

double FileRoad::height(double x) const {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  if (!(x >= x_.front() && x <= x_.back())) {  // also NaN
    throw std::logic_error("FileRoad::height: x = " + format_number(x) + " m is outside the data of " +
                           source_ + " [" + format_number(x_.front()) + ", " +
                           format_number(x_.back()) + "]");
  }
  // First row with x_[i] > x, clamped so that x = x_.back() uses the last interval.
  auto upper = std::upper_bound(x_.begin(), x_.end(), x);
  if (upper == x_.end()) --upper;
  const std::size_t i = static_cast<std::size_t>(upper - x_.begin());
  const double x0 = x_[i - 1];
  const double x1 = x_[i];
  const double f = (x - x0) / (x1 - x0);
  return (1.0 - f) * z_[i - 1] + f * z_[i];
}

}  // namespace rollnoise
