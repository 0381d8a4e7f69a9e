#pragma once
// A translation-invariant tyre (greens/modal_tyre.hpp: the Kropp plate, the two-layer tyre, a
// tabulated model) seen from the fixed contact window of a rolling tyre (MODEL.md §4). One
// rolling code path for every such model: each mode comes as poles and residues
// (greens/pole_residue_response.hpp), h_ml(τ) = d·δ(τ) + Σ_r ρ_r e^{p_r τ}.
//
// Rolling is a shear of the kernel: the tyre advances one cell per step, so a force applied at
// fixed point q, k steps ago, acted on material that is now about k cells further round:
//   G_fixed[k](p, q) ≈ G_material[k](x_p − x_q + k·dx).
// Exactly: during a step the material keeps moving under the constant force, so the force acts
// on material at x_p − x_q + vτ for every delay τ in the lag, and
//   G_fixed[k](p, q) = Σ_modes w_m Re(e^{i k_m (x_p − x_q)} ∫_{kΔt}^{(k+1)Δt} e^{i k_m v τ} h_ml(τ) dτ)·φ_l(y_p)φ_l(y_q).
// Taking the shift only at whole cells would leave half a cell of spurious lag: a phase error
// that makes even an undamped tyre's pressure lean and dissipate. With the phase inside the
// integral every pole keeps an exact one-state recursion with the shifted rate q_r = p_r + iω_m,
// ω_m = k_m·v (the rate at which order m passes a fixed point):
//   y_r(n) = e^{q_r Δt}·y_r(n−1) + ρ_r (e^{q_r Δt} − 1)/q_r · f_ml(n),
//   X_ml(n) = Σ_r y_r(n) + d·f_ml(n),   f_ml(n) = Σ_q φ_l(y_q)·e^{−i k_m x_q}·F_q(n),
//   u_p     = Σ_ml w_m·Re(e^{i k_m x_p}·X_ml)·φ_l(y_p),
// with w_0 = 1 and w_m = 2 for m ≥ 1 (the modes m and −m together). Summed over all lags,
// Σ_k G̃[k] = ∫_0^∞ e^{iωτ} h = α(−ω): the compliance of steady rolling, non-symmetric when
// the tyre is damped (the pressure leans forward: rolling resistance). G_fixed[0] is slightly
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
// sub-steps bring into the band (at p = 1 it aliases to 0 Hz): docs/physics/contact.md, "The band up to 5 kHz".
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "contact/tyre_grid.hpp"
#include "greens/discrete_kernel.hpp"
#include "greens/modal_tyre.hpp"
#include "greens/pole_residue_response.hpp"

namespace rollnoise {

class RollingModes {
 public:
  // Refers to `tyre`, which must outlive it. Throws std::invalid_argument when the tyre has more circumferential orders than the grid
  // can represent (M > Nθ/2) or its circumference differs from the grid's.
  // `substeps` p ≥ 1: the tyre advances one cell every p steps (v = dx/(p·time_step)).
  RollingModes(const ModalTyre& tyre, const TyreGrid& grid, double time_step, int substeps = 1);

  const TyreGrid& grid() const noexcept { return grid_; }
  const ModalTyre& tyre() const noexcept { return tyre_; }
  double time_step() const noexcept { return time_step_; }
  int substeps() const noexcept { return substeps_; }
  double speed() const noexcept { return grid_.dx() / (substeps_ * time_step_); }  // v, m/s
  int orders() const noexcept { return orders_; }                // m = 0 … M
  int lateral_modes() const noexcept { return lateral_modes_; }  // l = 0 … N − 1
  // φ_l(y_j) at the window's lateral points: Ny × N.
  const Eigen::MatrixXd& lateral_shapes() const noexcept { return lateral_shapes_; }
  // Mode (m, l) at index m + (M + 1)·l.
  Eigen::Index mode_index(int m, int l) const { return m + static_cast<Eigen::Index>(orders_ + 1) * l; }
  const PoleResidueResponse& mode(Eigen::Index index) const { return modes_[static_cast<std::size_t>(index)]; }
  // ω_m = k_m·v, the rate at which order m passes a fixed point (rad/s).
  double passing_rate(int m) const;
  double weight(int m) const { return m == 0 ? 1.0 : 2.0; }

  // The structural kernel, sheared for rolling: G_fixed[0 … lags−1] (P × P each), from the
  // poles' closed-form travelling step integrals (not from the recursion, so that the modal
  // engine is checked against an independent evaluation), and its total over all lags, the
  // steady-rolling compliance. A separate tread compliance is not included.
  DiscreteKernel sheared_kernel(std::size_t lags) const;
  // G_fixed[k] alone (P × P), without the all-lag total that sheared_kernel() also computes.
  Eigen::MatrixXd sheared_lag(std::size_t k) const;
  // Σ_k G_fixed[k]: the compliance of steady rolling (P × P).
  Eigen::MatrixXd rolling_compliance() const;

 private:
  // Fills out(p, q) += Σ_l φ_l(y_p) φ_l(y_q)·a_l(i_p − i_q) for one set of per-mode
  // coefficients, where a_l(Δ) = Σ_m w_m Re(e^{2πi m Δ/Nθ}·c_ml).
  void add_modal_sum(const std::vector<std::complex<double>>& coefficients, Eigen::MatrixXd& out) const;

  const ModalTyre& tyre_;
  TyreGrid grid_;
  double time_step_;
  int substeps_;
  int orders_;
  int lateral_modes_;
  Eigen::MatrixXd lateral_shapes_;
  std::vector<PoleResidueResponse> modes_;  // for the grid's cells
};

}  // namespace rollnoise
