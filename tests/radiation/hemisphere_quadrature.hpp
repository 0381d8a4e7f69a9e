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

namespace rollnoise::test {

struct Hemisphere {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd weights;  // m²
};

inline Hemisphere hemisphere_quadrature(int n, int m, double radius) {
  constexpr double kPi = std::numbers::pi;
  std::vector<double> x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double t = std::cos(kPi * (i + 0.75) / (n + 0.5));  // Newton on P_n from Tricomi's estimate
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-15) break;
    }
    x[static_cast<std::size_t>(i)] = 0.5 * (t + 1.0);                 // mapped to [0, 1]
    w[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - t * t) * dp * dp);  // ½ · 2/((1 − t²)P′²)
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
