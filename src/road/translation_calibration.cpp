#include "road/translation_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

#include "road/texture_spectrum.hpp"

namespace rollnoise {
namespace {

constexpr int max_iterations = 10;
constexpr double converged_db = 0.05;
// The line's length in longest band wavelengths: long enough that the map's scatter between
// realisations (its intermodulation depends on the phases) is small in every band, so that the
// levels are not fitted to one realisation; at most max_samples samples.
constexpr double longest_wavelengths = 400.0;
constexpr double max_samples = 1048576.0;

}  // namespace

double translation_calibration_length(std::span<const double> centres_m, double spacing_m) {
  if (centres_m.empty()) throw std::invalid_argument("translation_calibration_length: no band");
  return std::min(std::max(longest_wavelengths * centres_m.back() * std::pow(10.0, 0.05), 4096.0 * spacing_m), max_samples * spacing_m);
}

TranslationSpectrum calibrate_translation(std::span<const double> centres_m, std::span<const double> target_db,
                                          double spacing_m, const TranslatedLineMaker& make_line) {
  if (centres_m.empty() || centres_m.size() != target_db.size() || !make_line)
    throw std::invalid_argument("calibrate_translation: one target level per band, and a line maker");
  TranslationSpectrum result;
  result.gaussian_levels_db.assign(target_db.begin(), target_db.end());
  std::vector<double> miss(centres_m.size(), 0.0);
  for (result.iterations = 1;; ++result.iterations) {
    const std::vector<double> h = make_line(result.gaussian_levels_db);
    const std::vector<TextureBand> bands = texture_spectrum(h, spacing_m);
    std::vector<double> level(centres_m.size());
    double made = 0.0, wanted = 0.0;
    for (std::size_t b = 0; b < centres_m.size(); ++b) {
      const auto found = std::find_if(bands.begin(), bands.end(), [&](const TextureBand& t) {
        return std::abs(t.centre_wavelength_m / centres_m[b] - 1.0) < 1e-6;
      });
      if (found == bands.end() || !std::isfinite(found->level_db))
        throw std::logic_error("calibrate_translation: the line does not resolve a band");
      level[b] = found->level_db;
      made += std::pow(10.0, level[b] / 10.0);
      wanted += std::pow(10.0, target_db[b] / 10.0);
    }
    // The map keeps the record's variance, some of which it moves outside the bands: the heights
    // are scaled so that the bands hold the record's (the moments do not change with a scale).
    result.scale = std::sqrt(wanted / made);
    result.worst_miss_db = 0.0;
    for (std::size_t b = 0; b < centres_m.size(); ++b) {
      miss[b] = target_db[b] - (level[b] + 20.0 * std::log10(result.scale));
      result.worst_miss_db = std::max(result.worst_miss_db, std::abs(miss[b]));
    }
    if (result.worst_miss_db < converged_db || result.iterations == max_iterations) break;
    for (std::size_t b = 0; b < miss.size(); ++b) result.gaussian_levels_db[b] += miss[b];
  }
  return result;
}

}  // namespace rollnoise
