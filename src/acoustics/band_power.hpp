#pragma once
// Band powers of sampled signals that are not sound pressures (a road profile, a force, a
// surface velocity), and of fields of many such signals averaged over points: the third-octave
// "energy budget" of a run (issue 10 §1) follows one quantity per stage through them.
//
// Every band power here is a Welch PSD (welch_psd.hpp) integrated over the ideal band edges
// (band_mean_squares_from_psd, fractional_octave_bands.hpp): the same estimator for every line of
// the budget, so that ratios between lines compare like with like. Short records limit it: the
// segment (at most `max_segment`, a power of two, at most the record) sets the resolution fs/N,
// and a band narrower than about 10 bins is smeared by the Hann window's main lobe (±2 bins), by
// up to ~1 dB where the spectrum is steep (fractional_octave_bands.hpp).
//
// Units follow the signal: m² for a profile, N² for a force, (m/s)² for a velocity.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "acoustics/fractional_octave_bands.hpp"
#include "acoustics/welch_psd.hpp"

namespace rollnoise {

// The Welch segment for a record of `samples`: the largest power of two that fits in the record
// and is at most max_segment (>= 8). InputError (key "samples") for records shorter than 8.
std::size_t welch_segment_for(std::size_t samples, std::size_t max_segment = 1024);

// Band mean squares of `signal`, its mean removed first (the fluctuating part only).
std::vector<double> fluctuation_band_mean_squares(std::span<const double> signal, double sample_rate,
                                                  const std::vector<FractionalOctaveBand>& bands,
                                                  std::size_t segment_length);

// Sum of per-bin values (powers, W or Pa², that already sum to the total) over the bins whose
// frequency lies in [lower, upper) of each band. frequency and value have the same length.
std::vector<double> band_sums(std::span<const double> frequency, std::span<const double> value,
                              const std::vector<FractionalOctaveBand>& bands);

// The mean of of_frequency(f) over each band, at `points` evenly spaced midpoints of [lower,
// upper]: a transfer |T(f)|² averaged over a band whose input has a flat density per Hz.
std::vector<double> band_means_of(const std::vector<FractionalOctaveBand>& bands,
                                  const std::function<double(double)>& of_frequency, int points = 8);

// 10 lg(mean_square / reference²) dB; −∞ for 0.
double level_db(double mean_square, double reference);

// The Welch PSD of every one of P signals, averaged over the points with weights, for signals
// that arrive one sample of all points at a time (a field over time: nothing but one segment of
// it is kept). Each average a has weights w_a,p >= 0 (normalised to sum 1). Segments of N
// samples start at 0, N/2, N, … exactly as welch_psd's, so average(a) equals Σ_p w_a,p ·
// welch_psd(signal_p, fs, N) of the whole records, to the single precision of the buffer (P·N
// floats). Each segment's periodogram is, bit for bit, welch_psd's of that segment as buffered,
// with one window and one FFT plan made here: push() allocates nothing.
class PointAveragedPsd {
 public:
  PointAveragedPsd(std::size_t points, double sample_rate, std::size_t segment_length,
                   std::vector<std::vector<double>> weights);

  // The next sample of every point (size P).
  void push(std::span<const double> sample);
  std::size_t segments() const noexcept { return segments_; }
  // The weighted mean PSD of average a (density ÷ segments). InputError (key "samples") before
  // the first full segment.
  PowerSpectralDensity average(std::size_t a) const;

 private:
  std::size_t points_;
  double sample_rate_;
  std::size_t length_;
  std::vector<std::vector<double>> weights_;
  std::vector<char> used_;  // per point: a positive weight in some average
  WelchSegment segment_;
  std::vector<double> power_;  // one segment's |X|², then its density (scratch)
  // Points gathered at a time (N × kBlock floats, 256 KB at N = 1024: within L2): each buffered
  // row is a page or more apart, so a gather pass misses the TLB once per row; 64 points a pass
  // (256 bytes a row, copied whole) make a quarter of the 16-point passes' misses (perf: the
  // gather had been most of push()'s time on the 32 760 belt cells of the 50 km/h grid).
  static constexpr std::size_t kBlock = 64;
  std::vector<float> buffer_;    // the last N samples: sample t in row t mod N, P floats a row
  std::vector<float> gathered_;  // N × kBlock: row i holds sample i of the segment of kBlock points
  std::size_t pushed_ = 0;
  std::size_t segments_ = 0;
  std::vector<std::vector<double>> sums_;  // per average, Σ_segments Σ_p w·P[k]
};

}  // namespace rollnoise
