// make_road_profile: reads a [road] table and builds the profile it describes (1-D types only;
// the 2-D surfaces are built by make_road_surface, road_surface.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/file_road.hpp"
#include "road/flat_road.hpp"
#include "road/random_road.hpp"
#include "road/random_spectrum.hpp"
#include "road/road_absorption.hpp"
#include "road/road_profile.hpp"
#include "road/sine_road.hpp"
#include "road/cleat_road.hpp"
#include "road/aggregate_road.hpp"
#include "road/iso8608_road.hpp"
#include "road/texture_road.hpp"

namespace rollnoise {
namespace {

// The profile constructors check their parameters without knowing the case file: their
// InputErrors carry the bare key and no source. Name the key as "[road] key" in its file.
// Errors that already name a source (a profile file) pass through.
template <class Build>
std::unique_ptr<RoadProfile> build_named(const ConfigTable& road, Build build) {
  try {
    return build();
  } catch (const InputError& e) {
    if (!e.source().empty() || e.key().empty()) throw;
    road.fail(e.key(), e.problem());
  }
}

std::unique_ptr<RoadProfile> make_cleat(const ConfigTable& road) {
  const double height = road.number("height");
  const double length = road.positive("length");
  const double position = road.non_negative("position", 1.0);
  road.reject_unknown_keys();
  return build_named(road, [&] { return std::make_unique<CleatRoad>(height, length, position); });
}

std::unique_ptr<RoadProfile> make_sine(const ConfigTable& road) {
  const double amplitude = road.positive("amplitude");
  const double wavelength = road.positive("wavelength");
  road.reject_unknown_keys();
  return build_named(road, [&] { return std::make_unique<SineRoad>(amplitude, wavelength); });
}

std::unique_ptr<RoadProfile> make_random(const ConfigTable& road, double x_max, RoadBuild build) {
  RandomRoadSpec spec;
  read_random_spectrum_keys(road, spec);
  // A fixed stretch of road, so that runs of different duration on the same case see the same
  // profile; a run longer than `length` gets a longer (and so different) road.
  spec.x_max = std::max(x_max, road.positive("length", 100.0));
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return std::make_unique<RandomRoad>(spec); });
}

std::unique_ptr<RoadProfile> make_texture(const ConfigTable& road, double x_max, RoadBuild build) {
  TextureRoadSpec spec;
  read_texture_keys(road, spec, false, 100.0);
  spec.x_max = x_max;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return make_texture_profile(spec); });
}

std::unique_ptr<RoadProfile> make_iso8608(const ConfigTable& road, double x_max, RoadBuild build) {
  Iso8608RoadSpec spec;
  read_iso8608_keys(road, spec);
  spec.x_max = x_max;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return make_iso8608_profile(spec); });
}

std::unique_ptr<RoadProfile> make_aggregate(const ConfigTable& road, double x_max, RoadBuild build) {
  AggregateRoadSpec spec;
  read_aggregate_keys(road, spec, false, 100.0);
  spec.x_max = x_max;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  return build_named(road, [&] { return make_aggregate_profile(spec); });
}

std::unique_ptr<RoadProfile> make_file(const ConfigTable& road, double x_min, double x_max, RoadBuild build) {
  const std::string name = road.text("file");
  if (name.empty()) {
    road.fail("file", "must name a profile file (a CSV with columns x,z in m, or x_mm,z_mm; a laser "
                      "profilometer export; or a line laser file of one profile)");
  }
  // ISO 13473-1 spike removal suits measured texture; a made-up profile's steep steps are meant.
  const SpikeHandling spikes =
      road.choice("spikes", {"remove", "keep"}, "remove") == "keep" ? SpikeHandling::keep : SpikeHandling::remove;
  road.reject_unknown_keys();
  if (build == RoadBuild::keys_only) return nullptr;
  // Relative to the file that set the key (the case file, or a model file it includes).
  const ReferencedFile found = find_referenced_file(name, road.source_of("file"));
  road.note_referenced_file("file", found);  // listed in the summary when outside its folder
  const std::filesystem::path& path = found.path;
  return std::make_unique<FileRoad>(path, x_min, x_max, spikes);
}

}  // namespace

std::unique_ptr<RoadProfile> make_road_profile(const ConfigTable& road, double x_min, double x_max, RoadBuild build) {
  if (std::isnan(x_min) || std::isnan(x_max)) {
    throw std::invalid_argument("make_road_profile: the x range must be numbers");
  }
  // A library surface file's descriptive [about] table (name, description, mpd_m, sources, ...)
  // is for people and tools, not for building the road.
  if (const toml::node* about = road.raw("about"); about && !about->is_table()) {
    road.fail("about", "must be a table of descriptive keys ([about] name = ..., description = ...)");
  }
  // The 2-D surfaces (road_surface.hpp) vary across the road: only a tyre model with lateral
  // lines can roll over them. Named here so that a point model gets a message that says so
  // rather than an unknown type.
  if (road.contains("type")) {
    const std::string asked = road.text("type");
    if (asked == "random_surface" || asked == "surface" || asked == "profile_surface") {
      road.fail("type", "\"" + asked +
                            "\" is a 2-D road surface r(x, y): it needs a tyre model, which rolls "
                            "lateral lines over the road; point models (sdof, coupled_sdof) take a "
                            "1-D profile: \"flat\", \"sine\", \"random\", \"file\" or \"cleat\"");
    }
  }
  const std::string type = road.choice("type", {"flat", "sine", "random", "file", "cleat", "iso8608", "texture", "aggregate"});
  // A profile has no acoustics of its own (a point model radiates nothing), but the table's
  // [road.absorption] is checked and known, so that a surface file serves both kinds of model.
  (void)read_road_absorption(road);
  if (type == "flat") {
    road.reject_unknown_keys();
    return std::make_unique<FlatRoad>();
  }
  if (type == "sine") return make_sine(road);
  if (type == "cleat") return make_cleat(road);
  if (type == "random") return make_random(road, x_max, build);
  if (type == "iso8608") return make_iso8608(road, x_max, build);
  if (type == "texture") return make_texture(road, x_max, build);
  if (type == "aggregate") return make_aggregate(road, x_max, build);
  return make_file(road, x_min, x_max, build);
}

}  // namespace rollnoise
