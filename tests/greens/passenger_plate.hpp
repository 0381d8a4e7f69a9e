#pragma once
// The belt of models/tyres/passenger_205_55R16.toml as PlateParameters, with fewer modes for
// quick tests (calibration, and the budget's estimates: plate_mobility_average,
// contact_force_estimate). The defaults are the model file's mode counts.
#include "greens/kropp_plate.hpp"

namespace rollnoise::test {

inline PlateParameters passenger_plate(int circumferential_modes = 256, int lateral_modes = 25) {
  PlateParameters p;
  p.radius = 0.316;
  p.width = 0.18;
  p.mass_per_area = 12.0;
  p.tension_x = 6e4;
  p.tension_y = 9e3;
  p.bending_x = 7;
  p.bending_y = 3;
  p.bending_xy = 4.6;
  p.foundation_stiffness = 3.2e6;
  p.loss_factor = 0.1;
  p.circumferential_modes = circumferential_modes;
  p.lateral_modes = lateral_modes;
  return p;
}

}  // namespace rollnoise::test
