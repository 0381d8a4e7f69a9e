#pragma once
// A translation-invariant tyre in the form the rolling tyre needs (MODEL.md §4; issue 11): modes
// e^{i k_m x}·φ_l(y) around the circumference (x, periodic over L = 2πR, k_m = 2πm/L) and across
// the width (y from the belt's edge), each with its own normal response in pole–residue form.
// The Kropp plate is one (kropp_plate.hpp, exactly: one oscillator per mode); the two-layer tyre
// and tabulated models are others (fitted_modal_tyre.hpp, through a pole fit per mode). The
// rolling code (contact/rolling_modes.hpp) is written once against this interface.
//
// Scaling: the normal displacement at (x, y) caused by point forces F_q at (x_q, y_q) is
//   u(x, y, t) = Σ_l Σ_{m=0}^{M} w_m·Re(e^{i k_m x}·X_ml(t))·φ_l(y),   w_0 = 1, w_m = 2,
//   X_ml = h_ml ∗ f_ml,   f_ml = Σ_q φ_l(y_q)·e^{−i k_m x_q}·F_q,
// with h_ml the impulse response that mode_response() returns (normalisation included). Models
// whose point response diverges (a tread surface: 1/r, Boussinesq) are queried for cells of a
// given size: a cell's force spread uniformly over it and its displacement averaged over it,
// which multiplies each mode by the square of the cell's mean of e^{i k_m x}·φ_l(y).
#include <string>

#include "greens/pole_residue_response.hpp"

namespace rollnoise {

class ModalTyre {
 public:
  virtual ~ModalTyre() = default;
  virtual std::string name() const = 0;
  virtual double circumference() const = 0;  // L, m
  virtual double width() const = 0;          // b, m: the span of the lateral shapes
  virtual int orders() const = 0;            // M: m = 0 … M
  virtual int lateral_modes() const = 0;     // shapes l = 0 … N − 1
  // φ_l(y), 0 ≤ y ≤ b.
  virtual double lateral_shape(int l, double y) const = 0;
  // h_ml of the header, for point forces (cell_length = cell_width = 0) or cells of that size (m).
  virtual PoleResidueResponse mode_response(int m, int l, double cell_length, double cell_width) const = 0;
  // Whether the responses include the tread's local deformation (the contact then adds no
  // separate tread compliance).
  virtual bool includes_tread() const = 0;
};

}  // namespace rollnoise
