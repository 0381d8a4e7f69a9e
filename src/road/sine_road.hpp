#pragma once
// A single sinusoidal undulation, r(x) = amplitude * sin(2 pi x / wavelength) for x >= 0.
// It starts at r = 0 with the sine's zero crossing, so the lead-in (r = 0 for x < 0) joins it
// without a jump.
#include <string>

#include "road/road_profile.hpp"

namespace rollnoise {

class SineRoad final : public RoadProfile {
 public:
  // amplitude and wavelength in m, both > 0 (InputError naming the key otherwise; the error
  // names no file, make_road_profile adds it).
  SineRoad(double amplitude, double wavelength);

  std::string type() const override;
  double height(double x) const override;

  double amplitude() const noexcept { return amplitude_; }
  double wavelength() const noexcept { return wavelength_; }

 private:
  double amplitude_;
  double wavelength_;
};

}  // namespace rollnoise
