#include "simulation/road_acoustics.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>

#include "acoustics/fractional_octave_bands.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "radiation/impedance_plane_green.hpp"

namespace rollnoise {
namespace {

// The third octaves of the reports: 100 Hz to 10 kHz, at their exact mid-band frequencies.
std::vector<FractionalOctaveBand> report_bands() { return fractional_octave_bands(3, 100.0, 10000.0); }

}  // namespace

std::vector<AbsorptionBand> absorption_bands(const RoadAbsorption& absorption) {
  std::vector<AbsorptionBand> out;
  for (const FractionalOctaveBand& band : report_bands()) {
    AbsorptionBand row;
    row.band_hz = band.exact;
    if (absorption.absorber) {
      row.impedance = absorption.absorber->normalised_impedance(band.exact);
      row.alpha = absorption.absorber->absorption_coefficient(band.exact);
    } else {
      row.impedance = {std::numeric_limits<double>::infinity(), 0.0};
    }
    out.push_back(row);
  }
  return out;
}

void check_ground_effect_geometry(const GroundEffectGeometry& geometry, const std::string& source,
                                  const std::string& key) {
  const auto bad = [](double v) { return !(v > 0.0) || !std::isfinite(v); };
  if (bad(geometry.source_height) || bad(geometry.distance) || bad(geometry.receiver_height))
    throw InputError(source, key,
                     "must be three positive distances in m, HS,D,HR: the source height, the horizontal distance and "
                     "the receiver height (got " + format_number(geometry.source_height) + "," +
                         format_number(geometry.distance) + "," + format_number(geometry.receiver_height) + ")");
}

std::vector<GroundEffectBand> ground_effect_bands(const RoadAbsorption& absorption, const GroundEffectGeometry& geometry,
                                                  int frequencies_per_band) {
  check_ground_effect_geometry(geometry, "", "ground effect geometry");
  const double c = absorption.air.sound_speed;
  const auto fields = [&](double frequency) {
    const double k = 2.0 * std::numbers::pi * frequency / c;
    const auto at = [&](std::complex<double> beta) {
      return impedance_plane_green(k, geometry.distance, geometry.receiver_height, geometry.source_height, beta);
    };
    return std::pair{at(absorption.normalised_admittance(frequency)), at(0.0)};
  };
  std::vector<GroundEffectBand> out;
  for (const FractionalOctaveBand& band : report_bands()) {
    GroundEffectBand row;
    row.band_hz = band.exact;
    const auto [g, rigid] = fields(band.exact);
    row.delta_db = 20.0 * std::log10(std::abs(g) / std::abs(rigid));
    double energy = 0.0, rigid_energy = 0.0;
    const double span = std::log(band.upper / band.lower);
    for (int n = 0; n < frequencies_per_band; ++n) {
      const double f = band.lower * std::exp(span * (n + 0.5) / frequencies_per_band);
      const auto [gf, rf] = fields(f);
      energy += std::norm(gf);
      rigid_energy += std::norm(rf);
    }
    row.delta_band_db = 10.0 * std::log10(energy / rigid_energy);
    out.push_back(row);
  }
  return out;
}

void write_absorption_csv(const std::filesystem::path& path, const std::vector<AbsorptionBand>& bands) {
  std::ofstream out(path);
  CsvWriter csv(out, {"band_hz", "alpha", "z_re", "z_im"});
  for (const AbsorptionBand& b : bands) {
    const double row[] = {b.band_hz, b.alpha, b.impedance.real(), b.impedance.imag()};
    csv.row(row, 4);
  }
  close_output_file(out, path);
}

void write_ground_effect_csv(const std::filesystem::path& path, const std::vector<GroundEffectBand>& bands) {
  std::ofstream out(path);
  CsvWriter csv(out, {"band_hz", "delta_dB", "delta_band_dB"});
  for (const GroundEffectBand& b : bands) {
    const double row[] = {b.band_hz, b.delta_db, b.delta_band_db};
    csv.row(row, 3);
  }
  close_output_file(out, path);
}

nlohmann::json absorption_summary(const RoadAbsorption& absorption, const std::vector<AbsorptionBand>& bands) {
  nlohmann::json out;
  out["model"] = absorption.model;
  out["air"] = {{"temperature_c", absorption.air.temperature_c},
                {"static_pressure_Pa", absorption.air.static_pressure},
                {"density_kg_m3", absorption.air.density},
                {"sound_speed_m_s", absorption.air.sound_speed},
                {"viscosity_Pa_s", absorption.air.viscosity},
                {"prandtl", absorption.air.prandtl},
                {"ratio_of_specific_heats", absorption.air.ratio_of_specific_heats}};
  out["layers"] = nlohmann::json::array();
  if (absorption.absorber) {
    for (const PorousLayer& layer : absorption.absorber->layers()) {
      nlohmann::json entry{{"model", porous_model_name(layer.model)},
                           {"porosity", layer.porosity},
                           {"flow_resistivity_Pa_s_m2", layer.flow_resistivity},
                           {"tortuosity", layer.tortuosity},
                           {"thickness_m", layer.thickness}};
      if (layer.model == PorousModel::jca) {
        entry["viscous_length_m"] = layer.viscous_length;
        entry["thermal_length_m"] = layer.thermal_length;
      }
      out["layers"].push_back(entry);
    }
  }
  const AbsorptionBand* peak = nullptr;
  for (const AbsorptionBand& b : bands)
    if (!peak || b.alpha > peak->alpha) peak = &b;
  if (peak && absorption.absorber) {
    out["peak_alpha"] = peak->alpha;
    out["peak_band_hz"] = peak->band_hz;
  }
  return out;
}

nlohmann::json ground_effect_summary(const GroundEffectGeometry& geometry, const std::vector<GroundEffectBand>& bands) {
  nlohmann::json out{{"source_height_m", geometry.source_height},
                     {"distance_m", geometry.distance},
                     {"receiver_height_m", geometry.receiver_height}};
  const GroundEffectBand* lowest = nullptr;
  for (const GroundEffectBand& b : bands)
    if (!lowest || b.delta_band_db < lowest->delta_band_db) lowest = &b;
  if (lowest) {
    out["min_delta_band_dB"] = lowest->delta_band_db;
    out["min_delta_band_hz"] = lowest->band_hz;
  }
  return out;
}

}  // namespace rollnoise
