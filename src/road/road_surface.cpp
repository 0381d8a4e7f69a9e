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
#include "road/height_map_surface.hpp"
#include "road/random_surface.hpp"

namespace rollnoise {

ProfileSurface::ProfileSurface(std::unique_ptr<RoadProfile> profile) : profile_(std::move(profile)) {
  if (!profile_) throw std::invalid_argument("ProfileSurface: no profile");
}

std::string ProfileSurface::type() const { return profile_->type(); }

double ProfileSurface::height(double x, double /*y*/) const { return profile_->height(x); }

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

std::unique_ptr<RoadSurface> make_random_surface(const ConfigTable& road, double x_max, double half_width) {
  RandomSurfaceSpec spec;
  spec.std_dev = road.positive("std_dev");
  const bool has_lc = road.contains("correlation_length");
  const bool has_min = road.contains("min_wavelength");
  const bool has_max = road.contains("max_wavelength");
  if (has_lc && (has_min || has_max)) {
    road.fail("correlation_length",
              "give either correlation_length (Gaussian autocorrelation) or min_wavelength and "
              "max_wavelength (band-limited spectrum), not both");
  }
  if (has_lc) {
    spec.spectrum = RandomSurfaceSpec::Spectrum::gaussian;
    spec.correlation_length = road.positive("correlation_length");
  } else if (has_min || has_max) {
    if (!has_min) road.fail("min_wavelength", "is required with max_wavelength (band-limited spectrum)");
    if (!has_max) road.fail("max_wavelength", "is required with min_wavelength (band-limited spectrum)");
    spec.spectrum = RandomSurfaceSpec::Spectrum::band;
    spec.min_wavelength = road.positive("min_wavelength");
    spec.max_wavelength = road.positive("max_wavelength");
  } else {
    road.fail("correlation_length",
              "is required, or else min_wavelength and max_wavelength (band-limited spectrum)");
  }
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  if (road.contains("lead_in")) spec.lead_in = road.non_negative("lead_in");
  spec.seed = static_cast<std::uint64_t>(
      road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  // A fixed patch of road, so that runs of different duration and tyres of different width on
  // the same case see the same surface.
  spec.length = road.positive("length", 20.0);
  spec.width = road.positive("width", 0.5);
  spec.x_max = x_max;
  spec.half_width = half_width;
  road.reject_unknown_keys();
  return build_named(road, [&] { return std::make_unique<RandomSurface>(spec); });
}

std::unique_ptr<RoadSurface> make_height_map(const ConfigTable& road, double x_min, double x_max,
                                             double half_width) {
  const std::string name = road.text("file");
  if (name.empty()) road.fail("file", "must name a CSV file (columns x,y,z in m, one row per grid point)");
  road.reject_unknown_keys();
  // Relative to the file that set the key (the case file, or a model file it includes).
  const auto path = resolve_referenced_file(name, road.source_of("file"));
  return std::make_unique<HeightMapSurface>(path, x_min, x_max, half_width);
}

}  // namespace

std::unique_ptr<RoadSurface> make_road_surface(const ConfigTable& road, double x_min, double x_max,
                                               double half_width) {
  if (std::isnan(x_min) || std::isnan(x_max)) {
    throw std::invalid_argument("make_road_surface: the x range must be numbers");
  }
  if (!(half_width >= 0.0) || !std::isfinite(half_width)) {
    throw std::invalid_argument("make_road_surface: half_width must be finite and >= 0");
  }
  const std::string type = road.choice(
      "type", {"flat", "sine", "random", "file", "cleat", "random_surface", "surface"});
  if (type == "random_surface") return make_random_surface(road, x_max, half_width);
  if (type == "surface") return make_height_map(road, x_min, x_max, half_width);
  return std::make_unique<ProfileSurface>(make_road_profile(road, x_min, x_max));
}

}  // namespace rollnoise
