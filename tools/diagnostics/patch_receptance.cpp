// A diagnostic for issue 10's energy budget (docs/energy_budget.md): the receptance that a rigid
// flat patch feels, a unit force spread as uniform pressure over the patch and the mean
// displacement over it, for the plate with its Winkler tread and for the two-layer tyre, in the
// third-octave bands where the budget finds the contact force too large. The budget showed that
// from 250 to 500 Hz the model's force is what a rigid patch riding on the patch-mean texture
// produces, so this receptance sets that force: a tyre model whose patch receptance were much
// larger would give a proportionally smaller force.
//
//   patch_receptance [PLATE.toml TWO_LAYER.toml [LENGTH WIDTH]]
//
// Prints one row per band: the band-mean receptances in dB re 1 m/N and their difference.
#include <cmath>
#include <complex>
#include <cstdio>
#include <exception>
#include <numbers>
#include <string>

#include "core/case_file.hpp"
#include "core/config_table.hpp"
#include "greens/plate_factory.hpp"
#include "greens/plate_mobility_average.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_tyre.hpp"

int main(int argc, char** argv) {
  using namespace rollnoise;
  try {
    const std::string plate_path = argc > 2 ? argv[1] : "models/tyres/passenger_205_55R16.toml";
    const std::string layer_path = argc > 2 ? argv[2] : "models/tyres/passenger_205_55R16_two_layer.toml";
    // The patch of the plate tyre under the CPX load (README, "The rolling tyre": 119 × 140 mm).
    const double length = argc > 4 ? std::stod(argv[3]) : 0.12;
    const double width = argc > 4 ? std::stod(argv[4]) : 0.14;
    const PlateTyre plate_tyre = read_plate_tyre(CaseFile::load_model(plate_path).top());
    if (plate_tyre.tread.type != TreadSettings::Type::winkler) throw std::runtime_error("the plate's tread must be winkler");
    const KroppPlate plate(plate_tyre.plate);
    const TwoLayerTyre tyre(read_two_layer_tyre(CaseFile::load_model(layer_path).top()));
    // Winkler springs under a uniform pressure: one compliance 1/(k·A) in series with the belt.
    const double tread = 1.0 / (plate_tyre.tread.stiffness_per_area * length * width);
    const SurfaceLocation patch{0.0, 0.5 * tyre.width(), length, width};
    std::printf("band_hz,plate_with_tread_dB_re_1m_per_N,two_layer_dB_re_1m_per_N,two_layer_minus_plate_dB\n");
    // Per third octave (IEC 61260-1, base 10) 100 Hz … 2 kHz: the mean of |α|² over 8 frequencies
    // spread evenly in log across the band, so that single modal peaks and dips do not decide.
    constexpr int kPerBand = 8;
    for (int x = -10; x <= 3; ++x) {
      const double centre = 1000.0 * std::pow(10.0, x / 10.0);
      double plate_sq = 0.0, layer_sq = 0.0;
      for (int i = 0; i < kPerBand; ++i) {
        const double f = centre * std::pow(10.0, (-0.5 + (i + 0.5) / kPerBand) / 10.0);
        const double omega = 2.0 * std::numbers::pi * f;
        plate_sq += std::norm(patch_receptance(plate, length, width, omega) + tread) / kPerBand;
        layer_sq += std::norm(tyre.at(omega)->receptance(patch, patch)) / kPerBand;
      }
      std::printf("%.0f,%.2f,%.2f,%.2f\n", centre, 10.0 * std::log10(plate_sq), 10.0 * std::log10(layer_sq),
                  10.0 * std::log10(layer_sq / plate_sq));
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "patch_receptance: %s\n", error.what());
    return 2;
  }
  return 0;
}
