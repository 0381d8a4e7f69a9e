#pragma once
// A measured or externally made profile, read from a profile CSV file (profile_csv.hpp: columns
// x and z, in m or with a unit such as x_mm, z [mm]; one height line), a laser profilometer
// export or a line laser file of one profile (line_laser_csv.hpp), interpolated linearly between its rows: that linear interpolation is how the profile
// is resampled to the contact grid of a run.
//
// Cleaning (ISO 13473-1, line_cleaning.hpp): when x is evenly spaced (profile_file.hpp's
// test), dropouts (empty cells) are filled and spikes (steps |dz| >= 3 dx) replaced by
// clean_profile. When it is not, or with SpikeHandling::keep (a made-up profile whose steep
// steps are meant: a cleat, a kerb), spikes are not looked for and the rows with a dropout are
// left out, so that linear interpolation bridges them. The counts are kept.
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "road/road_profile.hpp"

namespace rollnoise {

enum class SpikeHandling { remove, keep };

class FileRoad final : public RoadProfile {
 public:
  // Reads `path` (header x,z; '#' comments) and checks that it covers the range the run needs,
  // [max(0, x_min), x_max]. Every problem is an InputError naming the file.
  FileRoad(const std::filesystem::path& path, double x_min, double x_max,
           SpikeHandling spikes = SpikeHandling::remove);
  // From data already in memory; `source` names it in messages. x strictly increasing, at
  // least 2 rows, all values finite.
  FileRoad(std::vector<double> x, std::vector<double> z, std::string source);

  std::string type() const override;
  // Linear interpolation; 0 for x < 0. x >= 0 outside the data is a std::logic_error: the
  // range was checked when the road was read.
  double height(double x) const override;

  double x_first() const { return x_.front(); }
  double x_last() const { return x_.back(); }
  const std::string& source() const noexcept { return source_; }
  // Samples filled as dropouts (or rows left out) and replaced as spikes when reading the file.
  std::size_t dropouts() const noexcept { return dropouts_; }
  std::size_t spikes() const noexcept { return spikes_; }

  struct Rows {
    std::vector<double> x, z;
    std::size_t dropouts = 0, spikes = 0;
  };

 private:
  FileRoad(Rows rows, std::string source);
  void check_covers(double x_min, double x_max) const;

  std::vector<double> x_;
  std::vector<double> z_;
  std::string source_;
  std::size_t dropouts_ = 0;
  std::size_t spikes_ = 0;
};

}  // namespace rollnoise
