#include "road/profile_surface_road.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/referenced_file.hpp"
#include "core/fftw_plan.hpp"
#include "road/profile_file.hpp"
#include "road/spectral_synthesis.hpp"
#include "road/texture_band_psd.hpp"
#include "road/texture_road.hpp"
#include "road/translation_calibration.hpp"

namespace rollnoise {
namespace {

// Below this longest wavelength a tyre misses much of what excites it (10 to 100 mm and more).
constexpr double tyre_wavelength_m = 0.1;
constexpr std::uint64_t calibration_seed = 1;

// The measured lines of every file `file` names (a string or a list of strings), at one spacing.
struct Record {
  std::vector<std::vector<double>> lines;
  double spacing = 0.0;
  std::string names;  // for messages
};

// The files `file` names (a string or a list of strings), found relative to the file that sets it.
std::vector<std::filesystem::path> record_files(const ConfigTable& road) {
  const toml::node* node = road.raw("file");
  const std::string files = "a profile file (a CSV of x,z or x,z_1..z_n; a laser profilometer export; a line laser "
                            "file; an HDF5 height map), or a list of such files measured at the same spacing";
  const std::string allowed = "must name " + files;
  if (node == nullptr) road.fail("file", "is required: the measured lines the surface is made from, " + files);
  std::vector<std::string> names;
  if (const auto* one = node->as_string()) {
    names.push_back(one->get());
  } else if (const auto* list = node->as_array()) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto* item = list->get(i)->as_string();
      if (item == nullptr) road.fail("file", "item " + std::to_string(i + 1) + " is not a string: the list " + allowed);
      names.push_back(item->get());
    }
  }
  if (names.empty()) road.fail("file", allowed);
  std::vector<std::filesystem::path> paths;
  for (const std::string& name : names) {
    if (name.empty()) road.fail("file", allowed);
    const ReferencedFile found = find_referenced_file(name, road.source_of("file"));
    road.note_referenced_file("file", found);
    paths.push_back(found.path);
  }
  return paths;
}

// The measured lines of those files, at one spacing.
Record read_record(const ConfigTable& road, const std::vector<std::filesystem::path>& paths) {
  Record record;
  for (const std::filesystem::path& path : paths) {
    LoadedProfile p = load_profile_file(path);
    if (record.lines.empty()) {
      record.spacing = p.spacing_m;
    } else if (std::abs(p.spacing_m / record.spacing - 1.0) > 1e-6) {
      road.fail("file", "the files are sampled at different spacings (" + format_number(record.spacing) + " m and " +
                            format_number(p.spacing_m) + " m in " + path.string() +
                            "): list only records measured at one spacing");
    }
    for (auto& line : p.z_lines) record.lines.push_back(std::move(line));
    record.names += (record.names.empty() ? "" : ", ") + path.filename().string();
  }
  return record;
}

// One period of a line of the road (texture_road.hpp, texture_waves.hpp) for calibrate_translation:
// fixed amplitudes, random phases (a fixed seed), the line density of the bands, or for an
// isotropic surface the density its lines have (TextureBandPsd::realisable_line_density),
// standardised and mapped through the marginal.
TranslatedLineMaker translated_line_maker(const std::vector<double>& centres, double spacing,
                                          std::function<double(double)> marginal, bool isotropic) {
  const auto n = fft_friendly_size(static_cast<std::size_t>(std::ceil(translation_calibration_length(centres, spacing) / spacing)));
  return [centres, spacing, marginal = std::move(marginal), isotropic, n](const std::vector<double>& levels) {
    const TextureBandPsd psd(centres, levels);
    const double period = spacing * static_cast<double>(n);
    std::vector<double> line = synthesise_periodic_profile(
        n, spacing, calibration_seed,
        [&](double wavenumber) {
          return spectral_amplitude_1d(isotropic ? psd.realisable_line_density(wavenumber) : psd.line_density(wavenumber), period);
        },
        SynthesisAmplitudes::fixed);
    map_period_through_marginal(line, marginal);
    return line;
  };
}

// The band levels an isotropic surface's lines have when its 2-D spectrum is the Abel inverse of
// `levels` clipped at 0 (TextureBandPsd::realisable_line_density): `levels` wherever the line
// spectrum falls towards longer wavelengths by no more than about 1 dB per band, more in the
// bands just longer than a steeper fall (the projection of the shorter bands' annuli).
std::vector<double> isotropic_levels(const std::vector<double>& centres, const std::vector<double>& levels) {
  const TextureBandPsd psd(centres, levels);
  constexpr int steps = 400;  // midpoint rule within each band: the density is smooth there
  std::vector<double> out;
  for (double centre : centres) {
    const double low = 1.0 / (centre * std::pow(10.0, 0.05));
    const double high = std::pow(10.0, 0.05) / centre;
    double power = 0.0;
    for (int i = 0; i < steps; ++i)
      power += psd.realisable_line_density(low + (high - low) * (i + 0.5) / steps) * (high - low) / steps;
    out.push_back(10.0 * std::log10(power / 1e-12));
  }
  return out;
}

