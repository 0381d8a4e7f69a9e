#pragma once
// The two-layer tyre's normal Green's functions in time (MODEL.md §1: g(t) is the displacement
// response to a unit force impulse, α(ω) = ∫ g e^{−iωt} dt), per mode and between surface
// locations, from its receptance by one batch of inverse FFTs (FFTW, planned once).
//
// Mode (m, n) has the normal modal impulse response h_mn(t) ↔ H_zz(m, n, ω)
// (two_layer_tyre.hpp), and
//   g(r, s; t) = Σ_n Σ_{m=0}^{M} w_m cos(k_m(x_r − x_s)) φ_n(y_r) φ_n(y_s) c_r c_s h_mn(t) / (L·N_n),
// w_0 = 1, w_m = 2, c the cells' sinc factors.
//
// Sampling. K samples at Δt, centred: t_k = (k − K/2)·Δt, k = 0 … K − 1, so the record shows the
// K/2 samples before t = 0 in which a causal response must vanish. Each sample is the mean over
// the step that ends at it, (1/Δt)∫_{t_k−Δt}^{t_k} h dt: the transform of the receptance times
// B(ω) = (1 − e^{−iωΔt})/(iωΔt). This mean is itself causal (it looks back only), needs no δ
// part (a layer's receptance falls like 1/ω: its g jumps at t = 0 but has no impulse), and gives
// the contact's step kernel directly (MODEL.md §2): G[k] = ∫_{kΔt}^{(k+1)Δt} g = Δt·(sample at
// t = (k + 1)Δt), with the sample at t = 0 equal to zero for a causal g.
// The record length T = K·Δt is periodic: an exponential window e^{−σt} with σ = ln(10⁴)/T
// (the receptance evaluated at ω − iσ, undone after the transform) damps what rings beyond the
// record by 10⁴ before it wraps round into the early samples (Phinney 1965; Kausel & Roësset
// 1992). The Nyquist bin is dropped.
#include <vector>

#include "greens/surface_receptance_model.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {

class TwoLayerGreensFunctions {
 public:
  // Δt > 0, K even and ≥ 4.
  TwoLayerGreensFunctions(const TwoLayerTyre& tyre, double time_step, int samples);

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
