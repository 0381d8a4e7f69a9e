#pragma once
// One-sided power spectral density of a sampled pressure signal by Welch's method (P. D. Welch,
// IEEE Trans. Audio Electroacoust. 15, 1967): the signal is cut into segments of N samples
// overlapping by 50 %, each is multiplied by a periodic Hann window
//   w[n] = ½ (1 − cos(2π n/N)),  n = 0 .. N−1,
// and the squared magnitudes of their DFTs are averaged. Scaling (Pa²/Hz, one-sided):
//   P[k] = c_k |X[k]|² / (fs Σ w²),  c_k = 1 at k = 0 and k = N/2, 2 in between,
// so that by Parseval Σ_k P[k]·Δf (Δf = fs/N) equals the window-weighted mean square of each
// segment, Σ (w x)² / Σ w², averaged over the segments. For a stationary signal that is the mean
// square (unbiased); it is not the plain mean square of the record, because the Hann window
// weights each segment's middle more than its ends and 50 % overlap does not even this out for
// w² (the summed weight Σ_m w²[n − mN/2] ripples by ±1/3 about its mean). The Hann window at
// 50 % overlap is the usual compromise (Harris, Proc. IEEE 66, 1978): −31 dB first side lobe,
// equivalent noise bandwidth 1.5 Δf, and nearly independent segments (overlap correlation 17 %).
//
// Segments start at 0, N/2, N, …; samples after the last full segment are not used. The mean is
// not removed (an acoustic pressure has none; a DC offset appears in bins 0 and 1).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <fftw3.h>

#include "core/fftw_plan.hpp"

namespace rollnoise {

struct PowerSpectralDensity {
  double sample_rate = 0.0;        // Hz
  std::size_t segment_length = 0;  // N
  std::size_t segments = 0;        // number of segments averaged
  std::vector<double> density;     // Pa²/Hz at f_k = k·resolution(), k = 0 .. N/2

  // Bin spacing Δf = fs/N (Hz).
  double resolution() const { return sample_rate / static_cast<double>(segment_length); }
  double frequency(std::size_t k) const { return resolution() * static_cast<double>(k); }
  // Equivalent noise bandwidth of one bin (Hz): fs Σw²/(Σw)² = 1.5 Δf for the Hann window.
  double equivalent_noise_bandwidth() const { return 1.5 * resolution(); }
};

// One segment's windowed transform, made once and reused (its window, buffers and FFTW plan):
// what welch_psd does per segment, for callers that transform many segments of one length
// (PointAveragedPsd: every belt cell's segment, every half segment of a run; making a plan and
// a window per call was most of a tyre run's response stage, issue 12).
class WelchSegment {
 public:
  // segment_length: even, >= 8 (InputError "segment_length" otherwise).
  explicit WelchSegment(std::size_t segment_length);
  std::size_t length() const noexcept { return n_; }
  double window_power() const noexcept { return window_power_; }  // Σ w²
  // Adds |X[k]|² of the windowed segment x[0 .. N) to power[k], k = 0 .. N/2. No allocation.
  // It transforms in the object's own buffers: one object per thread.
  template <class Sample>
  void add_power(const Sample* x, std::span<double> power) const {
    add_power(x, 1, power);
  }
  // The same for a segment whose samples lie `stride` apart: x[0], x[stride], … (a tile of
  // several signals' segments interleaved; the same operations as add_power).
  template <class Sample>
  void add_power(const Sample* x, std::size_t stride, std::span<double> power) const {
    for (std::size_t i = 0; i < n_; ++i) in_.get()[i] = window_[i] * static_cast<double>(x[i * stride]);
    transform_and_add(power);
  }
  // Turns Σ |X[k]|² over `segments` segments into the one-sided density (per Hz) in place: the
  // power of the negative frequencies folded onto the positive ones (factor 2), except at DC
  // and Nyquist, which have no mirror.
  void to_one_sided_density(std::span<double> power, double sample_rate, std::size_t segments) const;

 private:
  void transform_and_add(std::span<double> power) const;
  struct FftwFree {
    void operator()(void* p) const noexcept { fftw_free(p); }
  };
  std::size_t n_;
  std::vector<double> window_;
  double window_power_ = 0.0;
  std::unique_ptr<double[], FftwFree> in_;
  std::unique_ptr<fftw_complex[], FftwFree> out_;
  std::unique_ptr<FftwPlan> plan_;
};

// The Welch estimate with segments of `segment_length` samples (even, >= 8, at most the signal's
// length). sample_rate: Hz, finite, > 0. Bad arguments are InputErrors with keys "sample_rate" and
// "segment_length".
PowerSpectralDensity welch_psd(std::span<const double> signal, double sample_rate, std::size_t segment_length);

// ∫ P df over [f_low, f_high] (Pa²), each bin k taken as a constant density over
// [(k − ½)Δf, (k + ½)Δf] (so the DC and Nyquist bins reach half a bin beyond [0, fs/2]). Partly
// covered bins count in proportion. Over (−∞, ∞) this is Σ P[k] Δf, the mean square by Parseval.
double integrate_psd(const PowerSpectralDensity& psd, double f_low, double f_high);

// Σ_k P[k] Δf: the whole power (Pa²).
double total_power(const PowerSpectralDensity& psd);

}  // namespace rollnoise
