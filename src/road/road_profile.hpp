#pragma once
// A road surface profile r(x) along the direction of travel (m, upward; MODEL.md §1).
//
// Convention shared by every profile: the road is flat, r = 0, for x < 0. That is the lead-in
// on which the pre-history of the static load rolled, so a run starts in static equilibrium
// and points that trail the first one (coupled_sdof) see a flat road until they reach x = 0.
#include <memory>
#include <string>

namespace rollnoise {

class ConfigTable;

class RoadProfile {
 public:
  virtual ~RoadProfile() = default;
  // "flat", "sine", "random", "file", "cleat", "iso8608", "texture", "aggregate".
  virtual std::string type() const = 0;
  // Height at x (m). Defined for every x; r(x) = 0 for x < 0.
  virtual double height(double x) const = 0;
};

// What make_road_profile and make_road_surface do with a table: build the road, or only read and
// check its keys (unknown keys, types and the ranges read with them), without generating the
// road or reading the files it names, and return nullptr: a run checks its road before the
// tyre's model, whose two-layer tables take tens of seconds.
enum class RoadBuild { road, keys_only };

// Builds the profile of a [road] table. The run will look at x in [x_min, x_max]; profiles
// that are generated or read cover at least that range (a file that does not is an
// InputError). Unknown keys are rejected; an [about] table (a library surface file's
// description, models/surfaces) is ignored.
std::unique_ptr<RoadProfile> make_road_profile(const ConfigTable& road, double x_min, double x_max,
                                               RoadBuild build = RoadBuild::road);

}  // namespace rollnoise
