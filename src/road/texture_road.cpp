// The texture road (texture_road.hpp): its keys and checks, the 1-D profile and the 2-D map.
#include "road/texture_road.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <fftw3.h>
#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/spectral_synthesis.hpp"
#include "road/texture_band_psd.hpp"
#include "road/texture_spectrum.hpp"
#include "road/texture_waves.hpp"

namespace rollnoise {
namespace {

[[noreturn]] void throw_bad(const char* key, const std::string& problem) {
  throw InputError("", key, problem);  // the factory names the file and the section
}

// A TOML array of numbers (integers or floats; nan and inf pass, the checks name them).
std::vector<double> read_number_list(const ConfigTable& road, const char* key) {
  const toml::node* node = road.raw(key);
  if (node == nullptr) road.fail(key, "is required: a list of numbers, one per texture band");
  const toml::array* list = node->as_array();
  if (list == nullptr) road.fail(key, "must be a list of numbers, such as [0.004, 0.005, 0.0063]");
  std::vector<double> values;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& item = *list->get(i);
    if (const auto* f = item.as_floating_point()) {
      values.push_back(f->get());
    } else if (const auto* n = item.as_integer()) {
      values.push_back(static_cast<double>(n->get()));
    } else {
      road.fail(key, "item " + std::to_string(i + 1) + " is not a number");
    }
  }
  return values;
}

// Nominal centres of the supported band set are within 1.6 % of the exact ones.
constexpr double centre_tolerance = 0.02;
constexpr double shortest_band = 0.5e-3;  // m, nominal
constexpr double longest_band = 0.5;      // m, nominal

}  // namespace