std::vector<std::string> surface_warnings(const RecordTexture& record) {
  std::vector<std::string> warnings;
  const double longest = record.centres_m.back() * std::pow(10.0, 0.05);
  if (longest < tyre_wavelength_m) {
    warnings.push_back("[road] profile_surface: the record's lines (" + format_number(std::round(record.shortest_line_m * 1e3) / 1e3) +
                       " m) support texture wavelengths up to " + format_number(std::round(longest * 1e4) / 10.0) +
                       " mm only; the surface has none longer, where a tyre is excited most (up to 100 mm and "
                       "more): lines of at least " + format_number(std::ceil(record_band_length_factor * tyre_wavelength_m * 1.1220184543 * 100.0) / 100.0) +
                       " m give the bands to 100 mm");
  }
  return warnings;
}

}  // namespace

ProfileSurfaceRoad::ProfileSurfaceRoad(std::unique_ptr<RoadSurface> surface, RecordTexture record,
                                       HeightMoments record_moments, std::vector<double> levels_db,
                                       std::vector<double> gaussian_levels_db, double spacing,
                                       std::vector<std::string> warnings)
    : surface_(std::move(surface)),
      record_(std::move(record)),
      record_moments_(record_moments),
      levels_db_(std::move(levels_db)),
      gaussian_levels_db_(std::move(gaussian_levels_db)),
      spacing_(spacing),
      warnings_(std::move(warnings)) {
  if (!surface_) throw std::invalid_argument("ProfileSurfaceRoad: no surface");
}

std::unique_ptr<ProfileSurfaceRoad> make_profile_surface(const ConfigTable& road, double x_max, double half_width) {
  TextureRoadSpec spec;
  spec.seed = static_cast<std::uint64_t>(road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  spec.length = road.positive("length", 20.0);
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  if (road.contains("lead_in")) spec.lead_in = road.non_negative("lead_in");
  spec.width = road.positive("width", 0.5);
  const std::string a = road.choice("anisotropy", {"isotropic", "transverse", "longitudinal"}, "isotropic");
  spec.anisotropy = a == "transverse"     ? TextureRoadSpec::Anisotropy::transverse
                    : a == "longitudinal" ? TextureRoadSpec::Anisotropy::longitudinal
                                          : TextureRoadSpec::Anisotropy::isotropic;
  spec.x_max = x_max;
  spec.half_width = half_width;
  const std::vector<std::filesystem::path> files = record_files(road);
  road.reject_unknown_keys();
  Record data = read_record(road, files);
  try {
    RecordTexture record = measure_record_texture(data.lines, data.spacing, data.names);
    std::vector<double> pooled;
    for (const auto& line : record.band_passed) pooled.insert(pooled.end(), line.begin(), line.end());
    const auto distribution = std::make_shared<const HeightDistribution>(std::move(pooled));
    spec.marginal = [distribution](double u) { return distribution->from_standard_normal(u); };
    spec.wavelengths = record.centres_m;
    spec.levels = record.levels_db;
    const double spacing = texture_sample_spacing(spec);
    const bool isotropic = spec.anisotropy == TextureRoadSpec::Anisotropy::isotropic;
    std::vector<double> surface_levels = isotropic ? isotropic_levels(record.centres_m, record.levels_db) : record.levels_db;
    const TranslationSpectrum gaussian =
        calibrate_translation(record.centres_m, surface_levels, spacing,
                              translated_line_maker(record.centres_m, spacing, spec.marginal,
                                                    isotropic));
    spec.levels = gaussian.gaussian_levels_db;
    spec.marginal = [distribution, scale = gaussian.scale](double u) { return scale * distribution->from_standard_normal(u); };
    std::vector<std::string> warnings = surface_warnings(record);
    const HeightMoments moments = distribution->moments();
    return std::make_unique<ProfileSurfaceRoad>(make_rolling_texture_surface(spec), std::move(record), moments,
                                                std::move(surface_levels), gaussian.gaussian_levels_db, spacing,
                                                std::move(warnings));
  } catch (const InputError& e) {
    if (!e.source().empty() || e.key().empty()) throw;
    road.fail(e.key(), e.problem());
  }
}

}  // namespace rollnoise
