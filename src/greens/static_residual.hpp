#pragma once
// The static compliance between contact cells of the modes that a modal table leaves out
// (modal_receptance_table.hpp): the classic static correction of a truncated modal sum
// (residual flexibility; e.g. Craig & Kurdila, "Fundamentals of Structural Dynamics", §13.4).
//
// Why a tyre whose modes include its tread needs it: on the tread surface the point response
// diverges like 1/r (Boussinesq), and a cell's response to its own load is made up mostly of
// wavenumbers up to ~2π/(cell size). A table that stops at the grid's Nyquist order (or at the
// model file's circumferential_modes, lateral_modes) misses a large part of the cell's own
// compliance: the tread would look far stiffer under an asperity than it is. The missing modes
// have their first resonance at the tread's Rayleigh wave, c_R·k, k beyond the table; well below
// it their static compliance is what they add. (For the passenger tyre that is above 4.2 kHz
// for the orders around, but from 2.3 kHz for the lateral half-waves under 7.2 mm: in the top
// bands an approximation.)
//
// With the kept modes m ≤ M and n ≤ n_last, the residual between cells p and q (centres
// x_p − x_q = Δx, y_p, y_q; length ℓ, width w) is
//   R(p, q) = Σ_{(m, n) not kept} w_m cos(k_m Δx)·H_n(k_m, k_n, 0)·c_m² c_n²·φ_n(y_p) φ_n(y_q)/(L·N_n),
// c_m = sinc(k_m ℓ/2), c_n = sinc(k_n w/2), summed until the cells' sinc factors have made the
// terms negligible: m up to `tail_factor`·π/ℓ·L/(2π), n up to `tail_factor`·b/w (sinc² ≤ 1/(tail_factor·π/2)²).
#include <functional>
#include <span>

#include <Eigen/Core>

#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

struct KeptModes {
  double circumference = 0.0;  // L, m
  double width = 0.0;          // b, m
  LateralShape lateral_shape = LateralShape::sine;
  int first_lateral_order = 1;
  int lateral_orders = 0;  // N kept: n = first … first + N − 1
  int orders = 0;          // M kept: m = 0 … M
};

// The residual R for the contact window: Nw cells along x at spacing ℓ (p = i + Nw·j), and the
// lateral cells centred at `y` (m from the edge of the lateral shapes' span), each `cell_width`
// wide. `static_compliance(kx, ky)`: H_zz at ω = 0 of the mode with those wavenumbers (m/Pa).
Eigen::MatrixXd static_residual_compliance(const KeptModes& kept,
                                           const std::function<double(double kx, double ky)>& static_compliance,
                                           int window, double cell_length, std::span<const double> y,
                                           double cell_width, double tail_factor = 8.0);

}  // namespace rollnoise
