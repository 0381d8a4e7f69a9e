#pragma once
// A response in pole–residue form (MODEL.md §1 convention α(ω) = ∫ h e^{−iωt} dt):
//   h(t) = d·δ(t) + Σ_r ρ_r e^{p_r t}  (t ≥ 0),     α(ω) = d + Σ_r ρ_r/(iω − p_r),
// with every pole stable (Re p_r < 0) and complex poles present with their conjugates (with
// conjugate residues), so that h is real. It is the common currency of the rolling tyre
// (rolling_modes.hpp): every mode of a translation-invariant tyre model is handed over in this
// form, the plate's exactly (an oscillator is a conjugate pair, or two real poles when
// over-damped) and tabulated or layered models through a fit (vector_fitting.hpp).
//
// Seen from a load that the body carries past at phase e^{iωτ} (a mode e^{ikx} of a tyre rolling
// at v, ω = k·v), each term stays a first-order exponential with the shifted rate q = p + iω:
//   ∫_{t0}^{t1} e^{iωτ} ρ e^{pτ} dτ = ρ (e^{q t1} − e^{q t0})/q,
// so step integrals, the exact one-state recursion per pole and the steady (all-lag) total
// −ρ/q are closed forms.
#include <complex>
#include <vector>

namespace rollnoise {

struct SdofOscillator;

struct PoleResidueResponse {
  std::vector<std::complex<double>> poles;     // p_r, 1/s, Re p_r < 0
  std::vector<std::complex<double>> residues;  // ρ_r, m/(N·s) (or per modal unit)
  double direct = 0.0;                         // d, m/N: the instantaneous part

  std::size_t size() const noexcept { return poles.size(); }
  // α(ω) = d + Σ ρ/(iω − p), m/N; ω = 0 is the static compliance.
  std::complex<double> receptance(double omega) const;
  // h(t) without the δ part (0 for t < 0), m/(N·s).
  double impulse_response(double t) const;
  // ∫_{t0}^{t1} e^{iωτ} h(τ) dτ for 0 ≤ t0 ≤ t1, the δ part included when t0 = 0.
  std::complex<double> phase_integral(double omega, double t0, double t1) const;
  // ∫_0^∞ e^{iωτ} h dτ = α(−ω): the compliance of steady rolling.
  std::complex<double> steady_total(double omega) const { return receptance(-omega); }
  // Throws std::invalid_argument unless every pole is stable and finite, residues are finite,
  // sizes agree and the poles come in conjugate pairs with conjugate residues (relative
  // tolerance 1e-9).
  void validate() const;
};

// The oscillator's impulse response as poles: under-damped, a conjugate pair
// p = −a ± iω_d, ρ = ∓i/(2mω_d); over-damped, two real poles −a ± β with ρ = ±1/(2mβ).
// Critical damping (a double pole) is split into two real poles 1e-6·a apart.
PoleResidueResponse oscillator_poles(const SdofOscillator& oscillator);

}  // namespace rollnoise
