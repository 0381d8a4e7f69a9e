#pragma once
// Points and weights on a hemisphere of radius R above the plane z = 0, centred at the origin,
// for integrating a far field: Gauss–Legendre in cos θ over [0, 1] (n nodes: exact for
// polynomials of degree 2n − 1 in cos θ) times the trapezoidal rule in φ (m points: exact for
// trigonometric polynomials of degree < m). Σ w = 2πR². A field whose sources lie within a
// radius a of the origin has angular harmonics up to about ka + 10, so |p|² up to twice that:
// n and m of about ka + 10 integrate it to rounding.
#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "greens/gauss_legendre.hpp"

namespace rollnoise::test {

struct Hemisphere {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd weights;  // m²
};

inline Hemisphere hemisphere_quadrature(int n, int m, double radius) {
  constexpr double kPi = std::numbers::pi;
  // cos θ on [0, 1]: the rule on [−1, 1] mapped, its weights halved.
  const GaussRule rule = gauss_legendre(n);
  std::vector<double> x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = 0.5 * (rule.nodes[i] + 1.0);
    w[i] = 0.5 * rule.weights[i];
  }
  Hemisphere h{Eigen::Matrix3Xd(3, n * m), Eigen::VectorXd(n * m)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double c = x[static_cast<std::size_t>(i)], s = std::sqrt(1.0 - c * c), phi = 2.0 * kPi * (j + 0.5) / m;
      h.points.col(i * m + j) << radius * s * std::cos(phi), radius * s * std::sin(phi), radius * c;
      h.weights(i * m + j) = w[static_cast<std::size_t>(i)] * 2.0 * kPi / m * radius * radius;
    }
  return h;
}

}  // namespace rollnoise::test
