#pragma once
// The acoustics of a road's surface, as a [road] table's `absorption` sub-table gives it
// ([road.absorption] in a case, [absorption] in a surface file):
//   model = "rigid" (the default: a perfectly reflecting road) | "hamet_berengier" | "jca"
//   porosity, flow_resistivity (Pa·s/m²), tortuosity, thickness (m) [, viscous_length,
//   thermal_length (m), jca] for one layer, or layers = [{…}, {…}] top first (each may name its
//   own model), over a rigid base (layered_absorber.hpp);
//   temperature (°C, default 20) and static_pressure (Pa, default 101325) of the air.
// Absent: rigid. The rigid road's admittance is exactly 0.
#include <complex>
#include <optional>
#include <string>

#include "road/layered_absorber.hpp"

namespace rollnoise {

class ConfigTable;

struct RoadAbsorption {
  std::string model = "rigid";              // as the file says: "rigid", "hamet_berengier", "jca"
  std::optional<LayeredAbsorber> absorber;  // none: rigid
  AirProperties air = air_at();             // the air above (and in) the road

  bool rigid() const noexcept { return !absorber; }
  // β = ρ₀c₀/Z_s at normal incidence (e^{+iωt}); 0 exactly for a rigid road.
  std::complex<double> normalised_admittance(double frequency) const;
};

// Reads `absorption` from the [road] table `road` (and marks it known). Bad values are
// InputErrors naming the file and "[road.absorption] key" (or "[road.absorption.layers[n]] key")
// with what is allowed.
RoadAbsorption read_road_absorption(const ConfigTable& road);

}  // namespace rollnoise
