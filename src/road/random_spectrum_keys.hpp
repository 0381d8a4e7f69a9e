#pragma once
// The [road] keys shared by the random profile and the random surface: std_dev, either
// correlation_length (Gaussian autocorrelation) or min_wavelength + max_wavelength (a band),
// sample_spacing, lead_in and seed. `Spec` is RandomRoadSpec or RandomSurfaceSpec, which name
// these fields alike.
#include <cstdint>
#include <limits>

#include "core/config_table.hpp"
#include "core/csv.hpp"

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

}  // namespace rollnoise
