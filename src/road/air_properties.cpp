#include "road/air_properties.hpp"

#include <cmath>
#include <stdexcept>

namespace rollnoise {

AirProperties air_at(double temperature_c, double static_pressure) {
  const double kelvin = temperature_c + 273.15;
  if (!(kelvin > 0.0) || !std::isfinite(kelvin) || !(static_pressure > 0.0) || !std::isfinite(static_pressure))
    throw std::invalid_argument("air_at: the temperature must be above absolute zero and the pressure positive");
  constexpr double gas_constant = 287.05;  // J/(kg·K), dry air
  AirProperties air;
  air.temperature_c = temperature_c;
  air.static_pressure = static_pressure;
  air.density = static_pressure / (gas_constant * kelvin);
  air.sound_speed = std::sqrt(air.ratio_of_specific_heats * static_pressure / air.density);
  // Sutherland's law (η₀ = 1.716e-5 Pa·s at 273.15 K, S = 110.4 K).
  air.viscosity = 1.716e-5 * std::pow(kelvin / 273.15, 1.5) * (273.15 + 110.4) / (kelvin + 110.4);
  return air;
}

}  // namespace rollnoise
