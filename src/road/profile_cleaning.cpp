#include "road/profile_cleaning.hpp"

#include <cmath>
#include <string>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

// Marks the spikes of z (finite entries only) as NaN and returns how many were marked.
std::size_t remove_spikes(std::vector<double>& z, double spacing_m) {
  std::vector<char> spike(z.size(), 0);
  std::size_t previous = z.size();  // index of the last valid sample seen
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (!std::isfinite(z[i])) continue;
    if (previous < z.size()) {
      const double distance = static_cast<double>(i - previous) * spacing_m;
      if (std::abs(z[i] - z[previous]) >= spike_slope_threshold * distance) {
        spike[previous] = 1;  // forward and backward: both ends of the step
        spike[i] = 1;
      }
    }
    previous = i;
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (spike[i]) {
      z[i] = std::nan("");
      ++count;
    }
  }
  return count;
}

}  // namespace

CleaningReport clean_profile(std::vector<double>& z, double spacing_m) {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0)) {
    throw InputError("", "spacing",
                     "the sample spacing must be a finite number > 0 m (is " + format_number(spacing_m) + ")");
  }
  CleaningReport report;
  for (double& v : z) {
    if (!std::isfinite(v)) {
      v = std::nan("");  // infinities are dropouts as well
      ++report.dropouts;
    }
  }
  report.spikes = remove_spikes(z, spacing_m);

  std::size_t first = 0;
  while (first < z.size() && std::isnan(z[first])) ++first;
  if (first == z.size()) {
    throw InputError("", "profile",
                     "no valid point: all " + std::to_string(z.size()) +
                         " samples are dropouts or spikes");
  }
  for (std::size_t i = 0; i < first; ++i) z[i] = z[first];  // start: nearest valid value
  std::size_t last = first;  // the last valid sample so far
  for (std::size_t i = first + 1; i < z.size(); ++i) {
    if (std::isnan(z[i])) continue;
    // Linear interpolation over the gap (last, i).
    const double step = (z[i] - z[last]) / static_cast<double>(i - last);
    for (std::size_t j = last + 1; j < i; ++j) z[j] = z[last] + step * static_cast<double>(j - last);
    last = i;
  }
  for (std::size_t i = last + 1; i < z.size(); ++i) z[i] = z[last];  // end: nearest valid value
  return report;
}

}  // namespace rollnoise
