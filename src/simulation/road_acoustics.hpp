#pragma once
// What `rollnoise road` reports of a surface's acoustics (road/road_absorption.hpp): the
// normal-incidence absorption and impedance per third-octave band, and the ground effect of the
// surface on a point source against a rigid road (radiation/impedance_plane_green.hpp), in
// absorption.csv and ground_effect.csv.
#include <complex>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "road/road_absorption.hpp"

namespace rollnoise {

struct AbsorptionBand {
  double band_hz = 0.0;            // the exact third-octave mid-band frequency (IEC 61260-1)
  double alpha = 0.0;              // normal-incidence absorption coefficient
  std::complex<double> impedance;  // Z_s/(ρ₀c₀), e^{+iωt}
};

// The bands 100 Hz – 10 kHz. A rigid surface: α = 0 and an infinite impedance.
std::vector<AbsorptionBand> absorption_bands(const RoadAbsorption& absorption);

// A point source `source_height` above the road, a receiver `receiver_height` above it at the
// horizontal `distance` (all m, > 0).
struct GroundEffectGeometry {
  double source_height = 0.0;
  double distance = 0.0;
  double receiver_height = 0.0;
};

// Checks a geometry given on the command line (or by a caller): every value > 0 and finite, else
// an InputError naming `source` and `key` (such as "command line", "--ground-effect").
void check_ground_effect_geometry(const GroundEffectGeometry& geometry, const std::string& source,
                                  const std::string& key);

struct GroundEffectBand {
  double band_hz = 0.0;        // exact third-octave mid-band frequency
  double delta_db = 0.0;       // 20 lg |G/G_rigid| at band_hz
  double delta_band_db = 0.0;  // 10 lg (Σ|G|² / Σ|G_rigid|²) over frequencies_per_band in the band
};

// The level over this surface minus that over a rigid road, per band 100 Hz – 10 kHz; the band
// value is the energy average over `frequencies_per_band` frequencies spread evenly in
// log-frequency across the band (the centres of as many equal sub-bands). The rigid road: 0 dB.
std::vector<GroundEffectBand> ground_effect_bands(const RoadAbsorption& absorption, const GroundEffectGeometry& geometry,
                                                  int frequencies_per_band = 9);

// absorption.csv (band_hz,alpha,z_re,z_im) and ground_effect.csv (band_hz,delta_dB,delta_band_dB).
void write_absorption_csv(const std::filesystem::path& path, const std::vector<AbsorptionBand>& bands);
void write_ground_effect_csv(const std::filesystem::path& path, const std::vector<GroundEffectBand>& bands);

// What summary.json says of them: the model, its layers and air, the band of highest α; the
// geometry and the band of the largest attenuation.
nlohmann::json absorption_summary(const RoadAbsorption& absorption, const std::vector<AbsorptionBand>& bands);
nlohmann::json ground_effect_summary(const GroundEffectGeometry& geometry, const std::vector<GroundEffectBand>& bands);

}  // namespace rollnoise
