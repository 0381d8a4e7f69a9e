#include "road/file_road.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/line_cleaning.hpp"
#include "road/profile_csv.hpp"
#include "road/profile_file.hpp"
#include "road/profile_format.hpp"

namespace rollnoise {
namespace {

FileRoad::Rows read_profile(const std::filesystem::path& path, SpikeHandling spikes) {
  const std::string source = path.string();
  const ProfileFormat format = detect_profile_format(path);
  if (format == ProfileFormat::hdf5) {
    throw InputError(source, "",
                     "is an HDF5 height map (a 2-D surface); a 1-D profile (type = \"file\") is a CSV "
                     "with columns x and z; use type = \"surface\" with a tyre model for a height map");
  }
  if (format != ProfileFormat::csv) {
    // The laser profilometer export, line laser pairs (and anything unknown, which this
    // rejects): the loader cleans on its uniform grid.
    LoadedProfile loaded = load_profile_file(path);
    if (loaded.z_lines.size() != 1) {
      throw InputError(source, "", "holds " + std::to_string(loaded.z_lines.size()) +
                                       " height lines; a 1-D profile (type = \"file\") takes one (`rollnoise "
                                       "road` on the file writes them as columns z_1, z_2, ... of road.csv)");
    }
    return {std::move(loaded.x), std::move(loaded.z_lines.front()), loaded.dropouts, loaded.spikes};
  }
  ProfileTable table = read_profile_csv(path);  // its errors name the file already
  if (table.z_lines.size() != 1) {
    throw InputError(source, "header",
                     "has " + std::to_string(table.z_lines.size()) +
                         " height columns (z_1 ...); a 1-D profile (type = \"file\") takes one column z");
  }
  FileRoad::Rows rows;
  rows.x = std::move(table.x);
  rows.z = std::move(table.z_lines.front());
  if (spikes == SpikeHandling::remove && is_uniformly_spaced(rows.x)) {
    const double spacing = (rows.x.back() - rows.x.front()) / static_cast<double>(rows.x.size() - 1);
    const LineCleaning cleaning = clean_measured_line(rows.z, spacing, source);
    rows.dropouts = cleaning.dropouts;
    rows.spikes = cleaning.spikes;
    return rows;
  }
  // Uneven rows, or spikes kept: leave the dropouts out, linear interpolation bridges them.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < rows.x.size(); ++i) {
    if (std::isnan(rows.z[i])) continue;
    rows.x[kept] = rows.x[i];
    rows.z[kept] = rows.z[i];
    ++kept;
  }
  rows.dropouts = rows.x.size() - kept;
  rows.x.resize(kept);
  rows.z.resize(kept);
  return rows;
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

FileRoad::FileRoad(const std::filesystem::path& path, double x_min, double x_max, SpikeHandling spikes)
    : FileRoad(read_profile(path, spikes), path.string()) {
  check_covers(x_min, x_max);
}

FileRoad::FileRoad(Rows rows, std::string source)
    : FileRoad(std::move(rows.x), std::move(rows.z), std::move(source)) {
  dropouts_ = rows.dropouts;
  spikes_ = rows.spikes;
}

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
