#pragma once
// Octave and fractional-octave bands per IEC 61260-1:2014, base-10 system.
//
// Frequencies (clause 5: octave frequency ratio, reference frequency, mid-band and band-edge
// frequencies). The octave frequency ratio is G = 10^(3/10); the reference frequency
// f_r = 1000 Hz. For bandwidth designator 1/b the exact mid-band frequencies are
//   f_m = f_r·G^(x/b)            for odd b,
//   f_m = f_r·G^((2x+1)/(2b))    for even b,
// x any integer, and the band edges f_1 = f_m·G^(−1/(2b)), f_2 = f_m·G^(+1/(2b)). For third
// octaves G^(1/3) = 10^(1/10): f_m = 1000·10^(x/10) Hz.
// Nominal mid-band frequencies (Annex E): for octave and third-octave bands the preferred
// numbers of the R10 series (…, 20, 25, 31.5, 40, 50, 63, 80, 100, 125, 160, 200, 250, 315, …)
// that label the exact frequencies; for other b the exact frequency rounded to three significant
// figures when its leading digit is 1 to 4, to two when it is 5 to 9.
//
// The filters. A band filter is a Butterworth band-pass designed at the exact band edges: the
// low-pass prototype of order N (default 3, the customary "6th-order" band filter) is turned
// into a band-pass of order 2N by the low-pass to band-pass transform with the edges prewarped,
// then into a digital filter by the bilinear transform, which puts the −3.01 dB points exactly at
// f_1 and f_2 and maps the prototype's response onto the tangent-warped frequency axis. It runs
// as N second-order sections (zeros at z = ±1) in double precision, at the signal's own sample
// rate: at 48 kHz the 20 Hz band's poles lie about 2e-4 inside the unit circle, far from where
// rounding matters, so no decimation is needed for accuracy (it would only save time).
//
// Against the class 1 acceptance limits on relative attenuation (IEC 61260-1:2014, 5.10, Table 1,
// with the breakpoints of fractional-octave bands from formula (9)), the analogue order-3
// prototype has >= 0.4 dB to spare everywhere (the pass band's own ±0.4 dB at Ω = 1, where the
// relative attenuation is 0 by definition), >= 0.79 dB at the breakpoints away from Ω = 1
// (least at G^(3/8)) and >= 1.81 dB in the stop band (least just outside the edges). The digital
// filters meet the limits for every third-octave band whose upper edge lies below about fs/4:
// at 48 kHz the 20 Hz to 10 kHz bands, least stop-band margin 0.96 dB (the 10 kHz band); at
// 44.1 kHz up to 10 kHz, 0.31 dB; order 4 at 48 kHz up to 20 kHz, 1.7 dB. Above that the bilinear
// warping widens the band's low-frequency skirt beyond the limit (the 12.5 kHz band at 48 kHz,
// order 3: 1.1 dB short at Ω = 1/3.05, the G^(−3) breakpoint). Selectivity of order 3: a tone
// two third-octave bands away is attenuated by 37.0 dB, three bands away by 48.7 dB (order 4:
// 49.3 and 64.9 dB).
//
// Band powers of long stationary signals can also be had by integrating a Welch PSD over the
// ideal band edges (band_mean_squares_from_psd). That is a brick-wall "filter" sampled at the
// PSD's bins: no ripple or skirt, but each band's effective response is the ideal band smeared
// by the Hann window's main lobe (±2 bins), so it is only a class 1 realisation in the sense of
// IEC 61260-1 if that smearing is small against the band, i.e. the resolution fs/N is a small
// fraction (≤ 1/10) of the narrowest band's width. For short or non-stationary records use the
// filter bank.
#include <complex>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "acoustics/welch_psd.hpp"
#include "core/cancellation.hpp"