void read_texture_keys(const ConfigTable& road, TextureRoadSpec& spec, bool surface, double default_length) {
  spec.wavelengths = read_number_list(road, "wavelengths");
  spec.levels = read_number_list(road, "levels");
  spec.seed = static_cast<std::uint64_t>(road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  spec.length = road.positive("length", default_length);
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  if (road.contains("lead_in")) spec.lead_in = road.non_negative("lead_in");
  if (surface) {
    spec.width = road.positive("width", 0.5);
    const std::string a = road.choice("anisotropy", {"isotropic", "transverse", "longitudinal"}, "isotropic");
    spec.anisotropy = a == "transverse"     ? TextureRoadSpec::Anisotropy::transverse
                      : a == "longitudinal" ? TextureRoadSpec::Anisotropy::longitudinal
                                            : TextureRoadSpec::Anisotropy::isotropic;
  }
}

std::vector<double> checked_texture_band_centres(const TextureRoadSpec& spec) {
  if (spec.wavelengths.empty()) throw_bad("wavelengths", "must list at least one band centre wavelength (m)");
  if (spec.levels.size() != spec.wavelengths.size()) {
    throw_bad("levels", "has " + std::to_string(spec.levels.size()) + " values but wavelengths has " +
                            std::to_string(spec.wavelengths.size()) + ": give one level (dB re 1 µm) per band");
  }
  for (std::size_t i = 0; i < spec.levels.size(); ++i) {
    if (!std::isfinite(spec.levels[i])) {
      throw_bad("levels", "item " + std::to_string(i + 1) + " is " + format_number(spec.levels[i]) +
                              ": levels must be finite numbers (dB re 1 µm)");
    }
  }
  const std::vector<double> nominal = texture_band_nominal_wavelengths(shortest_band, longest_band);
  std::vector<double> centres;
  for (std::size_t i = 0; i < spec.wavelengths.size(); ++i) {
    const double w = spec.wavelengths[i];
    const std::string item = "item " + std::to_string(i + 1) + " (" + format_number(w) + " m)";
    if (!std::isfinite(w) || !(w >= shortest_band * (1.0 - centre_tolerance)) ||
        !(w <= longest_band * (1.0 + centre_tolerance))) {
      throw_bad("wavelengths", item + " is outside the supported ISO 13473-4 band set: third-octave band "
                                      "centres from 0.5 mm to 500 mm (0.0005 to 0.5 m)");
    }
    double centre = 0.0;
    for (double n : nominal) {
      const double exact = texture_band_centre_wavelength(n);
      if (std::abs(w / exact - 1.0) <= centre_tolerance) centre = exact;
    }
    if (centre == 0.0) {
      throw_bad("wavelengths", item + " is not a third-octave band centre (nominal 0.5, 0.63, 0.8, 1, 1.25, "
                                      "1.6, 2, 2.5, 3.15, 4, 5, 6.3, 8, 10 … 500 mm, or the exact base-10 "
                                      "centres 10^(k/10) mm)");
    }
    if (!centres.empty() && !(centre > centres.back() * (1.0 + centre_tolerance))) {
      throw_bad("wavelengths", "must be increasing, one entry per band: " + item + " does not follow " +
                                   format_number(spec.wavelengths[i - 1]) + " m");
    }
    centres.push_back(centre);
  }
  return centres;
}

namespace {

// Checked scales shared by the profile and the surface.
struct TextureScales {
  double spacing = 0.0;
  double lead_in = 0.0;
  double longest = 0.0;  // the longest band's upper edge wavelength (m)
};

TextureScales check_scales(const TextureRoadSpec& spec, const TextureBandPsd& psd) {
  TextureScales s;
  const double shortest = psd.shortest_wavelength();
  s.longest = psd.longest_wavelength();
  s.spacing = spec.sample_spacing.value_or(shortest / 4.0);
  if (!(s.spacing > 0.0) || !std::isfinite(s.spacing)) {
    throw_bad("sample_spacing", "must be a finite number > 0 (got " + format_number(s.spacing) + ")");
  }
  if (s.spacing > shortest / 2.0) {
    throw_bad("sample_spacing", "must be at most half the lower edge wavelength of the shortest band, " +
                                    format_number(shortest / 2.0) + " m, to resolve that band (got " +
                                    format_number(s.spacing) + ")");
  }
  s.lead_in = spec.lead_in.value_or(s.longest);
  if (!(s.lead_in >= 0.0) || !std::isfinite(s.lead_in)) {
    throw_bad("lead_in", "must be a finite number >= 0 (got " + format_number(s.lead_in) + ")");
  }
  if (!(spec.length > 0.0) || !std::isfinite(spec.length)) {
    throw_bad("length", "must be a finite number > 0 (got " + format_number(spec.length) + ")");
  }
  return s;
}

}  // namespace

namespace {

// The period (samples) of a road whose record ends at sample `last`: `last` itself when that is
// at least 8 longest wavelengths (enough lines in the longest band), else 8 longest wavelengths.
std::size_t texture_period(const TextureScales& s, double last) {
  const double needed = std::max(last, std::ceil(8.0 * s.longest / s.spacing));
  synthesis_grid_size(needed, needed);
  return static_cast<std::size_t>(needed);
}

// Samples 0 .. last of a profile with the band levels (spacing s.spacing, seed), fixed amplitudes
// and random phases (SynthesisAmplitudes::fixed) on the period texture_period(): when that is
// `last`, the record [0, last·spacing] is one period (sample `last` repeats sample 0), so its
// periodogram is the target in every band, for every seed; else the period is cut to last + 1.
// With a marginal (TextureRoadSpec::marginal) each sample of the period is mapped through it.
std::vector<double> texture_line(const TextureBandPsd& psd, const TextureScales& s, double last, std::uint64_t seed,
                                 const std::function<double(double)>& marginal) {
  const std::size_t n = texture_period(s, last);
  const double period = s.spacing * static_cast<double>(n);
  std::vector<double> r = synthesise_periodic_profile(
      n, s.spacing, seed, [&](double wavenumber) { return spectral_amplitude_1d(psd.line_density(wavenumber), period); },
      SynthesisAmplitudes::fixed);
  if (marginal) map_period_through_marginal(r, marginal);
  const auto count = static_cast<std::size_t>(last) + 1;
  if (r.size() < count) r.push_back(r.front());  // the period's end: the first sample again
  r.resize(count);
  return r;
}

// A surface made of one texture line: along x (transverse tining, r = w(x) p(x)) or across
// (longitudinal tining, r = w(x) p(y + width/2)); memory of one line.
class TextureLineSurface final : public RoadSurface {
 public:
  TextureLineSurface(SampledProfile line, bool along_x, double half_width, double lead_in)
      : line_(std::move(line)), along_x_(along_x), half_width_(half_width), lead_in_(lead_in) {}
  std::string type() const override { return "texture"; }
  double height(double x, double y) const override {
    if (x < 0.0) return 0.0;
    return lead_in_window(x, lead_in_) * (along_x_ ? line_.height(x) : line_.height(y + half_width_));
  }
  std::optional<double> sample_spacing() const override { return line_.spacing(); }

 private:
  SampledProfile line_;
  bool along_x_;
  double half_width_;
  double lead_in_;
};

struct CheckedSurface {
  TextureBandPsd psd;
  TextureScales scales;
};

CheckedSurface check_surface(const TextureRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_texture_surface: x_max must be finite");
  if (!(spec.half_width >= 0.0) || !std::isfinite(spec.half_width)) {
    throw std::invalid_argument("make_texture_surface: half_width must be finite and >= 0");
  }
  const std::vector<double> centres = checked_texture_band_centres(spec);
  TextureBandPsd psd(centres, spec.levels);
  const TextureScales s = check_scales(spec, psd);
  if (!(spec.width > 0.0) || !std::isfinite(spec.width)) {
    throw_bad("width", "must be a finite number > 0 (got " + format_number(spec.width) + ")");
  }
  if (spec.half_width > spec.width / 2.0) {
    throw_bad("width", "the surface is " + format_number(spec.width) +
                           " m wide (y from -width/2 to width/2), but the tyre's contact grid reaches |y| = " +
                           format_number(spec.half_width) + " m; set width to at least " +
                           format_number(2.0 * spec.half_width) + " m");
  }
  return {std::move(psd), s};
}

// The anisotropic surfaces: one line along x over the road, or across over the width.
std::unique_ptr<TextureLineSurface> make_line_surface(const TextureRoadSpec& spec, const CheckedSurface& c) {
  const double h = c.scales.spacing;
  const bool along_x = spec.anisotropy == TextureRoadSpec::Anisotropy::transverse;
  const double half_y = std::max(1.0, std::ceil(spec.width / 2.0 / h));
  const double last = along_x ? std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / h)) : 2.0 * half_y;
  SampledProfile line("texture", h, texture_line(c.psd, c.scales, last, spec.seed, spec.marginal));
  return std::make_unique<TextureLineSurface>(std::move(line), along_x, h * half_y, c.scales.lead_in);
}

}  // namespace

