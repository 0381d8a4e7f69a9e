#pragma once
// Sound levels of a sampled pressure signal p(t) (Pa) as IEC 61672-1:2013 defines them
// (clause 3, definitions of time-weighted and time-averaged sound level), and band spectra.
//
//  - Time-averaged (equivalent continuous) sound level over the record, frequency weighting W:
//      L_Weq = 10 lg[ (1/T) ∫ p_W²(t) dt / p0² ],   p0 = 20 µPa;
//    sampled: the mean of p_W² over the samples. Leq is Z-weighted (no weighting), LAeq A-weighted.
//  - Exponential time weighting, time constant τ (F: 0.125 s, S: 1 s):
//      L_Wτ(t) = 10 lg[ (1/τ) ∫_{−∞}^{t} p_W²(ξ) e^{−(t−ξ)/τ} dξ / p0² ],
//    sampled: y[n] = a y[n−1] + (1 − a) p_W²[n], a = e^{−1/(fs τ)}, which is that integral exactly
//    for p_W² held constant over each sample interval, and passes a constant p² unchanged.
//    It starts from rest (silence before the record). LAFmax is the maximum of L_AF over the record.
//    A tone burst of duration T_b from silence, steady level L, reaches L + 10 lg(1 − e^{−T_b/τ})
//    (the reference toneburst response of IEC 61672-1:2013).
//  - Band spectra: fractional-octave band levels L_p per band (fractional_octave_bands.hpp), and
//    their A-weighted values L_pA = L_p + A(f_m), A at the exact mid-band frequency
//    (frequency_weighting.hpp): the frequency-domain weighting, which needs no time-domain filter
//    and so holds at any sample rate that carries the band.
//
// Levels of a zero mean square are −∞ dB.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "acoustics/frequency_weighting.hpp"
#include "acoustics/fractional_octave_bands.hpp"

namespace rollnoise {

// p0, the reference sound pressure in air (IEC 61672-1; ISO 80000-8): 20 µPa.
inline constexpr double reference_sound_pressure = 20e-6;
// Time constants of the exponential time weightings F and S (IEC 61672-1:2013): s.
inline constexpr double fast_time_constant = 0.125;
inline constexpr double slow_time_constant = 1.0;

// Mean of p² (Pa²). An empty signal is std::invalid_argument.
double mean_square(std::span<const double> pressure);
// 10 lg(mean_square / p0²) (dB re 20 µPa); −∞ for 0.
double sound_pressure_level_db(double mean_square_pa2);

// Leq: the Z-weighted time-averaged level over the whole record.
double leq_db(std::span<const double> pressure);
// L_Weq with weighting W applied by WeightingFilter at `sample_rate` (from rest).
double weighted_leq_db(std::span<const double> pressure, double sample_rate, FrequencyWeighting weighting);
// LAeq.
double laeq_db(std::span<const double> pressure, double sample_rate);

// L_Wτ(t_n) at every sample (dB), weighting then exponential time weighting from rest.
// time_constant: s, finite, > 0 (InputError, key "time_constant"). Polls Ctrl-C (the default
// CancellationToken) as it goes, like the weighting's filter.
std::vector<double> time_weighted_levels_db(std::span<const double> pressure, double sample_rate,
                                            FrequencyWeighting weighting, double time_constant);
// The maximum of time_weighted_levels_db.
double max_time_weighted_level_db(std::span<const double> pressure, double sample_rate, FrequencyWeighting weighting,
                                  double time_constant);
// LAFmax: A weighting, F time weighting (τ = 0.125 s).
double lafmax_db(std::span<const double> pressure, double sample_rate);

struct BandSpectrumOptions {
  enum class Method {
    filter_bank,  // Butterworth band filters in the time domain (the IEC 61260-1 realisation)
    welch,        // integration of a Welch PSD over the ideal band edges (long stationary signals)
  };
  int bands_per_octave = 3;
  double f_low = 20.0;     // Hz: the bands from the one nearest f_low …
  double f_high = 10000.0;  // … to the one nearest f_high
  Method method = Method::filter_bank;
  int filter_order = 3;  // Butterworth prototype order of the band filters (filter_bank)
  // s: the start of the record left out of the band averages, for the filters' start-up
  // transient (filter_bank). The lowest band's envelope decays as e^{−t π B/2}, B its bandwidth
  // in Hz (third octave at 20 Hz: B = 4.6 Hz, 1/e in 0.14 s), so ~1 s suffices from 20 Hz up.
  double settle_time = 0.0;
  // Samples per Welch segment (even); 0: the smallest power of two whose resolution fs/N is at
  // most a tenth of the lowest band's width (welch).
  std::size_t welch_segment_length = 0;
  // Polled as the band filters run (filter_bank): Interrupted when cancelled.
  CancellationToken cancel;
};

struct BandSpectrum {
  int bands_per_octave = 3;
  std::vector<double> nominal_hz;  // nominal mid-band frequencies
  std::vector<std::string> labels;  // "31.5", "1000", …
  std::vector<double> exact_hz;    // exact mid-band frequencies f_m
  std::vector<double> lp_db;       // band sound pressure levels, dB re 20 µPa
  std::vector<double> lpa_db;      // lp_db + A(f_m)
};

// The band spectrum of `pressure` (Pa) sampled at `sample_rate`. Bad options are InputErrors
// with the option's name as key ("f_high", "settle_time", "welch_segment_length", …).
BandSpectrum band_spectrum(std::span<const double> pressure, double sample_rate, const BandSpectrumOptions& options = {});

}  // namespace rollnoise
