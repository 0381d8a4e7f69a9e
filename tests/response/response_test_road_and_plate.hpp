// The road, the plate and the grid the response-stage tests roll on (test_surface_response.cpp,
// test_step_outputs.cpp): a two-dimensional texture of two wavelengths, flat before x = 0, and
// a damped plate, so that the steady state leans (rolling resistance).
#pragma once

#include <cmath>
#include <string>

#include "contact/tyre_grid.hpp"
#include "greens/kropp_plate.hpp"
#include "road/road_surface.hpp"

namespace rollnoise::response_test {

class Texture : public RoadSurface {
 public:
  std::string type() const override { return "texture"; }
  double height(double x, double y) const override {
    if (x < 0.0) return 0.0;
    return 1e-3 * std::sin(2 * M_PI * x / 0.07) * std::cos(2 * M_PI * y / 0.11) +
           4e-4 * std::sin(2 * M_PI * x / 0.023 + 1.0);
  }
};

inline PlateParameters test_plate(int orders) {
  PlateParameters p;
  p.radius = 0.3;
  p.width = 0.16;
  p.mass_per_area = 10.0;
  p.tension_x = 8e4;
  p.tension_y = 1e4;
  p.bending_x = 6.0;
  p.bending_y = 3.0;
  p.bending_xy = 4.0;
  p.foundation_stiffness = 3e6;
  p.loss_factor = 0.1;
  p.circumferential_modes = orders;
  p.lateral_modes = 6;
  return p;
}

// The tyre grid over that plate: `around` cells around, 6 across, a contact window of `window`.
inline TyreGrid test_grid(int around, int window) {
  TyreGrid grid;
  grid.radius = 0.3;
  grid.width = 0.16;
  grid.circumferential = around;
  grid.lateral = 6;
  grid.window = window;
  return grid;
}

}  // namespace rollnoise::response_test
