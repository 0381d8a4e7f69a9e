#include "road/line_cleaning.hpp"

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"

namespace rollnoise {
namespace {

// INTERIM, to be replaced by clean_profile (profile_cleaning.hpp) when branch road-analysis
// merges: fills dropouts by linear interpolation between the nearest valid neighbours (the
// nearest valid value at the ends) and detects no spikes.
LineCleaning interim_fill_dropouts_until_road_analysis_merges(std::vector<double>& z) {
  LineCleaning report;
  std::size_t previous = z.size();  // index of the last valid value seen
  for (std::size_t i = 0; i <= z.size(); ++i) {
    if (i < z.size() && std::isnan(z[i])) continue;
    const std::size_t gap_start = previous == z.size() ? 0 : previous + 1;
    for (std::size_t k = gap_start; k < i; ++k) {
      ++report.dropouts;
      if (previous == z.size()) {
        z[k] = z[i];
      } else if (i == z.size()) {
        z[k] = z[previous];
      } else {
        const double f = static_cast<double>(k - previous) / static_cast<double>(i - previous);
        z[k] = (1.0 - f) * z[previous] + f * z[i];
      }
    }
    previous = i;
  }
  return report;
}

}  // namespace

LineCleaning clean_measured_line(std::vector<double>& z, double spacing_m, const std::string& source) {
  if (!(spacing_m > 0.0)) throw std::invalid_argument("clean_measured_line: spacing must be > 0");
  bool any_valid = false;
  for (double v : z) any_valid = any_valid || !std::isnan(v);
  if (!any_valid) throw InputError(source, "", "a height line has no value at all (every sample is a dropout)");
  return interim_fill_dropouts_until_road_analysis_merges(z);
}

}  // namespace rollnoise
