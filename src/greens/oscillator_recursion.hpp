#pragma once
// The exact recursion of a sampled oscillator kernel: for m ẍ + r ẋ + k x = f with f constant
// over each step (the `step` discretisation, MODEL.md §2), the state s = (x, ẋ) after step n is
//   s(n) = Φ·s(n−1) + Γ·f(n),   Φ = e^{AΔt},  Γ = ∫_0^Δt e^{Aτ} B dτ,
// so x(n) = Σ_{k≥0} c·Φ^k·Γ f(n−k) with c·Φ^k·Γ = ∫_{kΔt}^{(k+1)Δt} h: exactly the step kernel.
// Φ and Γ follow from the impulse response h, which solves the free equation with h(0) = 0,
// ḣ(0) = 1/m:  Φ = [[m ḣ + r h, m h], [−k h, m ḣ]] at Δt,  Γ = [∫_0^Δt h, h(Δt)].
//
// The travelling form, for a mode e^{ikx} of a body moving past a fixed load at speed v: in the
// load's frame the mode carries the phase e^{iωt}, ω = k·v, so
//   Φ̃ = e^{iωΔt}·Φ,   Γ̃ = ∫_0^Δt e^{iωτ} e^{Aτ} B dτ = [I, e^{iωΔt} h(Δt) − iω·I],
// with I = ∫_0^Δt e^{iωτ} h dτ (the second entry by parts), and c·Φ̃^k·Γ̃ = ∫_{kΔt}^{(k+1)Δt} e^{iωτ} h.
#include <Eigen/Core>

#include "greens/sdof_oscillator.hpp"

namespace rollnoise {

struct OscillatorRecursion {
  Eigen::Matrix2d transition;  // Φ
  Eigen::Vector2d input;       // Γ
};

OscillatorRecursion make_oscillator_recursion(const SdofOscillator& oscillator, double time_step);

struct TravellingRecursion {
  Eigen::Matrix2cd transition;  // Φ̃
  Eigen::Vector2cd input;       // Γ̃
};

TravellingRecursion make_travelling_recursion(const SdofOscillator& oscillator, double time_step, double omega);

}  // namespace rollnoise
