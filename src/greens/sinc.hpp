#pragma once
// sin(x)/x: the mean of e^{ikx'} over a cell of length ℓ centred on x is e^{ikx}·sinc(kℓ/2), the
// factor by which a cell's uniform load and averaged response weigh each mode (two_layer_tyre,
// fitted_modal_tyre, static_residual), and the transform of a box (two_layer_greens_functions).
// Below |x| = 1e-4 the series 1 − x²/6 (its next term, x⁴/120, is below 1e-18).
#include <cmath>

namespace rollnoise {

inline double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace rollnoise
