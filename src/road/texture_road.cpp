// The texture road (texture_road.hpp): its keys and checks, the 1-D profile and the 2-D map.
#include "road/texture_road.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

std::unique_ptr<SampledProfile> make_texture_profile(const TextureRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_texture_profile: x_max must be finite");
  const std::vector<double> centres = checked_texture_band_centres(spec);
  const TextureBandPsd psd(centres, spec.levels);
  const TextureScales s = check_scales(spec, psd);

  const double cover = std::max(spec.length, spec.x_max);
  const double last = std::max(1.0, std::ceil(cover / s.spacing));
  const double needed = std::max(last + 1.0 + std::ceil(2.0 * s.longest / s.spacing), std::ceil(8.0 * s.longest / s.spacing));
  const std::size_t n = synthesis_grid_size(needed, needed);
  const double period = s.spacing * static_cast<double>(n);
  std::vector<double> r = synthesise_periodic_profile(
      n, s.spacing, spec.seed, [&](double wavenumber) { return spectral_amplitude_1d(psd.line_density(wavenumber), period); });
  r.resize(static_cast<std::size_t>(last) + 1);
  for (std::size_t j = 0; j < r.size(); ++j) r[j] *= lead_in_window(s.spacing * static_cast<double>(j), s.lead_in);
  return std::make_unique<SampledProfile>("texture", s.spacing, std::move(r));
}

namespace {

struct FftwFree {
  void operator()(double* p) const noexcept { fftw_free(p); }
};

}  // namespace

std::unique_ptr<SampledSurface> make_texture_surface(const TextureRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_texture_surface: x_max must be finite");
  if (!(spec.half_width >= 0.0) || !std::isfinite(spec.half_width)) {
    throw std::invalid_argument("make_texture_surface: half_width must be finite and >= 0");
  }
  const std::vector<double> centres = checked_texture_band_centres(spec);
  const TextureBandPsd psd(centres, spec.levels);
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
  const double h = s.spacing;
  const double last_x = std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / h));
  const double half_y = std::max(1.0, std::ceil(spec.width / 2.0 / h));
  const auto x_count = static_cast<std::size_t>(last_x) + 1;
  const auto y_count = 2 * static_cast<std::size_t>(half_y) + 1;
  const double margin = std::ceil(2.0 * s.longest / h);
  const double min_points = std::ceil(8.0 * s.longest / h);
  const double needed_x = std::max(last_x + 1.0 + margin, min_points);
  const double needed_y = std::max(2.0 * half_y + 1.0 + margin, min_points);
  std::vector<double> samples(x_count * y_count);

  if (spec.anisotropy != TextureRoadSpec::Anisotropy::isotropic) {
    // One profile with the target spectrum, along x (transverse tining) or across (longitudinal).
    const bool along_x = spec.anisotropy == TextureRoadSpec::Anisotropy::transverse;
    const double needed = along_x ? needed_x : needed_y;
    const std::size_t n = synthesis_grid_size(needed, needed);
    const double period = h * static_cast<double>(n);
    const std::vector<double> p = synthesise_periodic_profile(
        n, h, spec.seed, [&](double wavenumber) { return spectral_amplitude_1d(psd.line_density(wavenumber), period); });
    for (std::size_t i = 0; i < x_count; ++i) {
      const double w = lead_in_window(h * static_cast<double>(i), s.lead_in);
      for (std::size_t j = 0; j < y_count; ++j) samples[i * y_count + j] = w * (along_x ? p[i] : p[j]);
    }
    return std::make_unique<SampledSurface>("texture", h, x_count, y_count, std::move(samples));
  }

  const std::size_t n0 = synthesis_grid_size(needed_x, needed_x * needed_y);
  const std::size_t n1 = synthesis_grid_size(needed_y, needed_x * needed_y);
  synthesis_grid_size(1.0, static_cast<double>(n0) * static_cast<double>(n1));  // the rounded-up grid too
  const std::size_t stride = 2 * (n1 / 2 + 1);
  const std::unique_ptr<double[], FftwFree> data(fftw_alloc_real(n0 * stride));
  if (!data) throw std::bad_alloc();
  const double period_x = h * static_cast<double>(n0);
  const double period_y = h * static_cast<double>(n1);
  // Each grid point stands for the density averaged over a radial interval of one wavenumber
  // step (texture_band_psd.hpp), which keeps the inverse-square-root peaks below the band edges
  // integrable on the grid.
  const double step = std::max(1.0 / period_x, 1.0 / period_y);
  synthesise_periodic_surface(data.get(), n0, n1, period_x, period_y, spec.seed, [&](double nx, double ny) {
    const double q = std::sqrt(nx * nx + ny * ny);
    const double q_low = std::max(0.0, q - 0.5 * step);
    return spectral_amplitude_2d(psd.isotropic_density(q_low, q_low + step), period_x, period_y);
  });
  for (std::size_t i = 0; i < x_count; ++i) {
    const double w = lead_in_window(h * static_cast<double>(i), s.lead_in);
    for (std::size_t j = 0; j < y_count; ++j) samples[i * y_count + j] = w * data[i * stride + j];
  }
  return std::make_unique<SampledSurface>("texture", h, x_count, y_count, std::move(samples));
}

}  // namespace rollnoise
