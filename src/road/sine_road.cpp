#include "road/sine_road.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {

SineRoad::SineRoad(double amplitude, double wavelength)
    : amplitude_(amplitude), wavelength_(wavelength) {
  // Negated comparisons so that NaN is rejected too.
  if (!(amplitude > 0.0) || !std::isfinite(amplitude)) {
    throw InputError("", "amplitude", "must be a finite number > 0 (got " + format_number(amplitude) + ")");
  }
  if (!(wavelength > 0.0) || !std::isfinite(wavelength)) {
    throw InputError("", "wavelength", "must be a finite number > 0 (got " + format_number(wavelength) + ")");
  }
}

std::string SineRoad::type() const { return "sine"; }

double SineRoad::height(double x) const {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  return amplitude_ * std::sin(2.0 * std::numbers::pi * x / wavelength_);
}

}  // namespace rollnoise
