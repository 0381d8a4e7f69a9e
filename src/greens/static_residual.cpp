#include "greens/static_residual.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "greens/sinc.hpp"

namespace rollnoise {

Eigen::MatrixXd static_residual_compliance(const KeptModes& kept,
                                           const std::function<double(double kx, double ky)>& static_compliance,
                                           int window, double cell_length, std::span<const double> y,
                                           double cell_width, double tail_factor) {
  if (!(kept.circumference > 0.0 && kept.width > 0.0 && window >= 1 && cell_length > 0.0 && cell_width > 0.0 &&
        !y.empty() && tail_factor >= 1.0))
    throw std::invalid_argument("static residual: invalid geometry");
  const double pi = std::numbers::pi;
  const double length = kept.circumference;
  const double b = kept.width;
  // Enough orders that the cells' sinc factors have fallen to 1/(tail_factor·π/2)² or less.
  const int m_big = std::max(kept.orders, static_cast<int>(std::ceil(tail_factor * length / (2.0 * cell_length))));
  const int first = kept.first_lateral_order;
  const int n_big = std::max(first + kept.lateral_orders - 1, static_cast<int>(std::ceil(tail_factor * b / cell_width)));
  const auto ny = static_cast<Eigen::Index>(y.size());
  const Eigen::Index points = window * ny;
  // a_n(Δi) for every lateral order (columns) and cell offset Δi = 0 … Nw − 1 (rows), and the
  // lateral shapes at the cells (rows) for every order (columns).
  const int orders_across = n_big - first + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(window, orders_across);
  Eigen::MatrixXd shapes(ny, orders_across);
  for (int n = first; n <= n_big; ++n) {
    const int c = n - first;
    const double kn = n * pi / b;
    const double cn = sinc(0.5 * kn * cell_width);
    const double norm = length * (kept.lateral_shape == LateralShape::cosine && n == 0 ? b : 0.5 * b);
    const bool lateral_kept = n <= first + kept.lateral_orders - 1;
    for (int m = lateral_kept ? kept.orders + 1 : 0; m <= m_big; ++m) {
      const double km = 2.0 * pi * m / length;
      const double cm = sinc(0.5 * km * cell_length);
      const double term = (m == 0 ? 1.0 : 2.0) * static_compliance(km, kn) * cm * cm * cn * cn / norm;
      // cos(k_m·d·ℓ) for d = 0 … Nw − 1 by the Chebyshev recurrence (rounding grows only
      // linearly in d: about 1e-14 at the window's far end).
      const double c1 = std::cos(km * cell_length);
      double previous = 1.0, current = c1;
      a(0, c) += term;
      for (int d = 1; d < window; ++d) {
        a(d, c) += term * current;
        const double next = 2.0 * c1 * current - previous;
        previous = current;
        current = next;
      }
    }
    for (Eigen::Index j = 0; j < ny; ++j)
      shapes(j, c) = kept.lateral_shape == LateralShape::sine ? std::sin(kn * y[static_cast<std::size_t>(j)])
                                                              : std::cos(kn * y[static_cast<std::size_t>(j)]);
  }
  // R(i_p + Nw·j_p, i_q + Nw·j_q) = Σ_n φ_n(y_p) φ_n(y_q)·a_n(|i_p − i_q|): one Ny × Ny block per
  // offset.
  Eigen::MatrixXd residual(points, points);
  for (int d = 0; d < window; ++d) {
    const Eigen::MatrixXd block = shapes * a.row(d).asDiagonal() * shapes.transpose();
    for (Eigen::Index jp = 0; jp < ny; ++jp)
      for (Eigen::Index jq = 0; jq < ny; ++jq)
        for (int ip = 0; ip < window; ++ip) {
          if (ip + d < window) residual(ip + window * jp, ip + d + window * jq) = block(jp, jq);
          if (ip - d >= 0) residual(ip + window * jp, ip - d + window * jq) = block(jp, jq);
        }
  }
  return residual;
}

}  // namespace rollnoise
