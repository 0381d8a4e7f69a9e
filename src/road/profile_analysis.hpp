#pragma once
// What a road engineer reads off a profile, in one call: RMS height, mean profile depth
// (ISO 13473-1, mean_profile_depth.hpp), the third-octave texture spectrum (ISO 13473-4,
// texture_spectrum.hpp) and the unevenness PSD with its ISO 8608 class (unevenness_psd.hpp).
// The same analysis runs on every profile, read or generated, so a user sees what the contact
// solver will roll over.
//
// Several parallel lines (a height map, or a CSV with z_1 … z_n) are analysed line by line:
// MPD is the mean of the lines' MPD (each line is a measurement, as in ISO 13473-1 §8), the
// texture levels are energy means per band (the lines sample one random surface), and the RMS
// is taken over all samples.
#include <optional>
#include <string>
#include <vector>

#include "road/mean_profile_depth.hpp"
#include "road/texture_spectrum.hpp"
#include "road/unevenness_psd.hpp"

namespace rollnoise {

struct ProfileAnalysis {
  double rms_m = 0.0;                       // about each line's mean
  std::optional<MpdResult> mpd;             // absent when a line is shorter than one 100 mm segment
  std::vector<TextureBand> texture;         // bands every line resolves
  std::optional<UnevennessPsd> unevenness;  // absent when no line reaches the ISO 8608 band
};

// `lines`: clean heights (m) at `spacing_m`, all of the same length (else std::invalid_argument).
ProfileAnalysis analyse_profile(const std::vector<std::vector<double>>& lines, double spacing_m);

}  // namespace rollnoise
