#pragma once
// The image path of a tyre driving past a receiver over an absorbing road: the looped source
// filtered by the spherical-wave reflection factor Q of the geometry at which it emits.
//
// Q(f, ρ) = 1 + C/E (radiation/impedance_plane_green.hpp) depends on the horizontal distance ρ
// between the tyre and the receiver, which the pass-by sweeps from the closest approach d to
// tens of metres, and, because the source moves, on the frequency the reflected wave has in the
// air at rest: the emitted f times the Doppler factor 1/(1 − M cos θ₂) along the image path
// (approaching: higher; receding: lower). Along the road, at x from the closest approach, it is
// a smooth function of η = asinh(x/d) (near x: linear; far: log ρ), so it is written as a
// Chebyshev series in η over the emission positions of the pass-by,
//     Q(f_r(f, x), ρ(x)) = Σ_k a_k(f) T_k(ξ(η(x))),
// and, filtering being linear, the image signal is Σ_k T_k(ξ(x_e)) · (a_k ∗ source)(t_e): a few
// filtered copies of the source, blended sample by sample with the polynomials' values at the
// emission's position. (In ρ the Doppler factor has a square-root branch at the closest
// approach, and a series in log ρ converged only as 1/N.) The degree is doubled from 8 until the
// series meets Q at the points between its nodes within kSeriesTolerance (absolute; |Q| <= about
// 1), everywhere on a grid of kFactorsPerOctave frequencies to the octave, between which Q is
// interpolated linearly in log frequency (its structure, the road's admittance and a numerical
// distance that grows as √f, is an octave or more wide).
#include <complex>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

// `response` sampled at MovingImageFilter::kFactorsPerOctave frequencies to the octave from
// bin 1 (sample_rate/n) to Nyquist, interpolated linearly in log frequency to bins 1 ... n/2 of
// an n-point real transform (element m: bin m; element 0, the mean, is response's value at bin 1's
// frequency). std::invalid_argument if it is not finite somewhere.
std::vector<std::complex<double>> response_on_bins(int n, double sample_rate,
                                                   const std::function<std::complex<double>(double)>& response);

// The looped (periodic) signal `source`'s transform, made with `fft` (an n-point real transform,
// n = source.size(), one transform).
Eigen::VectorXcd looped_spectrum(RealFftBatch& fft, const Eigen::VectorXd& source);

// The looped signal of transform `spectrum` filtered: bin m times gain(m) (FFTW's forward
// transform has e^{−iωt}, so a bin is the amplitude of e^{+iωt}, the convention of the gains),
// back in time. The circular convolution, exact for the periodic signal the pass-by reads;
// Nyquist's bin of an even n takes the real part of its gain, as it must stay real.
Eigen::VectorXd filtered_loop(RealFftBatch& fft, const Eigen::VectorXcd& spectrum,
                              const std::function<std::complex<double>(int bin)>& gain);

class MovingImageFilter {
 public:
  // Q at a frequency in the air (Hz) and a horizontal distance (m).
  using Factor = std::function<std::complex<double>(double frequency, double horizontal_distance)>;

  static constexpr double kFactorsPerOctave = 96.0;
  static constexpr double kSeriesTolerance = 1e-4;
  static constexpr int kMostTerms = 129;

  struct Geometry {
    double closest = 0.0;       // m, d > 0: the horizontal distance abeam
    double first = 0.0;         // m along the road: the first emission position (< last)
    double last = 0.0;          // m: the last
    double image_height = 0.0;  // m, h_r + h_s: the image path's vertical extent
    double mach = 0.0;          // V/c, [0, 0.3)
  };

  // `source`: the looped pressure signal at `sample_rate` (Hz). std::invalid_argument if Q is
  // not finite somewhere, or the series does not converge within kMostTerms terms.
  MovingImageFilter(const Eigen::VectorXd& source, double sample_rate, const Geometry& geometry, const Factor& factor);

  // The image path's signal at fractional source sample `u` (pass_by.hpp's time base) for a
  // tyre that emitted it at position `x` along the road (m; negative before the closest approach).
  double at(double x, double u) const;

 private:
  double position(double node) const;  // x (m) at ξ = node

  Geometry geometry_;
  double eta_first_ = 0.0;
  double eta_last_ = 1.0;
  std::vector<Eigen::VectorXd> filtered_;  // a_k ∗ source, k = 0 ... terms − 1
};

}  // namespace rollnoise
