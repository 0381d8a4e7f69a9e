#pragma once
// What a road engineer reads off a profile, in one call: RMS height, mean profile depth
// (ISO 13473-1, mean_profile_depth.hpp), the third-octave texture spectrum (ISO 13473-4,
// texture_spectrum.hpp) and the unevenness PSD with its ISO 8608 class (unevenness_psd.hpp).
// The same analysis runs on every profile, read or generated, so a user sees what the contact
// solver will roll over.
//
// Several parallel lines (a height map, or a CSV with z_1 … z_n) are analysed line by line:
// MPD is the mean of the lines' MPD (each line is a measurement, as in ISO 13473-1 §8), the
// texture levels are energy means per band (the lines sample one random surface), the RMS is
// taken over all samples, and the skewness is the mean of the lines' skewness, each about its
// least-squares line (positive: peaks stand up; negative: a plateau with pits and grooves).
#include <optional>
#include <string>
#include <vector>

#include "road/mean_profile_depth.hpp"
#include "road/texture_spectrum.hpp"
#include "road/unevenness_psd.hpp"

namespace rollnoise {

struct ProfileAnalysis {
  double rms_m = 0.0;                       // about each line's mean
  double skewness = 0.0;                    // mean over the lines, each detrended
  std::optional<MpdResult> mpd;             // absent when a line is shorter than one 100 mm segment
  std::vector<TextureBand> texture;         // bands every line resolves
  std::optional<UnevennessPsd> unevenness;  // absent when no line reaches the ISO 8608 band
};

// `lines`: clean heights (m) at `spacing_m`, all of the same length (else std::invalid_argument).
// The skewness m3 / m2^1.5 of `line` about its least-squares line (0 for a flat line).
double detrended_skewness(const std::vector<double>& line);

ProfileAnalysis analyse_profile(const std::vector<std::vector<double>>& lines, double spacing_m);

}  // namespace rollnoise
