#include "road/record_texture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/least_squares_line.hpp"
#include "road/texture_spectrum.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};
using FftwArray = std::unique_ptr<double[], FftwFree>;

FftwArray fftw_array(std::size_t n) {
  FftwArray a(fftw_alloc_real(n));
  if (!a) throw std::bad_alloc();
  return a;
}

// The cosine series (DCT-II, FFTW's REDFT10) of a line with its least-squares line removed.
std::vector<double> detrended_cosine_modes(const std::vector<double>& line) {
  const std::size_t n = line.size();
  FftwArray z = fftw_array(n);
  FftwArray modes = fftw_array(n);
  const FftwPlan forward([&] { return fftw_plan_r2r_1d(static_cast<int>(n), z.get(), modes.get(), FFTW_REDFT10, FFTW_ESTIMATE); });
  const LeastSquaresLine trend = least_squares_line(line);
  for (std::size_t i = 0; i < n; ++i) z[i] = line[i] - trend.at(i);
  forward.execute();
  return {modes.get(), modes.get() + n};
}

constexpr double edge_factor = 1.1220184543019633;  // 10^(1/20): a band's edges from its centre
constexpr double reference_m2 = 1e-12;              // (1 µm)^2

}  // namespace

RecordTexture measure_record_texture(const std::vector<std::vector<double>>& lines, double spacing_m,
                                     const std::string& source) {
  if (lines.empty()) throw std::invalid_argument("measure_record_texture: no lines");
  if (!(spacing_m > 0.0) || !std::isfinite(spacing_m)) throw std::invalid_argument("measure_record_texture: spacing");
  RecordTexture r;
  r.spacing_m = spacing_m;
  r.lines = lines.size();
  std::size_t shortest = std::numeric_limits<std::size_t>::max();
  for (const auto& line : lines) {
    if (line.size() < 4) throw std::invalid_argument("measure_record_texture: a line has fewer than 4 samples");
    shortest = std::min(shortest, line.size());
  }
  r.shortest_line_m = spacing_m * static_cast<double>(shortest);
  for (double nominal : texture_band_nominal_wavelengths()) {
    const double centre = texture_band_centre_wavelength(nominal);
    if (centre / edge_factor >= 2.0 * spacing_m && centre * edge_factor <= r.shortest_line_m / record_band_length_factor) {
      r.nominal_m.push_back(nominal);
      r.centres_m.push_back(centre);
    }
  }
  if (r.centres_m.empty()) {
    throw InputError("", "file",
                     source + ": the record (lines of " + format_number(r.shortest_line_m) + " m at " + format_number(spacing_m) +
                         " m spacing) supports no texture band: a third-octave band (0.5 to 500 mm) is taken from a "
                         "record when its wavelengths lie between 2 × spacing and a quarter of the line's length; the "
                         "shortest band, 0.5 mm, needs a spacing of at most 0.22 mm and lines of at least 2.3 mm");
  }
  r.highest_wavenumber = edge_factor / r.centres_m.front();
  r.lowest_wavenumber = 1.0 / (edge_factor * r.centres_m.back());
  std::vector<double> band_power(r.centres_m.size(), 0.0);
  for (const auto& line : lines) {
    for (double v : line)
      if (!std::isfinite(v)) throw std::invalid_argument("measure_record_texture: a height is not finite");
    const std::size_t n = line.size();
    const double length = spacing_m * static_cast<double>(n);
    const std::vector<double> modes = detrended_cosine_modes(line);
    const double scale = 1.0 / (2.0 * static_cast<double>(n) * static_cast<double>(n));
    for (std::size_t k = 1; k < n; ++k) {
      const double wavenumber = static_cast<double>(k) / (2.0 * length);
      for (std::size_t b = 0; b < r.centres_m.size(); ++b) {
        const double centre_n = 1.0 / r.centres_m[b];
        if (wavenumber >= centre_n / edge_factor && wavenumber < centre_n * edge_factor) band_power[b] += modes[k] * modes[k] * scale;
      }
    }
  }
  r.band_passed = band_pass_lines(lines, spacing_m, r.lowest_wavenumber, r.highest_wavenumber);
  for (std::size_t b = 0; b < band_power.size(); ++b) {
    const double power = band_power[b] / static_cast<double>(lines.size());
    if (!(power > 0.0)) {
      throw InputError("", "file",
                       source + ": the record has no texture at all in the " + format_number(r.nominal_m[b] * 1e3) +
                           " mm band: a surface cannot be given its spectrum (is the profile flat or constant?)");
    }
    r.levels_db.push_back(10.0 * std::log10(power / reference_m2));
  }
  return r;
}

std::vector<std::vector<double>> band_pass_lines(const std::vector<std::vector<double>>& lines, double spacing_m,
                                                 double lowest_wavenumber, double highest_wavenumber) {
  std::vector<std::vector<double>> out;
  for (const auto& line : lines) {
    const std::size_t n = line.size();
    if (n < 4) throw std::invalid_argument("band_pass_lines: a line has fewer than 4 samples");
    const double length = spacing_m * static_cast<double>(n);
    FftwArray modes = fftw_array(n);
    FftwArray z = fftw_array(n);
    const FftwPlan inverse([&] { return fftw_plan_r2r_1d(static_cast<int>(n), modes.get(), z.get(), FFTW_REDFT01, FFTW_ESTIMATE); });
    const std::vector<double> series = detrended_cosine_modes(line);
    std::copy(series.begin(), series.end(), modes.get());
    for (std::size_t k = 0; k < n; ++k) {
      const double wavenumber = static_cast<double>(k) / (2.0 * length);
      if (!(wavenumber >= lowest_wavenumber && wavenumber < highest_wavenumber)) modes[k] = 0.0;
    }
    inverse.execute();  // REDFT01 of REDFT10 is 2N times the line
    std::vector<double> passed(n);
    for (std::size_t i = 0; i < n; ++i) passed[i] = z[i] / (2.0 * static_cast<double>(n));
    out.push_back(std::move(passed));
  }
  return out;
}

std::vector<std::vector<double>> band_pass_in_record_pieces(const std::vector<double>& line, double spacing_m,
                                                            const RecordTexture& record) {
  const auto piece = static_cast<std::size_t>(std::lround(record.shortest_line_m / spacing_m));
  if (piece < 4) throw std::invalid_argument("band_pass_in_record_pieces: the record's lines are under 4 samples of this spacing");
  std::vector<std::vector<double>> pieces;
  for (std::size_t start = 0; start + piece <= line.size(); start += piece)
    pieces.emplace_back(line.begin() + static_cast<std::ptrdiff_t>(start), line.begin() + static_cast<std::ptrdiff_t>(start + piece));
  if (pieces.empty()) throw std::invalid_argument("band_pass_in_record_pieces: the line is shorter than the record's lines");
  return band_pass_lines(pieces, spacing_m, record.lowest_wavenumber, record.highest_wavenumber);
}

}  // namespace rollnoise
