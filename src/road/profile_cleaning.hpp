#pragma once
// Dropouts and spikes of a measured texture profile (ISO 13473-1:2019 §7.3 dropouts, §7.5
// spikes), and their correction by linear interpolation.
#include <cstddef>
#include <vector>

namespace rollnoise {

struct CleaningReport {
  std::size_t dropouts = 0;  // non-finite entries as given (NaN: the sensor saw nothing)
  std::size_t spikes = 0;    // finite entries rejected as spikes (not counted as dropouts)
};

// Slope threshold of the spike criterion: a height step between successive valid samples of
// at least spike_slope_threshold times their distance (|Δz| >= 3·Δx) is not road texture.
// ISO 13473-1:2019 §7.5 as the instrument maker's implementation (CAPTIF, captif-slp,
// alpha = 3) applies it; the standard's own text was not available to us.
inline constexpr double spike_slope_threshold = 3.0;

// ISO 13473-1:2019 handling of a measured profile sampled at `spacing_m`: non-finite entries
// are dropouts; spikes (see spike_slope_threshold: both samples on either side of such a step
// are marked) are set to dropouts; all dropouts are then filled by linear interpolation between
// their valid neighbours (before the first / after the last valid point: that point's value).
// Throws InputError (key "spacing") for a spacing that is not finite and > 0, and (key
// "profile") if no valid point remains. Counts are reported.
CleaningReport clean_profile(std::vector<double>& z, double spacing_m);

}  // namespace rollnoise
