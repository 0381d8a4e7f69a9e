#pragma once
// The two-layer tyre's normal Green's functions in time (MODEL.md §1: g(t) is the displacement
// response to a unit force impulse, α(ω) = ∫ g e^{−iωt} dt), per mode and between surface
// locations, from its receptance by batches of inverse FFTs (FFTW, planned once).
//
// Mode (m, n) has the normal modal impulse response h_mn(t) ↔ H_zz(m, n, ω)
// (two_layer_tyre.hpp), and
//   g(r, s; t) = Σ_n Σ_{m=0}^{M} w_m cos(k_m(x_r − x_s)) φ_n(y_r) φ_n(y_s) c_r c_s h_mn(t) / (L·N_n),
// w_0 = 1, w_m = 2, c the cells' sinc factors.
//
// Sampling. K samples at Δt, centred: t_k = (k − K/2)·Δt, k = 0 … K − 1, so the record shows the
// K/2 samples before t = 0 in which a causal response must vanish. Each sample is the mean over
// the step that ends at it, (1/Δt)∫_{t_k−Δt}^{t_k} h dt: the transform of the receptance times
// B(ω) = (1 − e^{−iωΔt})/(iωΔt). This mean is itself causal (it looks back only), and it gives the
// contact's step kernel directly (MODEL.md §2): G[k] = ∫_{kΔt}^{(k+1)Δt} g = Δt·(sample at
// t = (k + 1)Δt), with the sample at t = 0 equal to zero for a causal g.
//
// What makes the transform accurate:
//   - The jump at t = 0. A layer's surface, struck, moves at once: for every mode
//     H_zz → 1/(iω Z(ω)) as ω → ∞, Z = √(ρ C11 ψ(ω)) the tread's P-wave impedance (a dashpot), so
//     h_mn jumps by 1/Z at t = 0 and its spectrum falls only like 1/ω. Its samples would carry the
//     spectrum beyond the Nyquist frequency folded back, before t = 0 too. The asymptote
//     S(ω) = 1/((iω + a)Z(ω)), a = π/(4Δt), is subtracted from every mode and its step means added
//     back, computed once: (1/Z(∞))·(the step means of e^{−at}, exact) plus the transform of
//     (1/Z(ω) − 1/Z(∞))/(iω + a), which falls like 1/ω² and is folded from 64 times the Nyquist
//     frequency. The remainder falls like 1/ω² too.
//   - Aliasing. The remainder's spectrum is evaluated up to `oversampling` times the Nyquist
//     frequency and folded onto the K bins (the samples of a function are the inverse DFT of its
//     spectrum summed over all aliases). On a tyre-like cell kernel at Δt = 0.2 ms, halving Δt
//     changes the step means by 3.5e-3 of their peak without folding, 2.6e-4 with 4 (the
//     default) and 1e-4 with 8; the cost grows in proportion. On the passenger tyre's short
//     waves at Δt = 0.175 ms (m = 128 … 256) 4× folding is 0.4–3 % off 16×. Modes whose dynamics lie far above the Nyquist frequency
//     (c_R·k ≫ π/Δt: short waves on a coarse time step) are nearly instantaneous at this Δt; they
//     need an oversampling of about c_R·k·Δt/π to keep their quasi-static compliance in the right
//     sample (docs/physics/tyre-models.md: a pole–residue form is the better route for those).
//   - The record's periodicity. An exponential window e^{−σt}, σ = ln(10⁴)/T (T = KΔt; the
//     spectrum evaluated at ω − iσ, the window undone after the transform) damps what rings
//     beyond the record by 10⁴ before it wraps round into the early samples (Kausel & Roësset
//     1992).
#include <vector>

#include "greens/surface_receptance_model.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {

class TwoLayerGreensFunctions {
 public:
  // Δt > 0, K even and ≥ 4, oversampling ≥ 1. The modes are computed on `threads` threads (0: one
  // per core); the values do not depend on the number.
  TwoLayerGreensFunctions(const TwoLayerTyre& tyre, double time_step, int samples, int oversampling = 4,
                          unsigned threads = 0);

  double time_step() const noexcept { return dt_; }
  int samples() const noexcept { return samples_; }
  double window_decay() const noexcept { return sigma_; }  // σ, 1/s
  double time(int k) const noexcept { return (k - samples_ / 2) * dt_; }

  // The step means of h_mn (m/(Pa·s)) for m = 0 … M and the tyre's lateral orders.
  const std::vector<double>& mode(int m, int n) const;
  // The step means of g between two surface locations, m/(N·s).
  std::vector<double> between(const SurfaceLocation& receiver, const SurfaceLocation& source) const;

 private:
  const TwoLayerTyre* tyre_;
  double dt_ = 0.0;
  int samples_ = 0;
  double sigma_ = 0.0;
  std::vector<std::vector<double>> modes_;  // index (n − first)·(M + 1) + m
};

}  // namespace rollnoise
