#pragma once
// The frequency weightings A, C and Z of IEC 61672-1:2013 (5.5, Table 3, Annex E), as a
// magnitude at any frequency and as a digital filter applied to a sampled pressure signal.
//
// Magnitude (Annex E, the closed forms of the weightings): with the pole frequencies f1..f4 below,
//   C(f) = 20 lg[ f4² f² / ((f² + f1²)(f² + f4²)) ] − C1000
//   A(f) = 20 lg[ f4² f⁴ / ((f² + f1²)(f² + f2²)^½ (f² + f3²)^½ (f² + f4²)) ] − A1000
// The normalisation constants make the weighting exactly 0 dB at 1 kHz; the standard quotes them
// rounded to 0.001 dB as A1000 = −2.000 dB and C1000 = −0.062 dB. Here they are computed from the
// formulas (−1.99966 and −0.06190 dB), not taken rounded: Table 3 was computed that way — with
// the rounded −2.000 dB the A weighting at the exact 160 Hz frequency is −13.34996 dB, which
// rounds to the −13.3 dB the table does not print (it prints −13.4 dB). Z is 0 dB everywhere.
//
// Table 3 lists nominal frequencies, but its values are those of the formulas at the exact
// base-10 frequencies f = 1000·10^(n/10) Hz (at the nominal 12.5 Hz the A formula gives −63.58 dB,
// the table −63.4 dB = the value at 12.589 Hz): evaluate at exact frequencies to compare.
//
// The digital filter. The analogue prototype factors into second-order sections:
//   A: s²/(s + ω1)²  ·  s²/((s + ω2)(s + ω3))  ·  ω4²/(s + ω4)²     (ωi = 2π fi)
//   C: s²/(s + ω1)²  ·  ω4²/(s + ω4)²
// The high-pass sections (poles at 20.6, 107.7 and 737.9 Hz) are bilinear transformed with each
// pole prewarped to its own frequency: their poles lie far below any audio Nyquist frequency, so
// the frequency warping of the bilinear transform is negligible where they act (< 0.01 dB).
// The low-pass pair at f4 = 12.2 kHz is where the bilinear transform fails: it maps s = ∞ to the
// Nyquist frequency, so at fs = 48 kHz it is 6.4 dB low at 16 kHz and 16 dB low at 20 kHz.
// That section is instead a "matched" second-order section (after M. Vicanek, "Matched
// second order digital filters", 2016): poles by impulse invariance, z = e^{−ω4/fs} (double),
// and a numerator of degree 2 chosen so that the squared magnitude equals the prototype's
// exactly at 0, 0.3·fs and 0.4·fs (a linear problem in x = cos ω, then spectral factorisation
// to a minimum-phase numerator). Matching at 0.3 and 0.4 fs rather than at fs/4 and fs/2 keeps
// the error small where the standard asks for accuracy and lets it grow only above 0.4 fs.
// Deviation of the whole filter from the closed form, measured (test_frequency_weighting.cpp):
// <= 0.08 dB from 10 Hz to 0.4·fs for every fs from 32 kHz to 192 kHz (0.1 dB at 16 kHz), and
// <= 1.35 dB between 0.4·fs and fs/2 at 44.1/48 kHz (1.6 dB at 192 kHz). At 48 kHz against
// Table 3 up to 16 kHz: <= 0.09 dB, far inside the class 1 acceptance limits (±1 dB in mid
// band, +2.0/−5.0 dB at 12.5 kHz, +2.5/−16 dB at 16 kHz). The whole cascade is scaled to
// exactly the formula's value (0 dB) at 1 kHz.
//
// Limits. A sampled signal holds nothing above fs/2, and the weighting's high-frequency roll-off
// (f4 = 12.2 kHz) is only fully represented when fs/2 is well above f4: use fs >= 44.1 kHz for
// full-range (to 16-20 kHz) A- or C-weighted levels. At lower rates the filter remains a faithful
// weighting of the band the signal holds (fs = 32 kHz: within 0.08 dB to 12.8 kHz), but it cannot
// know about content above fs/2; for signals whose interesting content is near or above fs/2,
// or when only band levels are needed, apply the weighting in the frequency domain instead:
// L_A = L + weighting_db(A, f_m) on band levels (what band_spectrum does). Phase is not the
// analogue prototype's (the matched section is minimum phase but not phase-matched); levels do
// not depend on it. The filter starts from rest: the first few tens of ms of output carry the
// start-up transient of the 20.6 Hz poles (time constant 1/(2π·20.6 Hz) = 7.7 ms).
#include <complex>
#include <span>
#include <string>
#include <vector>

#include "core/cancellation.hpp"

namespace rollnoise {

enum class FrequencyWeighting { A, C, Z };

// "A", "C" or "Z".
std::string to_string(FrequencyWeighting weighting);
// Parses "A", "C" or "Z" (also lower case); anything else is an InputError for `key`.
FrequencyWeighting parse_frequency_weighting(const std::string& text, const std::string& key = "weighting");

// IEC 61672-1:2013 Annex E: the pole frequencies of the weightings (Hz).
struct WeightingPoles {
  static constexpr double f1 = 20.598997;
  static constexpr double f2 = 107.65265;
  static constexpr double f3 = 737.86223;
  static constexpr double f4 = 12194.217;
};

// The weighting's relative response (dB) at `frequency` (Hz, >= 0; -inf at 0 Hz for A and C),
// from the closed form of Annex E, exactly 0 dB at 1 kHz. Z: 0 dB.
double weighting_db(FrequencyWeighting weighting, double frequency);

// The normalisation constant (dB): the un-normalised formula's value at 1 kHz. A: −1.99966,
// C: −0.06190 (the standard's A1000 = −2.000 dB and C1000 = −0.062 dB, rounded); Z: 0.
double weighting_normalisation_db(FrequencyWeighting weighting);

// A frequency-weighting filter for signals sampled at `sample_rate` (design above).
class WeightingFilter {
 public:
  // sample_rate: Hz, finite, > 2000 (the 1 kHz reference must lie below fs/2); otherwise an
  // InputError with key "sample_rate".
  WeightingFilter(FrequencyWeighting weighting, double sample_rate);

  FrequencyWeighting weighting() const noexcept { return weighting_; }
  double sample_rate() const noexcept { return sample_rate_; }

  // Complex frequency response at `frequency` (Hz, 0 <= f <= fs/2).
  std::complex<double> response(double frequency) const;
  // |response| in dB.
  double response_db(double frequency) const;

  // The weighted signal, the filter starting from rest. `cancel` is polled every 65536 samples
  // of each section (Interrupted).
  std::vector<double> apply(std::span<const double> signal, const CancellationToken& cancel = {}) const;

 private:
  // One second-order section b(z)/a(z), a0 = 1.
  struct Section {
    double b0, b1, b2, a1, a2;
  };

  FrequencyWeighting weighting_;
  double sample_rate_;
  std::vector<Section> sections_;
  double gain_ = 1.0;
};

}  // namespace rollnoise
