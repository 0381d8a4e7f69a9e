#pragma once
// Vector fitting: a scalar frequency response sampled at real angular frequencies, turned into
// the pole–residue form (pole_residue_response.hpp)
//   α(ω) ≈ d + Σ_r ρ_r/(iω − p_r),   s = iω (the convention α(ω) = ∫ h e^{−iωt} dt),
// with a real, causal and stable impulse response: real poles, or conjugate pairs with conjugate
// residues, all with Re p < 0, and a real d (or d = 0).
//
// The method is the relaxed vector fitting of Gustavsen & Semlyen (IEEE Trans. Power Delivery
// 14(3) 1999 1052–1061, "GS99") with the relaxed non-triviality constraint of Gustavsen (IEEE
// Trans. Power Delivery 21(3) 2006 1587–1592, "G06"), in its real formulation (GS99 appendix):
//   1. Pole relocation. With the current poles a_j an unknown scaling function
//      σ(s) = d̃ + Σ c̃_j φ_j(s) is fitted together with (σα)(s) ≈ d + Σ c_j φ_j(s), linearly:
//      Σ c_j φ_j + d − α_k (Σ c̃_j φ_j + d̃) = 0 at every sample, weighted, plus G06's
//      constraint Re Σ_k σ(s_k) = K that leaves d̃ free (relaxed) instead of fixing d̃ = 1. The
//      zeros of σ are the new poles: the eigenvalues of A − b c̃ᵀ/d̃, A and b the real state-space
//      form of the current poles (GS99's appendix).
//   2. Unstable new poles are flipped into the left half-plane (GS99).
//   3. Residue identification: with the poles fixed, c and d by linear least squares.
// Every least-squares problem is solved with column scaling and a column-pivoting QR (Eigen):
// with ω from 1 Hz to 50 kHz the basis columns 1/(s − a) differ by orders of magnitude.
//
// fit_pole_residue raises the order until a target error is met. It is meant for many small fits
// (every mode of a tyre: ~10⁴ fits of 100–150 samples with 4–16 poles), so it keeps no state and
// allocates only its working matrices.
#include <complex>
#include <limits>
#include <span>
#include <vector>

#include "greens/pole_residue_response.hpp"

namespace rollnoise {

enum class FitWeighting {
  relative,  // weight 1/|α(ω_k)|: every sample fitted to the same relative accuracy
  uniform,   // weight 1: the absolute error
};

enum class StartingPoleSpacing { logarithmic, linear };

struct VectorFittingOptions {
  int starting_pole_pairs = 2;   // complex pairs of the first order tried
  int real_poles = 0;            // real starting poles (≥ 0; relocation may pair real poles or split pairs)
  int maximum_pole_pairs = 8;    // the order is raised up to 2·maximum_pole_pairs + real_poles poles
  int iterations = 6;            // pole relocations per order at most (≥ 1)
  double target_rms_error = 1e-3;  // relative RMS error at which the driver stops
  double target_max_error = std::numeric_limits<double>::infinity();  // and the largest relative error
  FitWeighting weighting = FitWeighting::relative;
  StartingPoleSpacing spacing = StartingPoleSpacing::logarithmic;
  bool fit_direct = true;  // false: d = 0 (a response that vanishes as ω → ∞)
};

struct VectorFittingResult {
  PoleResidueResponse response;
  // Over the samples: e_k = |fit(ω_k) − α_k|/|α_k| (a sample with α_k = 0 is measured against the
  // RMS of |α|); rms_error = √(mean e_k²), max_error = max e_k.
  double rms_error = 0.0;
  double max_error = 0.0;
  bool converged = false;  // both targets met
  std::size_t pole_count() const noexcept { return response.size(); }
};

// Gustavsen's starting poles (GS99): `pairs` lightly damped pairs p = −β/100 ± iβ with
// β spread logarithmically (or linearly) over [omega_low, omega_high], then `real` real poles
// −β spread the same way. Ordered as PoleResidueResponse stores them: each pair as p, conj(p).
std::vector<std::complex<double>> starting_poles(double omega_low, double omega_high, int pairs, int real,
                                                 StartingPoleSpacing spacing = StartingPoleSpacing::logarithmic);

// One order: `iterations` relocations from the given starting poles (stable, conjugate pairs
// adjacent as p, conj(p)), then the residues. The result of the iteration with the smallest
// RMS error is returned; `converged` reports the targets of `options`.
VectorFittingResult vector_fit(std::span<const double> omega, std::span<const std::complex<double>> response,
                               std::span<const std::complex<double>> initial_poles,
                               const VectorFittingOptions& options);

// The driver: vector_fit from starting_poles(options.starting_pole_pairs, options.real_poles)
// over the sampled band (the lowest nonzero ω to the highest); while the targets are not met, the
// order is raised — the poles found plus new pairs where the error peaks, a quarter more poles
// (at least one pair) at a time — up to 2·options.maximum_pole_pairs + options.real_poles poles
// or as many as the samples carry. Returns the first fit that meets the targets, otherwise the
// one with the smallest RMS error (converged = false).
// ω_k ≥ 0 strictly increasing (ω = 0 is the static value, whose imaginary part a real h cannot
// carry and which is then not fitted), at least 3 samples, all finite; relative weighting needs
// every α_k ≠ 0. std::invalid_argument for bad input, with what is wrong.
//
// The errors are those at the samples. Between them the fit is unconstrained: a resonance
// narrower than the sample spacing, or a fit with nearly as many unknowns as equations, can be
// far off there (the passenger two-layer tyre's modes on 120 log-spaced samples: see
// tests/greens/test_vector_fitting.cpp). Check on a finer grid when that matters.
VectorFittingResult fit_pole_residue(std::span<const double> omega, std::span<const std::complex<double>> response,
                                     const VectorFittingOptions& options = {});

}  // namespace rollnoise
