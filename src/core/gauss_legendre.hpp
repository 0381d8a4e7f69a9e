#pragma once
// Gauss–Legendre nodes and weights on [−1, 1]: Newton's method on P_n from the starting points
// cos(π(i − ¼)/(n + ½)), weights 2/((1 − x²)P_n′(x)²) (as gauleg in Press et al., Numerical
// Recipes, 3rd ed., §4.6). n nodes integrate polynomials of degree 2n − 1 exactly.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rollnoise {

struct GaussRule {
  std::vector<double> nodes, weights;  // on [−1, 1]
};

inline GaussRule gauss_legendre_rule(int n) {
  if (n < 1) throw std::invalid_argument("Gauss–Legendre rule: at least one node");
  GaussRule rule;
  for (int i = 1; i <= n; ++i) {
    double x = std::cos(std::numbers::pi * (i - 0.25) / (n + 0.5));
    double dp = 1.0;
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

}  // namespace rollnoise
