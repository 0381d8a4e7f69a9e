#pragma once
// Gauss–Legendre quadrature for the greens tests' independent integrals (Newton on P_n).
#include <cmath>
#include <numbers>
#include <vector>

namespace rollnoise::test {

struct GaussRule {
  std::vector<double> nodes, weights;  // on [−1, 1]
};

inline GaussRule gauss_legendre(int n) {
  GaussRule rule;
  for (int i = 1; i <= n; ++i) {
    double x = std::cos(std::numbers::pi * (i - 0.25) / (n + 0.5));
    double dp = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / dp;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(x);
    rule.weights.push_back(2.0 / ((1.0 - x * x) * dp * dp));
  }
  return rule;
}

}  // namespace rollnoise::test
