#pragma once
// Dropouts and spikes of a measured texture profile (ISO 13473-1:2019 §7.3 dropouts, §7.5 and
// Eqn E.1 spikes, as CAPTIF's implementation numbers them), and their correction by linear
// interpolation.
//
// The scale of the spike criterion. The standard's criterion is a step between successive
// samples of the profile it evaluates, which is sampled at 0.5 mm (mpd_resample_spacing_m;
// 1 mm at most). CAPTIF's implementation (captif-slp, captif_slp/slp.py, Reading.from_trace)
// does, in this order: dropouts (non-finite heights) filled by linear interpolation in distance
// (the ends take the first / last valid value); the profile resampled to 0.5 mm by averaging
// the samples of each 0.5 mm bin; spikes detected on that resampled profile (|Δz| >= α·0.5 mm
// between successive resampled points; both points of such a step are spikes); the spikes set
// to missing and filled again by linear interpolation on the resampled profile; then the
// low-pass filter and the segments. A spike is judged at 0.5 mm, never at the sensor's spacing.
//
// A profile sampled finer than 0.5 mm (the CAPTIF laser steps 0.0375 mm) is kept at its own
// spacing here, because the texture spectrum down to 0.5 mm uses it; the equivalent is:
//  1. a single reading that steps by at least α·0.5 mm (3 mm for α = 6) from the previous
//     valid reading — |Δz| >= α·max(Δx, 0.5 mm) — is a spike (both readings of the step). A
//     0.5 mm-sampled profile, where each point is one reading, would flag such a reading; in
//     CAPTIF's bin averages it is only diluted (by 1/13 at 0.0375 mm) and survives as a bump,
//     so this rule is stricter than captif-slp there (on the two CAPTIF profiles it adds 22
//     and 53 samples that no marked bin holds; 38 and 58 with α = 3);
//  2. with the dropouts and those readings filled by linear interpolation, the profile is
//     averaged over the 0.5 mm bins of mean_profile_depth (bin k holds the samples from
//     k·0.5 mm, counted from the first sample; a shorter last bin is kept so that every
//     sample is judged); a step |Δz| >= α·0.5 mm between successive bin means marks both bins,
//     and every valid sample in a marked bin is a spike. That is captif-slp's test on the
//     resampled profile; marking the fine samples of a marked bin and interpolating them
//     linearly on the fine grid stands for its interpolation of the marked 0.5 mm points, and
//     keeps the fine sampling of everything else.
// captif-slp's bins close on the right (0, 0.5], (0.5, 1] ...; these close on the left: a
// boundary sample may fall in the neighbouring bin. A profile sampled at 0.5 mm or coarser is
// judged sample by sample (rule 1 with Δx >= 0.5 mm: |Δz| >= α·Δx), as captif-slp does when
// no resampling is needed.
//
// What this means for a coarse chip seal: at 0.5 mm with α = 3, the steep faces of the chips
// are themselves flagged (1998 and 3092 samples, 4.1 % and 6.4 % of the two CAPTIF profiles;
// at the laser's spacing the criterion flagged 1803 and 2241). captif-slp
// says as much (README, `alpha`: α = 3 "results in a large number of false positives when
// analysing highly textured surfaces in New Zealand (e.g. chipseals). A value of 6 has been
// found to yield good results on profiles taken using the CAPTIF SLP instrument"), and its
// batch processing of CAPTIF SLP files (process_files) uses α = 6. α here is 6
// (spike_slope_threshold) for that reason: with it the two CAPTIF profiles keep their chip faces
// (120 and 588 samples flagged) and a steep aggregate profile survives a CSV round trip (sma8,
// 3 lines of 1 m at 0.2 mm: MPD 0.624 mm generated, 0.617 mm read back, 120 of 15 003 samples
// flagged; 0.47 mm with α = 3); the standard's suggested 3 removed 4-6 % of a real chip seal.
// A marked bin is replaced by a straight line over its 0.5 mm, so the fine texture of a marked
// face is gone: with α = 3 that took 2.5 to 4.5 dB off the CAPTIF profiles' mean levels below
// 2.5 mm, against the criterion applied at the laser's spacing (α = 3, 1803 and 2241 samples).
// With α = 6 the mean levels below 2.5 mm are 0.2 to 0.8 dB below those and within about
// 0.2 dB from 2.5 mm up, and the MPDs are 3.2107 and 3.0986 mm (-0.07 % and -0.26 %).
#include <cstddef>
#include <vector>

namespace rollnoise {

struct CleaningReport {
  std::size_t dropouts = 0;  // non-finite entries as given (NaN: the sensor saw nothing)
  std::size_t spikes = 0;    // finite entries rejected as spikes (not counted as dropouts)
};

// Slope threshold α of the spike criterion: a height step of at least α times the distance,
// the distance being at least the 0.5 mm of the evaluated profile (see above), is not road
// texture. ISO 13473-1:2019 Eqn E.1 with the value the instrument maker processes its own
// profiles with (captif-slp process_files: alpha = 6; its default and the standard's suggestion
// are 3, which flags the faces of coarse chips, see above); the standard's own text was not
// available to us.
inline constexpr double spike_slope_threshold = 6.0;

// ISO 13473-1:2019 handling of a measured profile sampled at `spacing_m`: non-finite entries
// are dropouts; spikes (rules 1 and 2 above) are set to dropouts; all dropouts are then filled
// by linear interpolation between their valid neighbours (before the first / after the last
// valid point: that point's value). Throws InputError (key "spacing") for a spacing that is
// not finite and > 0, and (key "profile") if no valid point remains. Counts are reported.
CleaningReport clean_profile(std::vector<double>& z, double spacing_m);

}  // namespace rollnoise
