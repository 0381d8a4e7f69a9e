#include "road/profile_cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/mean_profile_depth.hpp"

namespace rollnoise {
namespace {

// Relative slack for the bin edges (as mean_profile_depth's resampling: a bin of exactly
// 0.5 mm / spacing samples does not lose its last one to rounding).
constexpr double slack = 1e-9;

// Rule 1: marks (spike[i] = 1) both valid samples of every step between successive valid
// samples of at least spike_slope_threshold times their distance, the distance taken as at
// least `min_distance_m`.
void mark_steps(const std::vector<double>& z, double spacing_m, double min_distance_m, std::vector<char>& spike) {
  std::size_t previous = z.size();  // index of the last valid sample seen
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (std::isnan(z[i])) continue;
    if (previous < z.size()) {
      const double distance = std::max(static_cast<double>(i - previous) * spacing_m, min_distance_m);
      if (std::abs(z[i] - z[previous]) >= spike_slope_threshold * distance) {
        spike[previous] = 1;  // forward and backward: both ends of the step
        spike[i] = 1;
      }
    }
    previous = i;
  }
}

// Fills the NaN entries of z by linear interpolation between their valid neighbours (before the
// first / after the last valid point: that point's value). Throws if no entry is valid.
void fill_gaps(std::vector<double>& z) {
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
}

// Rule 2: the spike test on the 0.5 mm bin means of `filled` (no NaN). Marks every sample of
// both bins of each step |Δz| >= spike_slope_threshold · 0.5 mm between successive bins.
void mark_bins(const std::vector<double>& filled, double spacing_m, std::vector<char>& spike) {
  const double ratio = mpd_resample_spacing_m / spacing_m;  // samples per bin (> 1)
  const std::size_t n = filled.size();
  auto begin_of = [&](std::size_t k) {  // first sample of bin k (n past the last bin)
    return std::min(n, static_cast<std::size_t>(std::ceil(static_cast<double>(k) * ratio - slack)));
  };
  const double threshold = spike_slope_threshold * mpd_resample_spacing_m;
  double previous_mean = 0.0;
  for (std::size_t k = 0; begin_of(k) < n; ++k) {
    const std::size_t begin = begin_of(k), end = begin_of(k + 1);
    double sum = 0.0;
    for (std::size_t i = begin; i < end; ++i) sum += filled[i];
    const double mean = sum / static_cast<double>(end - begin);
    if (k > 0 && std::abs(mean - previous_mean) >= threshold) {
      std::fill(spike.begin() + static_cast<std::ptrdiff_t>(begin_of(k - 1)),
                spike.begin() + static_cast<std::ptrdiff_t>(end), char{1});  // both bins
    }
    previous_mean = mean;
  }
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
  std::vector<char> spike(z.size(), 0);
  mark_steps(z, spacing_m, mpd_resample_spacing_m, spike);  // rule 1
  if (spacing_m < mpd_resample_spacing_m * (1 - slack)) {
    // Rule 2 on the profile with its dropouts and rule-1 spikes filled.
    std::vector<double> filled = z;
    for (std::size_t i = 0; i < z.size(); ++i)
      if (spike[i]) filled[i] = std::nan("");
    fill_gaps(filled);
    mark_bins(filled, spacing_m, spike);
  }
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (spike[i] && !std::isnan(z[i])) {  // a dropout in a marked bin stays a dropout
      z[i] = std::nan("");
      ++report.spikes;
    }
  }
  fill_gaps(z);
  return report;
}

}  // namespace rollnoise
