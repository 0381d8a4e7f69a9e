#pragma once
// The small rolling plate the rolling-contact tests share (test_rolling_tyre.cpp,
// test_tread_newton_contact.cpp, test_texture_contact_law.cpp): a belt small enough that the
// direct engine's dense kernel stays small, 64 points around, 4 across, a 16-cell window.
#include "contact/tyre_grid.hpp"
#include "greens/kropp_plate.hpp"

namespace rollnoise::test {

inline PlateParameters small_plate(double loss_factor) {
  PlateParameters p;
  p.radius = 0.3;
  p.width = 0.16;
  p.mass_per_area = 10.0;
  p.tension_x = 8e4;
  p.tension_y = 4e4;
  p.bending_x = 6.0;
  p.bending_y = 3.0;
  p.bending_xy = 3.0;
  p.foundation_stiffness = 2.8e6;
  p.loss_factor = loss_factor;
  p.circumferential_modes = 32;
  p.lateral_modes = 4;
  return p;
}

inline TyreGrid small_grid() {
  TyreGrid g;
  g.radius = 0.3;
  g.width = 0.16;
  g.circumferential = 64;
  g.lateral = 4;
  g.window = 16;
  return g;
}

}  // namespace rollnoise::test
