#pragma once
// Reads the `two_layer` tyre model from a [tyre] table (or a model file's top level). The keys,
// all SI (models/tyres/passenger_205_55R16_two_layer.toml documents each):
//   model = "two_layer"
//   radius, width                                              m
//   belt_thickness (m), belt_density (kg/m³),
//   belt_youngs_modulus_x, _y, _z, belt_shear_modulus_xy, _xz, _yz (Pa),
//   belt_poisson_xy, belt_poisson_xz, belt_poisson_yz, belt_loss_factor
//   tread_thickness (m), tread_density (kg/m³), tread_youngs_modulus (Pa), tread_poisson_ratio,
//   tread_loss_factor
//   tension_x, tension_y (N/m), foundation_stiffness (N/m³),
//   foundation_loss_factor (optional, default 0)
//   circumferential_modes (M ≥ 0), lateral_modes (N ≥ 1),
//   side_condition = "simply_supported" (default) | "sliding"
//   crown_radius (m, optional, 0 = flat), tread_width (m, optional, default width): the contact
//   geometry, as in the plate file
// Moduli are storage moduli and loss factors are at 1 kHz (causal_modulus.hpp). Unknown keys
// and non-physical values are an InputError naming the file, the key and what is allowed.
#include "greens/two_layer_tyre.hpp"

namespace rollnoise {

class ConfigTable;

TwoLayerParameters read_two_layer_tyre(const ConfigTable& tyre);

}  // namespace rollnoise
