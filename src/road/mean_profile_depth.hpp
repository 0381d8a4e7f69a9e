#pragma once
// Mean profile depth (MPD) and estimated texture depth (ETD) of a texture profile,
// ISO 13473-1:2019.
//
// What is applied, in order (z up; all on the whole profile before it is cut into segments):
//  1. Resampling (§7.4): a profile sampled finer than mpd_resample_spacing_m (0.5 mm) is
//     averaged over consecutive 0.5 mm bins (the standard's recommended interval; the average
//     is itself a mild low pass). Spacings from 0.5 mm to mpd_max_spacing_m (1 mm, the
//     coarsest the standard allows) are used as they are; coarser ones are an InputError.
//  2. Low-pass filter (§7.6, Annex D): 2nd-order Butterworth with its -3 dB point at the
//     texture wavelength mpd_lowpass_cutoff_m = 2.4 mm, made digital by the bilinear transform
//     with pre-warping and run forward and backward (zero phase: the peaks stay where they are;
//     the overall gain is |H|², 1/(1 + (tan(πΔ/λ)/tan(πΔ/λc))⁴)). The 2.4 mm corner is what the
//     instrument maker's implementation of Annex D uses; the standard's coefficient table itself
//     was not available to us, so this is a documented equivalent. The ends are padded by odd
//     reflection and the filter starts in its steady state, so a line or an offset passes
//     unchanged.
//  3. Segments (§7.7): consecutive 100 mm segments from the start; a shorter rest is left out.
//  4. Slope suppression (§7.7): the least-squares line of each segment is subtracted (the
//     "spot" measurement variant; the standard's alternative, a high-pass filter, is for
//     profiles evaluated over long distances).
//  5. MSD (§7.8, eq. 1): the mean of the peak levels of the two 50 mm halves minus the mean
//     level of the segment (0 after step 4, kept for clarity).
//  6. MPD = mean of the MSDs of all segments; ETD = 0.2 mm + 0.8·MPD (§9, eq. 2).
// The standard's segment validity rules (more than 10 % dropouts, 5 % spikes) need the raw
// dropout map and are the caller's: z here is already clean.
#include <cstddef>
#include <span>
#include <vector>

namespace rollnoise {

inline constexpr double mpd_resample_spacing_m = 0.5e-3;
inline constexpr double mpd_max_spacing_m = 1.0e-3;
inline constexpr double mpd_lowpass_cutoff_m = 2.4e-3;
inline constexpr double mpd_segment_length_m = 0.1;

struct MpdResult {
  double mpd_m = 0;             // mean profile depth
  double etd_m = 0;             // estimated texture depth
  std::size_t segments = 0;     // 100 mm segments evaluated
  double spacing_m = 0;         // sample spacing of the evaluated (resampled) profile
};

// z: heights (m, z up) at `spacing_m`, clean (all finite: see clean_profile). A spacing that
// is not finite, <= 0 or > 1 mm is an InputError (key "spacing"); a non-finite height or a
// profile shorter than one segment (100 mm) is an InputError (key "profile").
MpdResult mean_profile_depth(std::span<const double> z, double spacing_m);

// The MPD low-pass filter alone (step 2), at `spacing_m`: for tests and plots.
std::vector<double> mpd_lowpass(std::span<const double> z, double spacing_m);

}  // namespace rollnoise
