#pragma once
// The roads the rolling-tyre tests share (test_rolling_tyre.cpp, test_rolling_two_layer.cpp).
#include <cmath>
#include <string>

#include "road/road_surface.hpp"

namespace rollnoise::test {

// Bumps that vary across the width too, so that lateral lines see different roads.
class Bumps : public RoadSurface {
 public:
  std::string type() const override { return "bumps"; }
  double height(double x, double y) const override {
    if (x < 0.0) return 0.0;
    return 1.5e-3 * std::sin(2 * M_PI * x / 0.09) * std::sin(2 * M_PI * x / 0.31) * (1.0 + 4.0 * y);
  }
};

class Flat : public RoadSurface {
 public:
  std::string type() const override { return "flat"; }
  double height(double, double) const override { return 0.0; }
};

}  // namespace rollnoise::test
