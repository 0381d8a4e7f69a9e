#include "road/profile_analysis.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/cancellation.hpp"
#include "core/error.hpp"
#include "road/least_squares_line.hpp"

namespace rollnoise {

double detrended_skewness(const std::vector<double>& line) {
  const std::size_t n = line.size();
  if (n < 3) return 0.0;
  const LeastSquaresLine trend = least_squares_line(line);
  double m2 = 0.0, m3 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = line[i] - trend.at(i);
    m2 += r * r;
    m3 += r * r * r;
  }
  m2 /= static_cast<double>(n);
  m3 /= static_cast<double>(n);
  return m2 > 0.0 ? m3 / std::pow(m2, 1.5) : 0.0;
}

ProfileAnalysis analyse_profile(const std::vector<std::vector<double>>& lines, double spacing_m) {
  if (lines.empty()) throw std::invalid_argument("analyse_profile: no line");
  for (const auto& line : lines)
    if (line.size() != lines.front().size()) throw std::invalid_argument("analyse_profile: lines of unequal length");
  ProfileAnalysis out;
  // A road of many long lines takes seconds per pass: Ctrl-C is polled line by line.
  const CancellationToken cancel;
  double squares = 0.0;
  for (const auto& line : lines) {
    const double mean = std::accumulate(line.begin(), line.end(), 0.0) / static_cast<double>(line.size());
    for (double z : line) squares += (z - mean) * (z - mean);
  }
  out.rms_m = std::sqrt(squares / static_cast<double>(lines.size() * lines.front().size()));
  for (const auto& line : lines) out.skewness += detrended_skewness(line) / static_cast<double>(lines.size());

  // MPD needs one 100 mm segment; a shorter profile simply has none (the caller says so).
  constexpr double segment_m = 0.1;
  if (static_cast<double>(lines.front().size()) * spacing_m >= segment_m) {
    MpdResult mean{};
    for (const auto& line : lines) {
      cancel.throw_if_cancelled();
      const MpdResult one = mean_profile_depth(line, spacing_m);
      mean.mpd_m += one.mpd_m / static_cast<double>(lines.size());
      mean.segments += one.segments;
      mean.spacing_m = one.spacing_m;
    }
    mean.etd_m = 0.2e-3 + 0.8 * mean.mpd_m;  // ISO 13473-1: ETD = 0.2 mm + 0.8·MPD
    out.mpd = mean;
  }

  // Energy mean of L_tx per band over the lines (same length, so the same bands).
  for (const auto& line : lines) {
    cancel.throw_if_cancelled();
    const std::vector<TextureBand> bands = texture_spectrum(line, spacing_m);
    if (out.texture.empty()) {
      out.texture = bands;
      for (auto& b : out.texture) b.level_db = 0.0;
    }
    for (std::size_t i = 0; i < bands.size(); ++i)
      out.texture[i].level_db += std::pow(10.0, bands[i].level_db / 10.0) / static_cast<double>(lines.size());
  }
  for (auto& b : out.texture) b.level_db = 10.0 * std::log10(b.level_db);

  // Unevenness only where a line reaches the standard's band (metres of road, not a texture
  // sample): unevenness_psd says so with an InputError on "profile".
  try {
    out.unevenness = unevenness_psd(lines.front(), spacing_m);
  } catch (const InputError& e) {
    if (e.key() != "profile") throw;
  }
  return out;
}

}  // namespace rollnoise
