// ProfileSurface and make_road_surface: reads a [road] table and builds the surface it
// describes, 1-D profiles through make_road_profile.
#include "road/road_surface.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/aggregate_road.hpp"
#include "road/height_map_surface.hpp"
#include "road/profile_surface_road.hpp"
#include "road/random_surface.hpp"
#include "road/random_spectrum.hpp"
#include "road/texture_road.hpp"

namespace rollnoise {

ProfileSurface::ProfileSurface(std::unique_ptr<RoadProfile> profile) : profile_(std::move(profile)) {
  if (!profile_) throw std::invalid_argument("ProfileSurface: no profile");
}

std::string ProfileSurface::type() const { return profile_->type(); }

double ProfileSurface::height(double x, double /*y*/) const { return profile_->height(x); }

std::vector<std::string> ProfileSurface::warnings() const {
  if (profile_->type() != "file") return {};
  return {"[road] type = \"file\": the one measured line is rolled under every lateral line of the contact patch, "
          "identical across the tyre as no real surface is, which overstates the excitation; for a 2-D surface with "
          "the line's texture spectrum and height distribution use type = \"profile_surface\" with the same file"};
}

namespace {

// RandomSurface checks its parameters without knowing the case file: its InputErrors carry the
// bare key and no source. Name the key as "[road] key" in its file.
template <class Build>
std::unique_ptr<RoadSurface> build_named(const ConfigTable& road, Build build) {
  try {
    return build();
  } catch (const InputError& e) {
    if (!e.source().empty() || e.key().empty()) throw;
    road.fail(e.key(), e.problem());
  }
}

std::unique_ptr<RoadSurface> make_random_surface(const ConfigTable& road, double x_max, double half_width,
                                                 RoadBuild build) {
  RandomSurfaceSpec spec;
  read_random_spectrum_keys(road, spec);
  // A fixed patch of road, so that runs of different duration and tyres of different width on
  // the same case see the same surface.
  spec.length = road.positive("length", 20.0);
  spec.width = road.positive("width", 0.5);
  spec.x_max = x_max;
  spec.half_width = half_width;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return std::make_unique<RandomSurface>(spec); });
}

std::unique_ptr<RoadSurface> make_texture_map(const ConfigTable& road, double x_max, double half_width, RoadBuild build) {
  TextureRoadSpec spec;
  read_texture_keys(road, spec, true, 20.0);
  spec.x_max = x_max;
  spec.half_width = half_width;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return make_rolling_texture_surface(spec); });
}

std::unique_ptr<RoadSurface> make_aggregate_map(const ConfigTable& road, double x_max, double half_width,
                                                RoadBuild build) {
  AggregateRoadSpec spec;
  read_aggregate_keys(road, spec, true, 5.0);
  spec.x_max = x_max;
  spec.half_width = half_width;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return make_rolling_aggregate_surface(spec); });
}

std::unique_ptr<RoadSurface> make_height_map(const ConfigTable& road, double x_min, double x_max,
                                             double half_width, RoadBuild build) {
  const std::string name = road.text("file");
  if (name.empty()) road.fail("file", "must name a CSV file (columns x,y,z in m, one row per grid point)");
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  // Relative to the file that set the key (the case file, or a model file it includes).
  const ReferencedFile found = find_referenced_file(name, road.source_of("file"));
  road.note_referenced_file("file", found);  // listed in the summary when outside its folder
  const std::filesystem::path& path = found.path;
  return std::make_unique<HeightMapSurface>(path, x_min, x_max, half_width);
}

}  // namespace

std::unique_ptr<RoadSurface> make_road_surface(const ConfigTable& road, double x_min, double x_max,
                                               double half_width, RoadBuild build) {
  if (std::isnan(x_min) || std::isnan(x_max)) {
    throw std::invalid_argument("make_road_surface: the x range must be numbers");
  }
  if (!(half_width >= 0.0) || !std::isfinite(half_width)) {
    throw std::invalid_argument("make_road_surface: half_width must be finite and >= 0");
  }
  // A library surface file's descriptive [about] table (name, description, mpd_m, sources, ...)
  // is for people and tools, not for building the road.
  if (const toml::node* about = road.raw("about"); about && !about->is_table()) {
    road.fail("about", "must be a table of descriptive keys ([about] name = ..., description = ...)");
  }
  const std::string type = road.choice(
      "type", {"flat", "sine", "random", "file", "cleat", "iso8608", "random_surface", "surface", "profile_surface", "texture", "aggregate"});
  // Read before the type's keys, whose check for unknown keys must know it.
  RoadAbsorption absorption = read_road_absorption(road);
  std::unique_ptr<RoadSurface> surface;
  if (type == "profile_surface") surface = make_profile_surface(road, x_max, half_width, build);
  else if (type == "random_surface") surface = make_random_surface(road, x_max, half_width, build);
  else if (type == "surface") surface = make_height_map(road, x_min, x_max, half_width, build);
  else if (type == "texture") surface = make_texture_map(road, x_max, half_width, build);
  else if (type == "aggregate") surface = make_aggregate_map(road, x_max, half_width, build);
  else if (build == RoadBuild::keys_only) (void)make_road_profile(road, x_min, x_max, build);
  else surface = std::make_unique<ProfileSurface>(make_road_profile(road, x_min, x_max));
  if (build == RoadBuild::keys_only) return nullptr;
  surface->set_absorption(std::move(absorption));
  return surface;
}

}  // namespace rollnoise
