#include "road/profile_surface_road.hpp"

#include <algorithm>
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
                                          std::function<double(double)> marginal, bool isotropic,
                                          std::uint64_t seed = calibration_seed) {
  const auto n = fft_friendly_size(static_cast<std::size_t>(std::ceil(translation_calibration_length(centres, spacing) / spacing)));
  return [centres, spacing, marginal = std::move(marginal), isotropic, n, seed](const std::vector<double>& levels) {
    const TextureBandPsd psd(centres, levels);
    const double period = spacing * static_cast<double>(n);
    std::vector<double> line = synthesise_periodic_profile(
        n, spacing, seed,
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

// The map and the Gaussian spectrum of the surface (step 3 of the method). The map starts as the
// record's band-limited distribution Q. The translated lines also hold, beside the bands, the
// harmonics the map makes, and taking them away (as the record's bands were taken) pulls the
// distribution towards the Gaussian: for the CAPTIF fine asphalt the kurtosis within the bands
// falls from 4.69 to 4.42. So, as IAAFT alternates its spectrum and its rank order
// (Schreiber & Schmitz 1996), the map's quantiles are corrected by what the band-passed line
// misses, z_i <- z_i + (q_i - h_i) / s at each plotting position, and the spectrum recalibrated,
// until the band-passed lines' skewness and kurtosis are the record's within 0.03 (one correction
// for the fine asphalt: 4.71). The lines are analysed in pieces as long as the record's
// (band_pass_in_record_pieces), as the record was.
struct Translation {
  std::shared_ptr<const HeightDistribution> map;
  TranslationSpectrum gaussian;
};

// `pooled`: the record's band-passed heights, all lines; `wanted`: their moments.
Translation calibrate_map_and_spectrum(const RecordTexture& record, std::vector<double> pooled, const HeightMoments& wanted,
                                       const std::vector<double>& surface_levels, double spacing, bool isotropic) {
  std::vector<double> target = std::move(pooled);
  std::sort(target.begin(), target.end());
  constexpr int rounds = 4;
  constexpr double converged = 0.03;   // skewness and kurtosis
  std::vector<double> map_heights = target;
  Translation best;
  double best_miss = std::numeric_limits<double>::infinity();
  for (int round = 0; round < rounds; ++round) {
    auto map = std::make_shared<const HeightDistribution>(map_heights);
    const auto marginal = [map](double u) { return map->from_standard_normal(u); };
    const TranslatedLineMaker maker = translated_line_maker(record.centres_m, spacing, marginal, isotropic);
    TranslationSpectrum gaussian = calibrate_translation(record.centres_m, surface_levels, spacing, maker);
    // The distribution the lines have, from several realisations (about 2^20 heights): the
    // kurtosis of one 30 m line of the fine asphalt scatters by 0.1 to 0.2.
    std::vector<double> pieces;
    const auto add_pieces = [&](std::vector<double> line) {
      for (double& v : line) v *= gaussian.scale;
      for (const auto& piece : band_pass_in_record_pieces(line, spacing, record)) pieces.insert(pieces.end(), piece.begin(), piece.end());
      return line.size();
    };
    const std::size_t length = add_pieces(maker(gaussian.gaussian_levels_db));
    const std::uint64_t lines = std::clamp<std::uint64_t>((std::uint64_t{1} << 20) / length, 1, 8);
    for (std::uint64_t seed = calibration_seed + 1; seed < calibration_seed + lines; ++seed)
      add_pieces(translated_line_maker(record.centres_m, spacing, marginal, isotropic, seed)(gaussian.gaussian_levels_db));
    const HeightDistribution made(std::move(pieces));
    const double miss = std::max(std::abs(made.moments().skewness - wanted.skewness),
                                 std::abs(made.moments().kurtosis - wanted.kurtosis));
    const double scale = gaussian.scale;
    if (miss < best_miss) {
      best_miss = miss;
      best = {map, std::move(gaussian)};
    }
    if (miss < converged || round + 1 == rounds) break;
    const double n = static_cast<double>(map_heights.size());
    for (std::size_t i = 0; i < map_heights.size(); ++i) {
      const double p = (static_cast<double>(i) + 0.5) / n;
      map_heights[i] += (target[i] - made.quantile(p)) / scale;
    }
    std::sort(map_heights.begin(), map_heights.end());
  }
  return best;
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

std::unique_ptr<ProfileSurfaceRoad> make_profile_surface(const ConfigTable& road, double x_max, double half_width,
                                                         RoadBuild build) {
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
  if (build == RoadBuild::keys_only) return nullptr;
  Record data = read_record(road, files);
  try {
    RecordTexture record = measure_record_texture(data.lines, data.spacing, data.names);
    spec.wavelengths = record.centres_m;
    spec.levels = record.levels_db;
    const double spacing = texture_sample_spacing(spec);
    const bool isotropic = spec.anisotropy == TextureRoadSpec::Anisotropy::isotropic;
    std::vector<double> surface_levels = isotropic ? isotropic_levels(record.centres_m, record.levels_db) : record.levels_db;
    std::vector<double> pooled;
    for (const auto& line : record.band_passed) pooled.insert(pooled.end(), line.begin(), line.end());
    const HeightMoments moments = height_moments(pooled);
    const Translation translation =
        calibrate_map_and_spectrum(record, std::move(pooled), moments, surface_levels, spacing, isotropic);
    const TranslationSpectrum& gaussian = translation.gaussian;
    spec.levels = gaussian.gaussian_levels_db;
    spec.marginal = [map = translation.map, scale = gaussian.scale](double u) { return scale * map->from_standard_normal(u); };
    std::vector<std::string> warnings = surface_warnings(record);
    return std::make_unique<ProfileSurfaceRoad>(make_rolling_texture_surface(spec), std::move(record), moments,
                                                std::move(surface_levels), gaussian.gaussian_levels_db, spacing,
                                                std::move(warnings));
  } catch (const InputError& e) {
    if (!e.source().empty() || e.key().empty()) throw;
    road.fail(e.key(), e.problem());
  }
}

}  // namespace rollnoise
