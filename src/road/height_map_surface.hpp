#pragma once
// A measured or externally made 2-D road surface: a height map read from a CSV file with
// columns x, y, z (m) in long form, one row per point of a regular rectangular grid (any row
// order), or from an HDF5 file (/x, /y, /z with units attributes, height_map_hdf5.hpp; told by
// its signature), interpolated bilinearly. HDF5 maps may mark dropouts with NaN: they are filled,
// and spikes replaced, along each y line per ISO 13473-1 (line_cleaning.hpp). As for every road, r = 0 for x < 0 (road_profile.hpp).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "road/road_surface.hpp"

namespace rollnoise {

struct NumericCsv;

class HeightMapSurface final : public RoadSurface {
 public:
  // Reads `path` (header with x, y and z; '#' comments; other columns ignored) and checks that
  // the points form a full regular grid and cover the range the run needs: x in
  // [max(0, x_min), x_max], y in [-half_width, half_width]. Every problem is an InputError
  // naming the file.
  HeightMapSurface(const std::filesystem::path& path, double x_min, double x_max, double half_width);
  // From a table already parsed; `source` names it in messages. The same checks.
  HeightMapSurface(const NumericCsv& csv, const std::string& source, double x_min, double x_max,
                   double half_width);

  std::string type() const override;  // "surface"
  // Bilinear interpolation; 0 for x < 0. A point with x >= 0 outside the data is a
  // std::logic_error: the range was checked when the map was read.
  double height(double x, double y) const override;

  // The grid lines, increasing, uniformly spaced (to 1e-9 relative).
  const std::vector<double>& x_lines() const noexcept { return x_; }
  const std::vector<double>& y_lines() const noexcept { return y_; }
  const std::string& source() const noexcept { return source_; }
  // Samples filled as dropouts and replaced as spikes (HDF5 maps).
  std::size_t dropouts() const noexcept { return dropouts_; }
  std::size_t spikes() const noexcept { return spikes_; }

 private:
  static void check_run_range(double x_min, double x_max, double half_width);
  void read_long_form(const NumericCsv& csv);
  void check_covers(double x_min, double x_max, double half_width) const;

  std::vector<double> x_;
  std::vector<double> y_;
  std::vector<double> z_;  // z_[i * y_.size() + j] at (x_[i], y_[j])
  std::string source_;
  std::size_t dropouts_ = 0;
  std::size_t spikes_ = 0;
};

}  // namespace rollnoise