std::unique_ptr<SampledProfile> make_texture_profile(const TextureRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_texture_profile: x_max must be finite");
  const std::vector<double> centres = checked_texture_band_centres(spec);
  const TextureBandPsd psd(centres, spec.levels);
  const TextureScales s = check_scales(spec, psd);
  const double last = std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / s.spacing));
  std::vector<double> r = texture_line(psd, s, last, spec.seed, spec.marginal);
  for (std::size_t j = 0; j < r.size(); ++j) r[j] *= lead_in_window(s.spacing * static_cast<double>(j), s.lead_in);
  return std::make_unique<SampledProfile>("texture", s.spacing, std::move(r));
}

double texture_sample_spacing(const TextureRoadSpec& spec) {
  const std::vector<double> centres = checked_texture_band_centres(spec);
  return check_scales(spec, TextureBandPsd(centres, spec.levels)).spacing;
}

void map_period_through_marginal(std::vector<double>& period, const std::function<double(double)>& marginal) {
  double square = 0.0;  // the mean is 0: no mode at n = 0
  for (double v : period) square += v * v;
  const double rms = std::sqrt(square / static_cast<double>(period.size()));
  for (double& v : period) v = marginal(v / rms);
}

std::unique_ptr<RoadSurface> make_rolling_texture_surface(const TextureRoadSpec& spec) {
  const CheckedSurface c = check_surface(spec);
  if (spec.anisotropy != TextureRoadSpec::Anisotropy::isotropic) return make_line_surface(spec, c);
  const double last = std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / c.scales.spacing));
  return std::make_unique<TextureWaveSurface>(c.psd, c.scales.spacing, texture_period(c.scales, last), spec.seed,
                                              c.scales.lead_in, spec.marginal);
}

std::unique_ptr<SampledSurface> make_texture_surface(const TextureRoadSpec& spec) {
  const CheckedSurface c = check_surface(spec);
  const double h = c.scales.spacing;
  const double last_x = std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / h));
  const auto half_y = static_cast<std::size_t>(std::max(1.0, std::ceil(spec.width / 2.0 / h)));
  const auto x_count = static_cast<std::size_t>(last_x) + 1;
  const std::size_t y_count = 2 * half_y + 1;
  if (!(static_cast<double>(x_count) * static_cast<double>(y_count) <= static_cast<double>(max_synthesis_points))) {
    throw_bad("sample_spacing", "the map of " + format_number(static_cast<double>(x_count) * static_cast<double>(y_count)) +
                                    " points is more than the limit of 2^26; a tyre run reads the road line by line, but a whole "
                                    "map must fit: use a larger sample_spacing or a shorter length (or a smaller width)");
  }
  std::vector<double> samples(x_count * y_count);
  if (spec.anisotropy != TextureRoadSpec::Anisotropy::isotropic) {
    const auto line = make_line_surface(spec, c);
    for (std::size_t i = 0; i < x_count; ++i)
      for (std::size_t j = 0; j < y_count; ++j)
        samples[i * y_count + j] = line->height(h * static_cast<double>(i), h * (static_cast<double>(j) - static_cast<double>(half_y)));
    return std::make_unique<SampledSurface>("texture", h, x_count, y_count, std::move(samples));
  }
  const TextureWaveSurface waves(c.psd, h, texture_period(c.scales, last_x), spec.seed, c.scales.lead_in, spec.marginal);
  for (std::size_t j = 0; j < y_count; ++j)
    for (std::size_t i = 0; i < x_count; ++i)
      samples[i * y_count + j] = waves.sample(i, static_cast<long>(j) - static_cast<long>(half_y));
  return std::make_unique<SampledSurface>("texture", h, x_count, y_count, std::move(samples));
}

}  // namespace rollnoise
