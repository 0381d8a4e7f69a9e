#pragma once
// Porous layers over a rigid base (a porous road on its dense binder course), locally reacting:
// the surface impedance at normal incidence from the layers' transfer matrices (Allard & Atalla,
// Propagating Sound in Porous Media, 2nd ed. (2009) §11.2). Time dependence e^{+iωt}. For one
// layer of thickness d this is Z = −i Z_c cot(k d).
//
// Local reaction (the impedance does not depend on the angle of incidence) holds when the wave
// in the layer travels nearly normal to the surface whatever the incidence: |k_layer| ≫ k₀, or
// a layer so lossy that a wave entering it dies out before it travels sideways. Porous asphalt
// (|k/k₀| ≈ √α∞ ≈ 1.5–2.5 at kHz) is only marginally so: at grazing incidence over a thick
// layer the extended-reaction impedance differs (the refraction angle in the layer reaches
// asin(k₀/|k|) ≈ 25–40°, so the wave's normal wavenumber k·cos θ_t is 10–35 % below k and the
// layer's quarter-wave peaks move up by as much at grazing incidence, which this model omits).
#include <complex>
#include <vector>

#include "road/air_properties.hpp"
#include "road/porous_layer.hpp"

namespace rollnoise {

class LayeredAbsorber {
 public:
  // `layers` top first, at least one (std::invalid_argument otherwise); each as porous_layer_wave
  // accepts.
  LayeredAbsorber(std::vector<PorousLayer> layers, AirProperties air);

  const std::vector<PorousLayer>& layers() const noexcept { return layers_; }
  const AirProperties& air() const noexcept { return air_; }

  // Z_s/(ρ₀c₀) at normal incidence, `frequency` Hz > 0 (Re > 0 for a passive surface).
  std::complex<double> normalised_impedance(double frequency) const;
  // The normal-incidence absorption coefficient 1 − |(Z − 1)/(Z + 1)|².
  double absorption_coefficient(double frequency) const;

 private:
  std::vector<PorousLayer> layers_;
  AirProperties air_;
};

}  // namespace rollnoise
