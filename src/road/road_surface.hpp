#pragma once
// A road surface r(x, y) (m, upward; MODEL.md §1, §4, §7): x along the road (direction of
// travel), y across it, y = 0 on the wheel's centre line. A rolling tyre samples it at
// (x_i + v t, y_j) for each lateral line y_j of its contact grid.
//
// Convention shared with the 1-D profiles (road_profile.hpp): r = 0 for x < 0, the flat lead-in
// on which the static load's pre-history rolled.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "road/road_absorption.hpp"
#include "road/road_profile.hpp"

namespace rollnoise {

class ConfigTable;

class RoadSurface {
 public:
  virtual ~RoadSurface() = default;
  // "flat", "sine", "random", "file", "cleat", "iso8608" (a 1-D profile on every line),
  // "random_surface", "surface" (a height-map file), "profile_surface", "texture", "aggregate".
  virtual std::string type() const = 0;
  // Height (m) at x along the road and y across it. r = 0 for x < 0. Generated and read
  // surfaces cover the range they were built for; outside it (x >= 0) they throw
  // std::logic_error.
  virtual double height(double x, double y) const = 0;
  // The spacing (m) a generated road was made at, where reading it shows it as made, without
  // interpolation between its samples; empty: any spacing.
  virtual std::optional<double> sample_spacing() const { return std::nullopt; }
  // What a user should know before rolling a tyre over this road; empty: nothing.
  virtual std::vector<std::string> warnings() const { return {}; }

  // The surface's acoustics ([road.absorption], road_absorption.hpp): rigid unless its table
  // says otherwise.
  const RoadAbsorption& absorption() const noexcept { return absorption_; }
  void set_absorption(RoadAbsorption absorption) { absorption_ = std::move(absorption); }

 private:
  RoadAbsorption absorption_;
};

// A 1-D profile used on every lateral line: r(x, y) = r(x).
class ProfileSurface final : public RoadSurface {
 public:
  // `profile` must not be null (std::invalid_argument).
  explicit ProfileSurface(std::unique_ptr<RoadProfile> profile);

  std::string type() const override;
  double height(double x, double y) const override;
  // A measured line (type "file") rolled under every lateral line of a tyre is fully correlated
  // across the tyre, which no real surface is: said, naming profile_surface.
  std::vector<std::string> warnings() const override;

  const RoadProfile& profile() const noexcept { return *profile_; }

 private:
  std::unique_ptr<RoadProfile> profile_;
};

// Builds the surface of a [road] table. The 1-D types (flat, sine, random, file, cleat, iso8608)
// give the same profile on every lateral line (a ProfileSurface around make_road_profile, with
// the same keys and defaults). The 2-D types are "random_surface" (random_surface.hpp),
// "surface" (a height-map file, height_map_surface.hpp), "texture" (texture_road.hpp; as a
// 2-D map, with the keys width and anisotropy) and "aggregate" (aggregate_road.hpp; as a 2-D
// map, with the key width). Every type takes the sub-table `absorption` (road_absorption.hpp),
// carried by the surface. The run looks at x in [x_min, x_max] and y in
// [-half_width, half_width] (half_width >= 0). Unknown keys are rejected; every bad value is an
// InputError naming "[road] key" in the file that set it, or the data file.
// RoadBuild::keys_only: the keys only, nullptr (road_profile.hpp).
std::unique_ptr<RoadSurface> make_road_surface(const ConfigTable& road, double x_min, double x_max,
                                               double half_width, RoadBuild build = RoadBuild::road);

}  // namespace rollnoise
