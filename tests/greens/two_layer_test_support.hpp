#pragma once
// What the two-layer tyre tests share: Gauss–Legendre quadrature, and parameter sets.
#include <cmath>
#include <numbers>
#include <vector>

#include "gauss_legendre.hpp"
#include "greens/two_layer_tyre.hpp"

namespace rollnoise::test {


// Nodes and weights of a composite rule: `panels` equal panels on [lo, hi], `rule` on each.
struct Quadrature {
  std::vector<double> nodes, weights;
};

inline Quadrature composite_rule(double lo, double hi, int panels, const GaussRule& rule) {
  Quadrature q;
  const double h = (hi - lo) / panels;
  for (int k = 0; k < panels; ++k) {
    const double mid = lo + (k + 0.5) * h;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      q.nodes.push_back(mid + 0.5 * h * rule.nodes[i]);
      q.weights.push_back(0.5 * h * rule.weights[i]);
    }
  }
  return q;
}

// A tyre-like two-layer parameter set (the passenger file's values, rounded) with few modes.
inline TwoLayerParameters tyre_like_two_layer(int circumferential_modes, int lateral_modes) {
  TwoLayerParameters p;
  p.radius = 0.316;
  p.width = 0.18;
  p.belt = {3.0e9, 1.3e9, 3.0e7, 8.0e8, 1.0e7, 1.0e7, 0.3, 0.45, 0.45};
  p.belt_thickness = 0.003;
  p.belt_density = 2000.0;
  p.belt_loss_factor = 0.05;
  p.tread_thickness = 0.007;
  p.tread_density = 1150.0;
  p.tread_youngs_modulus = 4.0e6;
  p.tread_poisson_ratio = 0.48;
  p.tread_loss_factor = 0.1;
  p.tension_x = 6.0e4;
  p.tension_y = 9.0e3;
  p.foundation_stiffness = 1.5e6;
  p.foundation_loss_factor = 0.08;
  p.circumferential_modes = circumferential_modes;
  p.lateral_modes = lateral_modes;
  return p;
}

}  // namespace rollnoise::test
