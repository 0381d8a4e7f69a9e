#pragma once
// Road unevenness by its displacement PSD and the ISO 8608:2016 class A–H.
//
// Estimator: Welch's method. Segments of L_s samples (the largest power of two <= N/4, so that
// at least 7 half-overlapping segments are averaged; all N if that is below 64), each with its
// least-squares line removed and a periodic Hann window, overlapping by half; one-sided
// G_d(n_k) = 2|X_k|²Δ/(L_s·mean(w²)) averaged over the segments (m³, n in cycles/m).
//
// Class: ISO 8608 describes a road by G_d(n) = G_d(n0)(n/n0)^-w, n0 = 0.1 cycles/m, w = 2, over
// 0.011 <= n <= 2.83 cycles/m (§5, Table 1 band). G_d(n0) is fitted with w fixed at 2 as the mean
// over the third-octave bands of n (equal weight per band, as a log-log fit weighs them) of the
// band means of G_d(n_k)·(n_k/n0)^w; every term is an unbiased estimate of G_d(n0), so their
// mean is too (a fit of logarithms would be biased low by the periodogram's scatter). Only bins
// k >= 3 of a segment (beyond the window's main lobe around the removed trend) and n below a
// quarter of the sampling rate take part. The class is the one whose limits (Table 1: the
// geometric means A: 16e-6 … H: 262144e-6 m³, limits a factor 2 either side) hold G_d(n0).
#include <span>
#include <string>
#include <vector>

namespace rollnoise {

inline constexpr double iso8608_n0 = 0.1;        // cycles/m
inline constexpr double iso8608_n_min = 0.011;   // cycles/m, lower end of the standard's band
inline constexpr double iso8608_n_max = 2.83;    // cycles/m, upper end

struct UnevennessPsd {
  std::vector<double> n;   // spatial frequencies, cycles/m (k / (L_s Δ), k = 1 … L_s/2)
  std::vector<double> gd;  // one-sided displacement PSD, m³
  double gd_n0 = 0;        // fitted G_d(n0), m³
  double waviness = 2;     // w, fixed by the standard's classification
  std::string iso8608_class;  // "A" … "H"
};

// z: clean heights (m) at `spacing_m` (finite, > 0: else InputError key "spacing"). A
// non-finite height, or a profile too short or too coarse to have any Welch bin inside the
// standard's band, is an InputError (key "profile").
UnevennessPsd unevenness_psd(std::span<const double> z, double spacing_m);

// The class table of ISO 8608 (Table 1): the geometric mean G_d(n0) of class 'A' … 'H', m³:
// 16e-6 · 4^(class - 'A'). Any other character is an InputError (key "class").
double iso8608_class_gd_n0(char cls);
// The class whose limits [gm/2, 2·gm) hold gd_n0 (below A's range: "A"; above H's: "H").
// Not finite or <= 0: InputError (key "gd_n0").
std::string iso8608_class_of(double gd_n0);

}  // namespace rollnoise
