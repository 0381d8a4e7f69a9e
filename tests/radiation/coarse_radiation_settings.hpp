#pragma once
// A coarse tyre mesh with one level for the band to 600 Hz, for the tests where the radiation
// stage, not the mesh, is under test (test_radiation_stage.cpp, test_radiation_stream.cpp).
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {

inline TyreRadiationSettings coarse_radiation_settings() {
  TyreRadiationSettings settings;
  settings.mesh.around = 48;
  settings.mesh.across = 4;
  settings.mesh.sidewall_rings = 6;
  settings.max_frequency_hz = 600.0;
  settings.anchor_spacing_hz = 100.0;
  return settings;
}

}  // namespace rollnoise
