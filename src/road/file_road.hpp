#pragma once
// A measured or externally made profile, read from a CSV file with columns x and z (m),
// interpolated linearly between its rows.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "road/road_profile.hpp"

namespace rollnoise {

class FileRoad final : public RoadProfile {
 public:
  // Reads `path` (header x,z; '#' comments) and checks that it covers the range the run needs,
  // [max(0, x_min), x_max]. Every problem is an InputError naming the file.
  FileRoad(const std::filesystem::path& path, double x_min, double x_max);
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

 private:
  FileRoad(std::pair<std::vector<double>, std::vector<double>> xz, std::string source);
  void check_covers(double x_min, double x_max) const;

  std::vector<double> x_;
  std::vector<double> z_;
  std::string source_;
};

}  // namespace rollnoise
