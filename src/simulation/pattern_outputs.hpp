#pragma once
// What a run with a tread pattern adds to its outputs: the pattern's map (tread_pattern.csv and
// its picture, tread_pattern.png with the gnuplot script that drew it) and its tones named in
// summary.json ("tread_pattern").
//
// Tones: a pattern of order N (N pitches) passes the contact N times a turn, at f_1 = N·v/(2πR);
// harmonic k at k·f_1. Each is named with its third-octave band (IEC 61260-1) and the level of
// that band of the total contact force over the mean level of its two neighbouring bands,
//   ΔL = L_b − (L_{b−1} + L_{b+1})/2   (dB; L: band levels of the fluctuating total force),
// the one-third-octave test for a prominent tone of ISO 1996-2:2017 Annex K (there applied to
// sound; here to the force that drives the tyre).
#include <filesystem>
#include <span>

#include <nlohmann/json.hpp>

#include "contact/tread_pattern.hpp"

namespace rollnoise {

class PlotBatch;

// tread_pattern.csv (s, y, height, m: about 2 mm around and across, one scan line per s) and, when
// `plots`, tread_pattern.gp / .png: the tread unrolled in four strips of a quarter turn each.
void write_tread_pattern_map(const std::filesystem::path& dir, const TreadPattern& pattern, double tread_width,
                             const std::string& title, PlotBatch* plots);

// The "tread_pattern" entry of summary.json: the pattern's order, fundamental and the first
// `harmonics` tones with their bands and ΔL from the total contact force (N) sampled at
// `sample_rate`. A tone whose upper neighbouring band reaches the Nyquist frequency, or a record
// too short for a spectrum (< 8 samples), has no level (null).
nlohmann::json pattern_tones(const TreadPattern& pattern, std::span<const double> total_force, double sample_rate,
                             double speed, int harmonics = 4);

}  // namespace rollnoise
