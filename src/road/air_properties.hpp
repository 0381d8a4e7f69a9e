#pragma once
// The air in and above a porous road: the constants the porous-layer models and the impedance
// plane need. Ideal gas (R_s = 287.05 J/(kg·K), γ = 1.4), viscosity by Sutherland's law, Prandtl
// number 0.71. At 20 °C and 101 325 Pa: ρ = 1.204 kg/m³, c = 343.2 m/s, η = 1.813e-5 Pa·s, the
// values the radiation stage uses (radiation/equivalent_sources.hpp).
namespace rollnoise {

struct AirProperties {
  double temperature_c = 20.0;         // °C
  double static_pressure = 101325.0;   // P₀, Pa
  double density = 0.0;                // ρ₀, kg/m³
  double sound_speed = 0.0;            // c₀ = √(γP₀/ρ₀), m/s
  double ratio_of_specific_heats = 1.4;  // γ
  double viscosity = 0.0;              // η, Pa·s
  double prandtl = 0.71;               // Pr
};

// Air at `temperature_c` (> −273.15 °C) and `static_pressure` (> 0 Pa); std::invalid_argument
// otherwise (the parser checks user input first and names the key).
AirProperties air_at(double temperature_c = 20.0, double static_pressure = 101325.0);

}  // namespace rollnoise
