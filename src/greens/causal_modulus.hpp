#pragma once
// A causal, passive complex modulus with a nearly constant loss factor, for the layers of the
// two-layer tyre (MODEL.md §4).
//
// Why not the constant hysteretic modulus E(1 + iη): its impulse response starts before the
// load (it violates Kramers–Kronig), so the time-domain Green's functions would have a
// precursor. Kelvin–Voigt E(1 + iωτ) is causal but its loss grows ∝ ω (η = 1 at ten times the
// reference for η = 0.1), and the standard linear solid's loss peaks within a decade. Rubber and
// rubber–cord composites show a loss factor that varies slowly over the acoustic band.
//
// The form used: a box relaxation spectrum (Liu, Anderson & Kanamori, Geophys. J. R. astr. Soc.
// 47 (1976) 41–58), i.e. a continuous, positive superposition of Debye (Maxwell–Zener)
// relaxations with relaxation times evenly spread in ln τ between τ1 = 1/(2π f_hi) and
// τ2 = 1/(2π f_lo):
//
//   C*(ω) = C_ref · ψ(ω),   ψ(ω) = ψ0 · [1 + c · ln((1 + iωτ2)/(1 + iωτ1))]
//
// (time dependence e^{iωt}, as everywhere in rollnoise: α(ω) = ∫ g(t) e^{−iωt} dt). Each Debye
// term iωτ/(1 + iωτ) is causal with its pole at ω = i/τ, in the upper half-plane, and ψ is
// analytic in the closed lower half-plane, so ψ(ω − iσ) may be evaluated for the exponential
// window of the time transform. Im ψ ≥ 0 for ω ≥ 0 (passive). ψ(0) = ψ0 is real: the relaxed
// (static) modulus, reached exactly at ω = 0.
//
// The two constants follow from the loss factor η at the reference frequency f_ref = 1 kHz:
// ψ(ω_ref) = 1 + iη exactly, i.e. C_ref is the storage modulus at 1 kHz and η = Im/Re there:
//   c = η / (Im L_ref − η Re L_ref),  ψ0 = 1/(1 + c Re L_ref),  L_ref = ln((1 + iω_ref τ2)/(1 + iω_ref τ1)).
// With the band 10 Hz – 100 kHz the loss factor stays within about ±12 % of η over 100 Hz – 5 kHz
// (η = 0.1: 0.111 at 100 Hz, 0.100 at 1 kHz, 0.089 at 5 kHz), and the static modulus is
// C_ref·ψ0 (ψ0 = 0.70 for η = 0.1, 0.85 for η = 0.05: the dispersion that Kramers–Kronig
// demands of a nearly constant loss). A loss factor at or above Im L_ref / Re L_ref ≈ 0.337
// cannot be carried by this band (the static modulus would not be positive) and is rejected.
#include <complex>

namespace rollnoise {

class CausalModulus {
 public:
  static constexpr double reference_frequency = 1000.0;  // Hz: C_ref and η hold here
  static constexpr double band_low = 10.0;               // Hz: 1/(2π τ2)
  static constexpr double band_high = 1.0e5;             // Hz: 1/(2π τ1)

  // η ≥ 0 at the reference frequency; std::invalid_argument if η is negative, not finite or
  // at least largest_loss_factor().
  explicit CausalModulus(double loss_factor);

  // The largest loss factor the band can carry.
  static double largest_loss_factor();

  double loss_factor() const noexcept { return eta_; }
  // ψ(ω) = C*(ω)/C_ref, for any ω with Im ω ≤ 0 (the exponential window evaluates ω − iσ).
  std::complex<double> factor(std::complex<double> omega) const;
  // ψ(0) = ψ0, the relaxed modulus over the reference storage modulus.
  double static_factor() const noexcept { return psi0_; }
  // ψ(∞) = ψ0·(1 + c·ln(τ2/τ1)), the unrelaxed (instantaneous) modulus over the reference one.
  double high_frequency_factor() const noexcept;
  // The loss factor Im ψ / Re ψ at a real frequency ω (rad/s).
  double loss_factor_at(double omega) const;

 private:
  double eta_ = 0.0;
  double c_ = 0.0;     // strength of the relaxation spectrum
  double psi0_ = 1.0;  // relaxed modulus / reference storage modulus
};

}  // namespace rollnoise
