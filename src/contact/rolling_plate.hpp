#pragma once
// The Kropp plate seen from the fixed contact window of a rolling tyre (MODEL.md §4).
//
// Rolling is a shear of the kernel: the tyre advances one cell per step, so a force applied at
// fixed point q, k steps ago, acted on material that is now about k cells further round:
//   G_fixed[k](p, q) ≈ G_material[k](x_p − x_q + k·dx).
// Exactly: during a step the material keeps moving under the constant force, so the force acts
// on material at x_p − x_q + vτ for every delay τ in the lag, and
//   G_fixed[k](p, q) = Σ_modes e^{i k_m (x_p − x_q)} ∫_{kΔt}^{(k+1)Δt} e^{i k_m v τ} h_mn(τ) dτ · …
// Taking the shift only at whole cells would leave half a cell of spurious lag: a phase error
// that makes even an undamped tyre's pressure lean and dissipate. With the phase inside the
// integral every mode keeps an exact two-state recursion (oscillator_recursion.hpp, travelling
// form, ω = k_m v):
//   X_mn(n) = Φ̃_mn·X_mn(n−1) + Γ̃_mn·f_mn(n),
//   f_mn(n) = Σ_q sin(k_n y_q)·e^{−i k_m x_q}·F_q(n),
//   u_p     = (1/M) Σ_mn w_m·Re(e^{i k_m x_p}·x_mn)·sin(k_n y_p),   M = m''·L·b/2,
// with w_0 = 1 and w_m = 2 for m ≥ 1 (the modes m and −m together). Summed over all lags,
// Σ_k c Φ̃^k Γ̃ = ∫_0^∞ e^{iωτ} h = α(−ω): the compliance of steady rolling, non-symmetric when
// the belt is damped (the pressure leans forward: rolling resistance). G_fixed[0] is slightly
// non-symmetric too: within one step the material moves by one cell.
//
// Sub-steps (issue 10 §3). With p sub-steps per cell, Δt = dx/(p·v): the material moves by dx/p
// per step, a fraction of a cell. Nothing above needs whole cells: the window's points stay at
// their fixed positions x_i (grid positions around the axle), the forces act there, and every
// mode carries the exact phase e^{i k_m v τ} of the material passing under them, ω_m = k_m·v =
// 2πm/(Nθ·p·Δt). The state of each mode is held in the fixed frame (its amplitude at fixed
// positions), so a fractional shift is only a phase: the recursion, the closed-form step
// integrals and the all-lag total are exact for any p. What p changes is the time step, so the
// highest frequency the contact steps carry (1/(2Δt) = p·v/(2·dx)); the spatial grid, and with it
// the shortest force pattern and texture wavelength seen across the window (2·dx), does not.
// Because the window's points are fixed and the texture (and the tread stuck to it) moves past
// them, the contact's nonlinearity modulates the forces at the cell-passing frequency v/dx, which
// sub-steps bring into the band (at p = 1 it aliases to 0 Hz): README, "The band up to 5 kHz".
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "contact/tyre_grid.hpp"
#include "greens/discrete_kernel.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/oscillator_recursion.hpp"

namespace rollnoise {

class RollingPlate {
 public:
  // Throws std::invalid_argument when the plate has more circumferential orders than the grid
  // can represent (M > Nθ/2).
  // `substeps` p ≥ 1: the tyre advances one cell every p steps (v = dx/(p·time_step)).
  RollingPlate(const KroppPlate& plate, const TyreGrid& grid, double time_step, int substeps = 1);

  const TyreGrid& grid() const noexcept { return grid_; }
  const KroppPlate& plate() const noexcept { return plate_; }
  double time_step() const noexcept { return time_step_; }
  int substeps() const noexcept { return substeps_; }
  double speed() const noexcept { return grid_.dx() / (substeps_ * time_step_); }  // v, m/s
  int orders() const noexcept { return orders_; }      // m = 0 … M
  int lateral_modes() const noexcept { return lateral_modes_; }  // n = 1 … N
  double modal_mass() const noexcept { return modal_mass_; }
  // sin(k_n y_j): Ny × N.
  const Eigen::MatrixXd& lateral_shapes() const noexcept { return lateral_shapes_; }
  // Mode (m, n) at index m + (M + 1)·(n − 1).
  Eigen::Index mode_index(int m, int n) const { return m + static_cast<Eigen::Index>(orders_ + 1) * (n - 1); }
  const SdofOscillator& oscillator(Eigen::Index mode) const { return oscillators_[static_cast<std::size_t>(mode)]; }
  const TravellingRecursion& recursion(Eigen::Index mode) const { return recursions_[static_cast<std::size_t>(mode)]; }
  // ω_m = k_m·v, the rate at which order m passes a fixed point (rad/s).
  double passing_rate(int m) const;
  double weight(int m) const { return m == 0 ? 1.0 : 2.0; }

  // The structural kernel, sheared for rolling: G_fixed[0 … lags−1] (P × P each), from the
  // modes' closed-form travelling step integrals (not from the recursion, so that the modal
  // engine is checked against an independent evaluation), and its total over all lags, the
  // steady-rolling compliance. The local (tread) compliance is not included.
  DiscreteKernel sheared_kernel(std::size_t lags) const;
  // G_fixed[k] alone (P × P), without the all-lag total that sheared_kernel() also computes.
  Eigen::MatrixXd sheared_lag(std::size_t k) const;
  // Σ_k G_fixed[k]: the structural compliance of steady rolling (P × P).
  Eigen::MatrixXd rolling_compliance() const;

 private:
  // Fills out(p, q) += Σ_n S(j_p, n) S(j_q, n)·a_n(i_p − i_q) / M for one set of per-mode
  // coefficients, where a_n(Δ) = Σ_m w_m Re(e^{2πi m Δ/Nθ}·c_mn).
  void add_modal_sum(const std::vector<std::complex<double>>& coefficients, Eigen::MatrixXd& out) const;

  const KroppPlate& plate_;
  TyreGrid grid_;
  double time_step_;
  int substeps_;
  int orders_;
  int lateral_modes_;
  double modal_mass_;
  Eigen::MatrixXd lateral_shapes_;
  std::vector<SdofOscillator> oscillators_;
  std::vector<TravellingRecursion> recursions_;
};

}  // namespace rollnoise
