#pragma once
// The time window of the velocities whose transform gives the radiated sound power
// (tyre_radiation.hpp: TyreRadiation::radiate for a whole record, TyreRadiationStream for each
// block), and its normalisation.
//
// Why a window. The power of a bin is W = ½qᴴSq of the bin's velocity spectrum (Parseval turns
// the bins into the record's mean power), and a quadratic estimate does not forgive what a
// record holds at its ends:
//  - a rolling run starts from the static tyre, and the sudden start rings through the belt for
//    about 10 ms: on pa16 at 50 km/h the tread's velocity above 1 kHz was 30 dB above its
//    steady level in the first 0.5 ms, still 5 dB above at 7–10 ms;
//  - the record's cut ends are steps in the velocity, whose spectrum falls only as 1/f².
// The microphones' band levels (band filters, the record's first tenth left out:
// simulation/sound_report.cpp) and the energy budget's ⟨v²⟩ (Welch, Hann segments:
// acoustics/band_power.hpp) weigh both next to nothing. The untapered transform weighed them fully: in a
// 0.1 s run that was 10–16 dB of velocity above 800 Hz that the steady rolling does not have
// (pa16, 50 km/h), so the power of those bands stood that far above what the microphones and
// the budget's ⟨v²⟩ said, and σ = W/(ρcS⟨v²⟩) came out at up to 17.
//
// The window: cosine ramps over `ramp` samples at both ends, 1 between (a Tukey window; a Hann
// window when the record is shorter than two ramps). Its first derivative is continuous, so what
// is left of an edge falls as 1/f⁶ in power. The mean power of a record of N samples from the
// windowed transform X_k of length L is Σ_k ½qᴴSq·4/(L·Σw²) over the bins (Parseval, with Σw²
// in place of N): for a stationary signal the same as the untapered record's, and what the
// microphones' band levels give within a few tenths of a decibel in a band of many bins
// (tests/radiation/test_sound_power_far_field.cpp: a hemisphere of microphones, 0.31 dB).
#include <Eigen/Core>

namespace rollnoise {

// The window w (`samples` values) with ramps of min(ramp, samples / 2) samples at each end.
// samples >= 1, ramp >= 0 (0: w = 1, the plain record); std::invalid_argument otherwise.
Eigen::VectorXd power_taper(Eigen::Index samples, Eigen::Index ramp);

}  // namespace rollnoise
