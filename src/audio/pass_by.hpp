#pragma once
// Pass-by auralisation: the sound of a tyre driving past a roadside microphone, made from the
// sound the same tyre gives at that microphone while standing abeam of it.
//
// Geometry (ISO 11819-1, Statistical Pass-By): the microphone stands 7.5 m from the centre of
// the lane and 1.2 m above the road; the vehicle drives along a straight line at a constant
// speed V. Here the road is the plane z = 0, the wheel path the x axis, the receiver is at
// (0, d, h_r) and the tyre at (V·(t − T/2), 0, h_s), so it is abeam at the middle of an output
// T long. The tyre's noise is radiated from near the contact patch (the horn effect), so it is
// one omnidirectional point source just above the road, plus its image in the road (height
// −h_s) weighted by the pressure reflection coefficient R (1: a rigid, dense road), one real
// number; or, over an absorbing road, filtered by the spherical-wave reflection factor
// Q(f, ρ) = 1 + C/E of the impedance plane at the horizontal distance ρ between the tyre, where
// it was when it emitted, and the receiver (radiation/impedance_plane_green.hpp: the exact
// field's correction C to the rigid image E = e^{−ikR₂}/(4πR₂), so that direct + Q·image is the
// exact field there). As the tyre moves away the incidence grows more grazing and Q changes,
// and as it moves the reflected wave's frequency in the air is Doppler-shifted: the image path
// reads the source filtered by Q at the distance and the shifted frequency of its emission
// (audio/moving_image_filter.hpp: Q as a Chebyshev series in log ρ on each side of the closest
// approach, exact there).
//
// Each path is the field of a moving source, q(t_e)/r(t_e), taken at the emission time t_e
// that satisfies t = t_e + r(t_e)/c. Reading the source at t_e gives the Doppler shift
// f/(1 − M cos θ) exactly (M = V/c, θ between the velocity and the source → receiver
// direction at emission) and the distance (−20 dB per decade) from where the tyre was when
// it emitted, not where it is when heard. The convective amplification of a moving monopole
// (a further factor (1 − M cos θ)^−1, within ±0.8 dB at 30 m/s) is not applied: the input is
// a pressure at the receiver, not a source strength, and the factor is small at road speeds.
//
// q is the input with the two paths' interference at the closest approach divided out, so that
// the paths there give the input back at every frequency: the input is what the stationary
// microphone hears, and already holds the road's reflection (the ground dip, and over an
// absorbing road its ground effect), which the paths would otherwise apply a second time. Bin by
// bin, q = source · (1/r1_0 + R/r2_0)^−1 · E(f), E = (1/r1_0 + R/r2_0)/(1/r1_0 + Q0(f)e^{−ikΔr}/r2_0)
// with r1_0, r2_0 the two path lengths abeam, Δr their difference, Q0 = R or the reflection
// factor abeam. Away from the closest approach the interference changes as the geometry does.
#include <complex>
#include <functional>

#include <Eigen/Core>

#include "core/cancellation.hpp"

namespace rollnoise {

struct PassBySettings {
  using ReflectionFactor = std::function<std::complex<double>(double frequency, double horizontal_distance)>;
  double speed = 0.0;              // m/s, > 0: the vehicle's speed along the road (x)
  double receiver_distance = 7.5;  // m from the wheel path (ISO 11819-1 SPB)
  double receiver_height = 1.2;    // m
  double source_height = 0.02;     // m: the tyre's effective source, near the contact (horn)
  double duration = 5.0;           // s: length of the output; the closest approach is at its middle
  double sound_speed = 343.2;      // m/s
  double ground_reflection = 1.0;  // pressure reflection coefficient of the road, 0..1 (1: rigid)
  // Over an absorbing road: Q at a frequency (Hz > 0) and a horizontal distance between source
  // and receiver (m, >= receiver_distance), for time dependence e^{+iωt}, which filters the
  // image path (above; the looped source, by its discrete Fourier transform) instead of
  // ground_reflection, which must then be 1. Q → 1 at low frequency for a porous layer over a
  // rigid base, so the normalisation below takes R = 1. Empty: the real R.
  ReflectionFactor ground_reflection_factor;
  CancellationToken cancel;        // polled every 65536 output samples (Interrupted)
};

// The pressure (Pa) at the receiver as the tyre drives past, sampled at `sample_rate` (Hz),
// round(duration · sample_rate) samples; sample n is at t = n / sample_rate.
//
// `source` is the pressure signal the stationary tyre gives at the receiver abeam at the
// closest approach (what the stationary SPB receiver computes), sampled at the same rate. It
// is treated as periodic (looped), so it may be shorter than the pass-by; pass a
// make_loopable() period (audio/seamless_loop.hpp) so that the joint does not click. Time is
// aligned so that a source standing abeam gives back `source` exactly: the signal emitted at
// t_e is source((t_e + r1_0/c) · sample_rate) along the direct path.
//
// The emission times are solved in closed form (straight line, constant speed) and the source
// is read between samples with 6-point Lagrange interpolation: the error for a tone is below
// −95 dB at 3 kHz, −77 dB at 4.3 kHz (3 kHz Doppler-shifted at M = 0.3) and −60 dB at 6 kHz
// for a 48 kHz source.
//
// std::invalid_argument (naming the parameter) for an empty or non-finite source, a
// non-positive or non-finite sample rate, speed not in (0, 0.3 · sound_speed) (the limit keeps
// the Doppler-compressed source well inside the interpolator's accurate band), a non-positive
// receiver distance, negative heights, a non-positive duration or one shorter than a sample,
// a non-positive sound speed, a ground reflection outside [0, 1], or a reflection factor with a
// ground reflection other than 1 or giving a non-finite value.
Eigen::VectorXd pass_by(const Eigen::VectorXd& source, double sample_rate,
                        const PassBySettings& settings);

}  // namespace rollnoise
