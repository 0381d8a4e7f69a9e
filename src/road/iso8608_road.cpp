#include "road/iso8608_road.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config_table.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/spectral_synthesis.hpp"
#include "road/unevenness_psd.hpp"

namespace rollnoise {
namespace {

[[noreturn]] void throw_bad(const char* key, const std::string& problem) {
  throw InputError("", key, problem);  // the factory names the file and the section
}

void require_finite_positive(const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw_bad(key, "must be a finite number > 0 (got " + format_number(value) + ")");
  }
}

}  // namespace

void read_iso8608_keys(const ConfigTable& road, Iso8608RoadSpec& spec) {
  const bool has_class = road.contains("class");
  const bool has_gd = road.contains("gd_n0");
  if (has_class && has_gd) {
    road.fail("gd_n0", "give either class (\"A\" .. \"H\") or gd_n0 (and waviness), not both");
  }
  if (has_class) {
    if (road.contains("waviness")) {
      road.fail("waviness", "the ISO 8608 classes have waviness 2; give gd_n0 instead of class to set it");
    }
    const std::string cls = road.choice("class", {"A", "B", "C", "D", "E", "F", "G", "H"});
    spec.gd_n0 = iso8608_class_gd_n0(cls.front());
    spec.waviness = 2.0;
  } else if (has_gd) {
    spec.gd_n0 = road.positive("gd_n0");
    spec.waviness = road.positive("waviness", 2.0);
  } else {
    road.fail("class", "is required (\"A\" .. \"H\"), or else gd_n0 (m^3) and optionally waviness");
  }
  spec.seed = static_cast<std::uint64_t>(road.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  spec.length = road.positive("length", 100.0);
  if (road.contains("sample_spacing")) spec.sample_spacing = road.positive("sample_spacing");
  spec.lead_in = road.non_negative("lead_in", 10.0);
}

std::unique_ptr<SampledProfile> make_iso8608_profile(const Iso8608RoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("make_iso8608_profile: x_max must be finite");
  require_finite_positive("gd_n0", spec.gd_n0);
  require_finite_positive("waviness", spec.waviness);
  require_finite_positive("length", spec.length);
  const double h = spec.sample_spacing.value_or(0.04);
  require_finite_positive("sample_spacing", h);
  const double limit = 1.0 / (2.0 * Iso8608RoadSpec::n_high);
  if (h > limit) {
    throw_bad("sample_spacing", "must be at most 1 / (2 × 2.83 cycles/m) = " + format_number(limit) +
                                    " m to resolve the ISO 8608 range (got " + format_number(h) + ")");
  }
  if (!(spec.lead_in >= 0.0) || !std::isfinite(spec.lead_in)) {
    throw_bad("lead_in", "must be a finite number >= 0 (got " + format_number(spec.lead_in) + ")");
  }
  const double longest = 1.0 / Iso8608RoadSpec::n_low;
  const double last = std::max(1.0, std::ceil(std::max(spec.length, spec.x_max) / h));
  const double needed = std::max(last + 1.0 + std::ceil(2.0 * longest / h), std::ceil(8.0 * longest / h));
  const std::size_t n = synthesis_grid_size(needed, needed);
  const double period = h * static_cast<double>(n);
  std::vector<double> r = synthesise_periodic_profile(n, h, spec.seed, [&](double wavenumber) {
    if (wavenumber < Iso8608RoadSpec::n_low || wavenumber > Iso8608RoadSpec::n_high) return 0.0;
    const double g = spec.gd_n0 * std::pow(wavenumber / Iso8608RoadSpec::n0, -spec.waviness);
    return spectral_amplitude_1d(g, period);
  });
  r.resize(static_cast<std::size_t>(last) + 1);
  for (std::size_t j = 0; j < r.size(); ++j) r[j] *= lead_in_window(h * static_cast<double>(j), spec.lead_in);
  return std::make_unique<SampledProfile>("iso8608", h, std::move(r));
}

}  // namespace rollnoise
