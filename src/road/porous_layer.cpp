#include "road/porous_layer.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr Complex i{0.0, 1.0};

void check(const PorousLayer& layer, double frequency) {
  const bool ok = layer.porosity > 0.0 && layer.porosity < 1.0 && layer.flow_resistivity > 0.0 &&
                  std::isfinite(layer.flow_resistivity) && layer.tortuosity >= 1.0 && std::isfinite(layer.tortuosity) &&
                  layer.thickness > 0.0 && std::isfinite(layer.thickness) && frequency > 0.0 && std::isfinite(frequency) &&
                  (layer.model != PorousModel::jca || (layer.viscous_length > 0.0 && layer.thermal_length > 0.0 &&
                                                       std::isfinite(layer.viscous_length) &&
                                                       std::isfinite(layer.thermal_length)));
  if (!ok) throw std::invalid_argument("porous_layer_wave: a layer parameter or the frequency is out of range");
}

}  // namespace

std::string porous_model_name(PorousModel model) {
  return model == PorousModel::jca ? "jca" : "hamet_berengier";
}

PorousLayerWave porous_layer_wave(const PorousLayer& layer, const AirProperties& air, double frequency) {
  check(layer, frequency);
  const double omega = 2.0 * std::numbers::pi * frequency;
  const double rho0 = air.density;
  const double gamma = air.ratio_of_specific_heats;
  const double eta = air.viscosity;
  const double pr = air.prandtl;
  const double phi = layer.porosity;  // Ω
  const double sigma = layer.flow_resistivity;
  const double alpha = layer.tortuosity;
  // The viscous and thermal relaxation terms (Hamet–Bérengier: the square roots are 1).
  Complex viscous = sigma * phi / (i * omega * rho0 * alpha);
  Complex thermal = sigma * phi / (i * omega * rho0 * pr);
  if (layer.model == PorousModel::jca) {
    const double lv = layer.viscous_length;
    const double lt = layer.thermal_length;
    viscous *= std::sqrt(1.0 + 4.0 * i * alpha * alpha * eta * rho0 * omega / (sigma * sigma * lv * lv * phi * phi));
    thermal = 8.0 * eta / (i * lt * lt * pr * omega * rho0) * std::sqrt(1.0 + i * rho0 * omega * pr * lt * lt / (16.0 * eta));
  }
  PorousLayerWave wave;
  wave.density = rho0 * alpha / phi * (1.0 + viscous);
  wave.bulk_modulus = gamma * air.static_pressure / phi / (gamma - (gamma - 1.0) / (1.0 + thermal));
  wave.characteristic_impedance = std::sqrt(wave.density * wave.bulk_modulus);
  wave.wavenumber = omega * std::sqrt(wave.density / wave.bulk_modulus);
  // The principal roots give Re ≥ 0; a wave decaying into the layer has Im k < 0 (e^{iωt}).
  if (wave.wavenumber.imag() > 0.0) wave.wavenumber = -wave.wavenumber;
  if (wave.characteristic_impedance.real() < 0.0) wave.characteristic_impedance = -wave.characteristic_impedance;
  return wave;
}

}  // namespace rollnoise