namespace rollnoise {

// G = 10^(3/10), the base-10 octave frequency ratio (IEC 61260-1:2014).
inline constexpr double octave_ratio = 1.9952623149688795;
// f_r, the reference frequency (IEC 61260-1:2014).
inline constexpr double band_reference_frequency = 1000.0;

struct FractionalOctaveBand {
  int bands_per_octave = 3;  // b of the bandwidth designator 1/b
  int index = 0;             // x
  double exact = 0.0;        // f_m, Hz
  double lower = 0.0;        // f_1, Hz
  double upper = 0.0;        // f_2, Hz
  double nominal = 0.0;      // Hz
  std::string label;         // the nominal frequency as printed: "31.5", "1000", "12500"
};

// f_m of band x for bandwidth 1/b (b >= 1, else std::invalid_argument).
double exact_mid_band_frequency(int index, int bands_per_octave);
double lower_band_edge(double mid_band, int bands_per_octave);
double upper_band_edge(double mid_band, int bands_per_octave);
// The x whose f_m is nearest to `frequency` (Hz, > 0) on a logarithmic scale.
int nearest_band_index(double frequency, int bands_per_octave);
// The nominal mid-band frequency of band x (Annex E).
double nominal_mid_band_frequency(int index, int bands_per_octave);
// "31.5", "1000", "12500", "6.3": up to six significant figures, no exponent, no trailing zeros.
std::string nominal_label(double nominal);

FractionalOctaveBand fractional_octave_band(int index, int bands_per_octave);
// The bands from the one nearest `f_low` to the one nearest `f_high` (e.g. b = 3, 20 Hz–10 kHz:
// the 28 bands 20 … 10000). Bad arguments are InputErrors: keys "bands_per_octave", "f_low",
// "f_high".
std::vector<FractionalOctaveBand> fractional_octave_bands(int bands_per_octave, double f_low, double f_high);

// A bank of Butterworth band filters (design above), one per band, for one sample rate.
class FractionalOctaveFilterBank {
 public:
  // bands: non-empty, each with 0 < lower < upper < sample_rate/2; order: prototype order, 1..8.
  // Bad arguments are InputErrors: keys "sample_rate", "f_high" (a band reaching fs/2),
  // "filter_order", "bands".
  FractionalOctaveFilterBank(std::vector<FractionalOctaveBand> bands, double sample_rate, int order = 3);

  const std::vector<FractionalOctaveBand>& bands() const noexcept { return bands_; }
  double sample_rate() const noexcept { return sample_rate_; }
  int order() const noexcept { return order_; }

  // Complex response of band i at `frequency` (Hz, 0 <= f <= fs/2); −3.01 dB at the exact edges,
  // and |H(f_m)| = 1 to 1e-7 dB (the prototype's centre lands at f_m up to the warping).
  std::complex<double> response(std::size_t band, double frequency) const;
  double response_db(std::size_t band, double frequency) const;

  // Band i's output for `signal`, the filter starting from rest.
  std::vector<double> filter(std::size_t band, std::span<const double> signal) const;

  // The mean square of every band's output over the samples [skip, signal.size()) (skip: the
  // start-up transient to leave out; the filters run over it). skip >= signal.size() is an
  // InputError with key "settle_time". `cancel` is polled every 65536 samples (Interrupted).
  std::vector<double> band_mean_squares(std::span<const double> signal, std::size_t skip = 0,
                                        const CancellationToken& cancel = {}) const;

 private:
  struct Section {
    double b0, b1, b2, a1, a2;
  };

  std::vector<FractionalOctaveBand> bands_;
  double sample_rate_;
  int order_;
  std::vector<std::vector<Section>> sections_;  // per band
};

// Band mean squares (Pa²) from a PSD by integration over the ideal band edges [f_1, f_2] (see
// above for when this is a valid band realisation). Bands reaching beyond fs/2 are an InputError
// with key "f_high".
std::vector<double> band_mean_squares_from_psd(const PowerSpectralDensity& psd,
                                               const std::vector<FractionalOctaveBand>& bands);

}  // namespace rollnoise
