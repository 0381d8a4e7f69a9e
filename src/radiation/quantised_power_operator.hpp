#pragma once
// The power operator at the precision the sound power needs, in a thirteenth of the room (issue 30:
// at most 50 MB of cache per radiating body, where the operator in doubles took 500 MB).
//
// The stage's power is W = ½ Σ_c ‖Q_c x_c‖² (EquivalentSources::power_operator), Q_c of r_c × t_c
// (r_c the power matrix's numerical rank, up to a few hundred, t_c a quarter of the tread's
// points). For any unitary U_c, ‖U_cᴴ Q_c x‖ = ‖Q_c x‖, so each block is first rotated to its
// left singular basis: B_c = U_cᴴ Q_c, U_c the eigenvectors of Q_c Q_cᴴ (LAPACK zheevd), rows in
// decreasing norm (the singular values, which fall by ten decades over the rank: most patterns
// on the tread radiate almost nothing). Then every real and imaginary part of every block is
// rounded to a multiple of one quantum h = σ₁/32767, σ₁ the anchor's largest singular value
// (which bounds every part, so each fits a 16-bit integer); rows that round to zero are dropped.
// The rows of weak patterns are small integers, which the cache's deflate packs into a few bits
// (radiation_cache.hpp).
//
// What it costs in accuracy: each part moves by at most h/2, so a bin's ‖B x‖ moves by a random
// sum of such steps over the tread's points, relative to ‖B x‖ about h·‖x‖/‖B x‖: small where the
// velocities radiate well, and larger where they radiate a small fraction of what the strongest
// pattern would. Measured on every surface of models/surfaces against the unrounded operator
// (docs/radiation_cache.md, "Precision"): the third-octave bands of the sound power within
// 0.0015 dB, LWA within 0.0002 dB. The receivers' pressures do not depend on it (the
// transfer is kept in doubles), so levels and WAVs at the microphones are unchanged.
//
// The stage applies the quantised operator whether it solved or loaded it, so a run from the
// cache and a run without it agree bit for bit.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

struct QuantisedPower {
  // Per symmetry block: k_c × t_c, every entry's real and imaginary part an integer multiple of
  // `quantum` in [−32767, 32767]·quantum (exactly: integer × quantum in doubles).
  std::vector<Eigen::MatrixXcd> blocks;
  double quantum = 0.0;  // 0 when every block is empty
};

// The blocks Q_c rotated and rounded as above; Σ_c ‖B_c x_c‖² ≈ Σ_c ‖Q_c x_c‖².
QuantisedPower quantise_power_operator(const std::vector<Eigen::MatrixXcd>& blocks);

using Int16Matrix = Eigen::Matrix<std::int16_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A part (real or imaginary) of a quantised block as its integers, and back. integers_of throws
// std::invalid_argument when a value is not an integer multiple of `quantum` within 16 bits.
Int16Matrix integers_of(const Eigen::MatrixXd& part, double quantum);
Eigen::MatrixXd values_of(const Int16Matrix& integers, double quantum);

}  // namespace rollnoise
