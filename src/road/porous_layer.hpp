#pragma once
// One rigid-framed porous layer of a road (porous asphalt): the effective density and bulk
// modulus of the air in its pores, and from them the characteristic impedance and wavenumber of
// the wave in it. Time dependence e^{+iωt}, as the radiation stage (radiation/equivalent_sources.hpp):
// losses make Im ρ < 0 and Im k < 0. Quantities per unit of flux (Darcy) velocity, so that
// pressure and normal velocity are continuous between layers (layered_absorber.hpp).
//
// Hamet & Bérengier (Inter-Noise 93; Bérengier, Stinson, Daigle & Hamet 1997, "Porous road
// pavements: acoustical characterization and propagation effects"), the usual phenomenological
// model of porous pavements, with porosity Ω, flow resistivity σ and
// tortuosity α∞ (their q²):
//   ρ(ω) = (ρ₀α∞/Ω)·(1 − i f_μ/f),                   f_μ = σΩ/(2πρ₀α∞)
//   K(ω) = (γP₀/Ω) / (γ − (γ − 1)/(1 − i f_θ/f)),     f_θ = σΩ/(2πρ₀Pr)
// Johnson–Champoux–Allard (Johnson et al., J. Fluid Mech. 176 (1987); Champoux & Allard,
// J. Appl. Phys. 70 (1991); Allard & Atalla, Propagating Sound in Porous Media, 2nd ed. (2009)
// eqs. 5.50–5.52, whose e^{jωt} is ours), adding the viscous and thermal characteristic lengths
// Λ and Λ':
//   ρ(ω) = (ρ₀α∞/Ω)·[1 + σΩ/(iωρ₀α∞)·√(1 + 4iα∞²ηρ₀ω/(σ²Λ²Ω²))]
//   K(ω) = (γP₀/Ω) / (γ − (γ − 1)/[1 + 8η/(iΛ'²Pr ωρ₀)·√(1 + iρ₀ωPrΛ'²/(16η))])
// Hamet–Bérengier is JCA with both square roots set to 1 and Λ' = √(8η/(σΩ)) (straight
// cylindrical pores): the two agree at low frequency; both tend to the rigid-frame limit
// k → ω√α∞/c₀, Z_c → ρ₀c₀√α∞/Ω at high frequency.
#include <complex>
#include <string>

#include "road/air_properties.hpp"

namespace rollnoise {

enum class PorousModel { hamet_berengier, jca };

// "hamet_berengier", "jca".
std::string porous_model_name(PorousModel model);

struct PorousLayer {
  PorousModel model = PorousModel::hamet_berengier;
  double porosity = 0.0;          // Ω, in (0, 1)
  double flow_resistivity = 0.0;  // σ, Pa·s/m², > 0
  double tortuosity = 1.0;        // α∞ (Hamet–Bérengier's q²), >= 1
  double thickness = 0.0;         // d, m, > 0
  double viscous_length = 0.0;    // Λ, m, > 0 (jca only)
  double thermal_length = 0.0;    // Λ', m, >= Λ usually (jca only)
};

struct PorousLayerWave {
  std::complex<double> density;                  // ρ(ω), kg/m³
  std::complex<double> bulk_modulus;             // K(ω), Pa
  std::complex<double> characteristic_impedance; // Z_c = √(ρK), Pa·s/m (Re > 0)
  std::complex<double> wavenumber;               // k = ω√(ρ/K), 1/m (Re > 0, Im < 0)
};

// The wave in `layer` at `frequency` (Hz, > 0). Parameters out of their ranges above, or a
// non-positive frequency: std::invalid_argument (user input is checked by road_absorption.cpp).
PorousLayerWave porous_layer_wave(const PorousLayer& layer, const AirProperties& air, double frequency);

}  // namespace rollnoise
