#pragma once
// Reads the `plate` tyre model and its tread from a [tyre] table (or a model file's top level).
#include <string>

#include "greens/kropp_plate.hpp"

namespace rollnoise {

class ConfigTable;

// The local compliance of the tread ([tyre.tread], MODEL.md §4).
struct TreadSettings {
  enum class Type { winkler, halfspace, nonlinear };
  Type type = Type::winkler;
  double stiffness_per_area = 0.0;  // winkler: N/m³
  // halfspace: the tread's Pa and ν; any type: the rubber that the texture contact law presses
  // onto the road (optional for winkler and nonlinear; 0: not given).
  double youngs_modulus = 0.0;
  double poisson_ratio = 0.0;
  double spring_stiffness = 0.0;    // nonlinear: N/m^exponent per m² of cell (k_p = this·dx·dy)
  double spring_exponent = 1.0;     // nonlinear: n ≥ 1
};

struct PlateTyre {
  PlateParameters plate;
  TreadSettings tread;
  double crown_radius = 0.0;  // m; 0 = flat across
  double tread_width = 0.0;   // m, the width in contact with the road, centred on the belt; 0 = width
};

// Reads [tyre.tread] (required; type winkler, halfspace or nonlinear): the plate's tread, or the
// local compliance a tabulated tyre's table lacks.
TreadSettings read_tread(const ConfigTable& tyre);

// Reads model = "plate"; unknown keys are rejected.
PlateTyre read_plate_tyre(const ConfigTable& tyre);

}  // namespace rollnoise
