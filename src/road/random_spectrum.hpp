#pragma once
// What the random profile and the random surface share: their [road] keys (std_dev, either
// correlation_length for a Gaussian autocorrelation or min_wavelength + max_wavelength for a
// band, sample_spacing, lead_in, seed) and the checks of the spectrum's scales. `Spec` is
// RandomRoadSpec or RandomSurfaceSpec, which name these fields alike.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {

template <class Spec>
void read_random_spectrum_keys(const ConfigTable& road, Spec& spec) {
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
    spec.spectrum = Spec::Spectrum::gaussian;
    spec.correlation_length = road.positive("correlation_length");
  } else if (has_min || has_max) {
    if (!has_min) road.fail("min_wavelength", "is required with max_wavelength (band-limited spectrum)");
    if (!has_max) road.fail("max_wavelength", "is required with min_wavelength (band-limited spectrum)");
    spec.spectrum = Spec::Spectrum::band;
    spec.min_wavelength = road.positive("min_wavelength");
    spec.max_wavelength = road.positive("max_wavelength");
    if (!(spec.min_wavelength < spec.max_wavelength)) {
      road.fail("min_wavelength", "must be less than max_wavelength (got " + format_number(spec.min_wavelength) +
                                      " and " + format_number(spec.max_wavelength) + ")");
    }
  } else {
    road.fail("correlation_length", "is required, or else min_wavelength and max_wavelength (band-limited spectrum)");
  }
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  if (road.contains("lead_in")) spec.lead_in = road.non_negative("lead_in");
  spec.seed = static_cast<std::uint64_t>(road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
}

// The checked scales of a random road's spectrum. Bad values are InputErrors whose key is the
// bare key name and whose source is empty (the factory names both).
struct SpectrumScales {
  double std_dev = 0.0;
  bool gaussian = true;
  double shortest = 0.0;  // correlation length, or the shortest wavelength of the band (m)
  double longest = 0.0;   // correlation length, or the longest wavelength (m)
  double spacing = 0.0;   // grid spacing (m)
  double lead_in = 0.0;   // m
};

inline double require_positive_scale(const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError("", key, "must be a finite number > 0 (got " + format_number(value) + ")");
  }
  return value;
}

// `spacing_divisor`: the default grid spacing is the shortest scale over this.
template <class Spec>
SpectrumScales check_spectrum_scales(const Spec& spec, double spacing_divisor) {
  SpectrumScales s;
  s.std_dev = require_positive_scale("std_dev", spec.std_dev);
  s.gaussian = spec.spectrum == Spec::Spectrum::gaussian;
  if (s.gaussian) {
    s.shortest = s.longest = require_positive_scale("correlation_length", spec.correlation_length);
  } else {
    s.shortest = require_positive_scale("min_wavelength", spec.min_wavelength);
    s.longest = require_positive_scale("max_wavelength", spec.max_wavelength);
    if (!(s.shortest < s.longest)) {
      throw InputError("", "min_wavelength", "must be less than max_wavelength (got " + format_number(s.shortest) +
                                                 " and " + format_number(s.longest) + ")");
    }
  }
  s.spacing = require_positive_scale("sample_spacing", spec.sample_spacing.value_or(s.shortest / spacing_divisor));
  // The grid must resolve the spectrum: the band up to the Nyquist wavenumber 1/(2·spacing); for
  // the Gaussian, spacing <= lc/2 leaves out spectral density below exp(−π²) ≈ 5e-5 of its peak.
  if (s.spacing > s.shortest / 2.0) {
    throw InputError("", "sample_spacing",
                     std::string("must be at most ") + (s.gaussian ? "correlation_length / 2" : "min_wavelength / 2") +
                         " to resolve the spectrum (got " + format_number(s.spacing) + ", limit " +
                         format_number(s.shortest / 2.0) + ")");
  }
  s.lead_in = spec.lead_in.value_or(2.0 * s.longest);
  if (!(s.lead_in >= 0.0) || !std::isfinite(s.lead_in)) {
    throw InputError("", "lead_in", "must be a finite number >= 0 (got " + format_number(s.lead_in) + ")");
  }
  return s;
}

}  // namespace rollnoise
