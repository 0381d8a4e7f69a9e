#pragma once
// Sample-rate conversion with libsamplerate's best sinc converter (SRC_SINC_BEST_QUALITY:
// 97 dB stop-band attenuation, 96 % pass band). The output is time-aligned with the input
// (sample k of the output is at time k / fs_out) and exactly round(n · fs_out / fs_in) long.
// Ratios beyond libsamplerate's 1/256 ... 256 are done in equal stages.
#include <Eigen/Core>

#include "core/cancellation.hpp"

namespace rollnoise {

// The standard audio rates the program writes.
inline constexpr double audio_rate_48k = 48000.0;
inline constexpr double audio_rate_44k1 = 44100.0;

// Resamples `signal` from fs_in to fs_out (Hz, positive and finite; std::invalid_argument
// otherwise). Equal rates return a copy. Computation is in single precision, as libsamplerate
// works (relative error ~1e-7, far below the converter's own 97 dB). `cancel` is polled between
// pieces of output (Interrupted).
Eigen::VectorXd resample(const Eigen::VectorXd& signal, double fs_in, double fs_out,
                         const CancellationToken& cancel = {});

}  // namespace rollnoise
