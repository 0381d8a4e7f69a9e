#include "greens/sdof_oscillator.hpp"

#include <cmath>
#include <limits>

namespace rollnoise {
namespace {

// e^{−at}·S(t) and e^{−at}·S'(t), with S = sin(ωt)/ω, sinh(βt)/β or t: the shape shared by
// the impulse and step responses. disc = a² − k/m decides the regime. The over-damped forms
// are written with the two real exponentials so that nothing overflows for large t.
struct DecayedShape {
  double s;   // e^{−at}·S(t)
  double ds;  // e^{−at}·S'(t): cos, cosh or 1 times the decay
};

DecayedShape decayed_shape(double a, double disc, double t) {
  const double decay = std::exp(-a * t);
  if (disc < 0.0) {
    const double w = std::sqrt(-disc);
    return {decay * std::sin(w * t) / w, decay * std::cos(w * t)};
  }
  if (disc > 0.0) {
    const double b = std::sqrt(disc);
    const double slow = std::exp(-(a - b) * t);
    const double fast = std::exp(-(a + b) * t);
    // e^{−at} sinh(βt)/β: the expm1 form keeps its digits for small βt.
    const double s = b * t < 1.0 ? fast * std::expm1(2.0 * b * t) / (2.0 * b) : (slow - fast) / (2.0 * b);
    return {s, 0.5 * (slow + fast)};
  }
  return {decay * t, decay};
}

}  // namespace

double SdofOscillator::impulse_response(double t) const {
  if (t < 0.0) return 0.0;
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  return decayed_shape(a, disc, t).s / mass;
}

double SdofOscillator::impulse_response_rate(double t) const {
  if (t < 0.0) return 0.0;
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  const DecayedShape sh = decayed_shape(a, disc, t);
  // d/dt (e^{−at} S) = e^{−at} (S' − a S)
  return (sh.ds - a * sh.s) / mass;
}

double SdofOscillator::step_response(double t) const {
  if (t <= 0.0) return 0.0;
  if (std::isinf(t)) return 1.0 / stiffness;
  // ∫_0^t h = (1/k)·(1 − e^{−at}(S'(t) + a·S(t))), the response to a unit step force.
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  const DecayedShape sh = decayed_shape(a, disc, t);
  return (1.0 - (sh.ds + a * sh.s)) / stiffness;
}

namespace {

// (e^z − 1)/z, accurate also for small |z|.
std::complex<double> exprel(std::complex<double> z) {
  if (std::abs(z) < 1e-4) return 1.0 + z / 2.0 + z * z / 6.0 + z * z * z / 24.0;
  return (std::exp(z) - 1.0) / z;
}

// ∫_{t0}^{t0+d} e^{μτ} dτ = e^{μ t0}·d·exprel(μ d).
std::complex<double> exp_integral(std::complex<double> mu, double t0, double d) {
  return std::exp(mu * t0) * d * exprel(mu * d);
}

}  // namespace

std::complex<double> SdofOscillator::phase_integral(double omega, double t0, double t1) const {
  using C = std::complex<double>;
  const double d = t1 - t0;
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  const C shift(0.0, omega);
  if (disc == 0.0) {
    // h = t e^{−at}/m: ∫ τ e^{μτ} = [e^{μτ}(τ/μ − 1/μ²)], or by the derivative in μ.
    const C mu = -a + shift;
    if (std::abs(mu) * std::max(t1, 1e-300) < 1e-8) return (t1 * t1 - t0 * t0) / (2.0 * mass);
    const auto antiderivative = [&](double t) { return std::exp(mu * t) * (t / mu - 1.0 / (mu * mu)); };
    return (antiderivative(t1) - antiderivative(t0)) / mass;
  }
  // h = (e^{λ1 τ} − e^{λ2 τ}) / (m (λ1 − λ2)) with λ = −a ± √disc (complex when under-damped).
  const C root = std::sqrt(C(disc, 0.0));
  const C l1 = -a + root;
  const C l2 = -a - root;
  return (exp_integral(l1 + shift, t0, d) - exp_integral(l2 + shift, t0, d)) / (mass * (l1 - l2));
}

std::complex<double> SdofOscillator::receptance(double omega) const {
  return 1.0 / std::complex<double>(stiffness - mass * omega * omega, omega * damping);
}

double SdofOscillator::damping_ratio() const {
  return damping / (2.0 * std::sqrt(stiffness * mass));
}

double SdofOscillator::slowest_decay_rate() const {
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  if (disc <= 0.0) return a;
  // a − √disc loses digits when k ≪ r²/m; k/(m(a + √disc)) is the same root, computed stably.
  return stiffness / (mass * (a + std::sqrt(disc)));
}

double SdofOscillator::fastest_rate() const {
  const double a = damping / (2.0 * mass);
  const double disc = a * a - stiffness / mass;
  if (disc <= 0.0) return std::sqrt(stiffness / mass);  // |λ|² = k/m for complex roots
  return a + std::sqrt(disc);
}

}  // namespace rollnoise
