#pragma once
// Looping a short simulation into a longer sound without clicks.
//
// Method: the signal is made periodic once, then repeated. Its last L samples (L = the
// crossfade, 50 ms by default) are crossfaded into its first L samples:
//     y[i] = a(i)·x[P+i] + b(i)·x[i]   for i < L,        y[i] = x[i]   for L <= i < P,
// and y (period P) is tiled. At every joint the waveform runs on as it would inside the
// original (y[P-1] = x[P-1] is followed by y[0] ≈ x[P]), so there is no jump, and the fade
// shape s = (1 - cos πu)/2 has zero slope at both ends, so there is no kink either.
// The gains keep the power constant for the measured correlation ρ of the two faded segments
// (a² + b² + 2ρab = 1 with a = g(1-s), b = gs): ρ ≈ 0 for noise gives an equal-power fade,
// ρ ≈ 1 for matching tonal content an equal-gain (linear) one, so the level neither dips nor
// swells at the joints (rolling noise has both: broadband noise and tread-pattern tones).
// The loop point P is chosen within the last few milliseconds to maximise ρ, so tonal
// components join in phase where the signal allows it.
#include <Eigen/Core>
#include <cstddef>

namespace rollnoise {

struct LoopOptions {
  double crossfade_s = 0.05;  // crossfade length; shortened to a quarter of the signal if needed
  double search_s = 0.02;     // how far the loop point may move to find the best match
};

// The periodic version y of `signal` described above (its length is the loop period), scaled
// to the mean power of the whole signal (the period leaves out its last L + d samples; the
// correction is limited to ±0.5 dB).
// Signals shorter than 8 samples are returned unchanged. std::invalid_argument for an empty
// signal or a non-positive sample rate.
Eigen::VectorXd make_loopable(const Eigen::VectorXd& signal, double sample_rate,
                              const LoopOptions& options = {});

// A signal of at least `min_duration_s` made of whole periods of make_loopable(signal), so it
// has exactly the level of one period and itself loops without a click in a player; a signal
// already long enough is returned as is.
Eigen::VectorXd loop_to_duration(const Eigen::VectorXd& signal, double sample_rate,
                                 double min_duration_s, const LoopOptions& options = {});

}  // namespace rollnoise
