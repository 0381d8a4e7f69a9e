#pragma once
// The damped single-degree-of-freedom oscillator m·ÿ + r·ẏ + k·y = F (MODEL.md §3), in all
// three damping regimes.
//
// The paper's eq. 6 prints (k/m)² inside the root and 1/(2m) as the amplitude; both are
// dimensionally wrong. The physically correct impulse response is
//   under-damped  h = e^{−at} sin(ω_d t)/(m ω_d),   ω_d = √(k/m − a²)
//   over-damped   h = e^{−at} sinh(β t)/(m β),      β  = √(a² − k/m)
//   critical      h = t e^{−at}/m
// with a = r/(2m). All three are h = e^{−at}·S(t)/m with S = sin(ω_d t)/ω_d, sinh(βt)/β or t,
// which is what is evaluated here, so the regimes join continuously.
#include <complex>

namespace rollnoise {

struct SdofOscillator {
  double mass;       // m, kg
  double damping;    // r, N·s/m
  double stiffness;  // k, N/m

  // Impulse response h(t) (m/(N·s)); 0 for t < 0.
  double impulse_response(double t) const;
  // Its rate dh/dt (m/(N·s²)), with dh/dt(0) = 1/m.
  double impulse_response_rate(double t) const;
  // Step response ∫_0^t h (m/N); 1/k as t → ∞.
  double step_response(double t) const;
  // ∫_{t0}^{t1} e^{iωτ} h(τ) dτ (m/N), 0 ≤ t0 ≤ t1 < ∞: the step integral seen by a load that
  // travels with phase e^{iωτ} (a rolling tyre's mode in the fixed contact window).
  std::complex<double> phase_integral(double omega, double t0, double t1) const;
  // Receptance 1/(k − mω² + iωr) (m/N).
  std::complex<double> receptance(double omega) const;
  // ζ = r/(2√(km)).
  double damping_ratio() const;
  // Decay rate of the slowest exponential in h (1/s).
  double slowest_decay_rate() const;
  // Largest |λ| of the characteristic roots of m λ² + r λ + k (1/s).
  double fastest_rate() const;
};

}  // namespace rollnoise
