#pragma once
// What a measured record says about its surface, for a surface generated from it
// (profile_surface_road.hpp): the third-octave texture levels of the bands the record supports,
// and its heights restricted to those bands, whose distribution the generated surface keeps.
//
// Bands the record supports. A base-10 third-octave band (ISO 13473-4, 0.5 to 500 mm) whose
// lower edge wavelength is at least 2 × spacing (below the Nyquist wavelength nothing was
// sampled) and whose upper edge is at most L / record_band_length_factor, L the shortest line's
// length: then each line holds about two cosine modes in the band (below), several lines more.
// For the CAPTIF fine asphalt (9 lines of 0.2 m at 0.305 mm) those are 0.8 to 40 mm; for the
// CAPTIF chip seal (1.8 m at 0.0375 mm) 0.5 to 400 mm.
//
// Estimator. Each line, its least-squares line removed, is expanded in cosines (the DCT-II, the
// Fourier series of the line mirrored at its ends): mode k, of wavenumber k / (2L), holds
// Y_k^2 / (2 N^2) of the line's mean square (Parseval), and a band's variance is the sum over
// its modes (wavenumbers in [10^(-1/20), 10^(1/20)) / centre, as texture_spectrum.hpp).
// Mirroring makes the line continuous at its ends, so no window is needed and the long,
// strong wavelengths of a short record do not leak into its short bands (a short record's
// Hann-windowed periodogram is resolved only to L / 12: texture_spectrum.hpp). The levels are
// energy means over the lines. The band-passed heights are the inverse transform of each line's
// modes within the bands' outer edges, all lines pooled.
#include <cstddef>
#include <string>
#include <vector>

namespace rollnoise {

inline constexpr double record_band_length_factor = 4.0;

struct RecordTexture {
  double spacing_m = 0.0;
  double shortest_line_m = 0.0;        // L, the shortest line's length (N spacing)
  std::size_t lines = 0;
  std::vector<double> centres_m;       // exact centres of the supported bands, shortest first
  std::vector<double> nominal_m;       // their nominal centres
  std::vector<double> levels_db;       // L_tx, dB re 1 µm, energy mean over the lines
  double lowest_wavenumber = 0.0;      // the pass band: the longest band's lower edge (cycles/m)
  double highest_wavenumber = 0.0;     // the shortest band's upper edge (cycles/m)
  std::vector<std::vector<double>> band_passed;  // each line within the pass band (m)
};

// `lines`: clean heights (m) at `spacing_m` (lines may differ in length). `source` names the
// record in errors: a record that supports no band, or a band with no texture at all, is an
// InputError with the bare key "file" whose problem names `source` (the road factory names the
// case file and the section); fewer than 4 samples in a line or a non-finite height is a
// std::invalid_argument (the readers deliver clean lines).
RecordTexture measure_record_texture(const std::vector<std::vector<double>>& lines, double spacing_m,
                                     const std::string& source);

// Each line, its least-squares line removed, restricted to wavenumbers in [lowest, highest)
// (cycles/m) through its cosine series (as measure_record_texture restricts a record): the same
// band limits applied to other lines, such as a generated surface's, for a like-for-like
// comparison with the record's band-passed heights.
std::vector<std::vector<double>> band_pass_lines(const std::vector<std::vector<double>>& lines, double spacing_m,
                                                 double lowest_wavenumber, double highest_wavenumber);

// A line at `spacing_m` analysed as the record's lines were: cut into consecutive pieces of the
// record's shortest line length (a shorter rest is dropped), each band-passed to the record's
// pass band (band_pass_lines). A band-passed line's height distribution depends on its length:
// with the band's outside, each piece loses its trend and its lowest modes, which on a 0.2 m
// record are the 45 mm and longer. Band-passed whole, 4 m lines of a surface made from the CAPTIF
// fine asphalt have a kurtosis of 4.5 and 16 m lines 4.3, against the record's 4.7; so a
// surface's distribution is compared with the record's piece by piece.
std::vector<std::vector<double>> band_pass_in_record_pieces(const std::vector<double>& line, double spacing_m,
                                                            const RecordTexture& record);

}  // namespace rollnoise
