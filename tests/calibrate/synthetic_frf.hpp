#pragma once
// Synthetic measurements: a model's mobility with seeded complex noise, Y·(1 + ε) with
// ε = level·(a + ib)/√2 and a, b standard normal (so E|ε|² = level²): "5 % complex noise"
// is level = 0.05. The normal numbers come from Box-Muller on std::mt19937_64's bits, the same
// on every platform.
#include <cstdint>
#include <random>
#include <vector>

#include "calibrate/calibration_model.hpp"
#include "calibrate/measured_frf.hpp"
#include "greens/kropp_plate.hpp"

namespace rollnoise::testing {

class NormalSource {
 public:
  explicit NormalSource(std::uint64_t seed) : rng_(seed) {}
  double next();

 private:
  std::mt19937_64 rng_;
  bool have_spare_ = false;
  double spare_ = 0.0;
};

// Frequencies first, first + step, ... up to last (inclusive, within rounding).
std::vector<double> linear_frequencies(double first, double last, double step);

// The model's mobility with `values` between `points` (with a transducer of `mass` kg at the
// response), times (1 + ε) with noise `level`; `points` become the FRF's positions.
MeasuredFrf synthetic_frf(const CalibrationModel& model, const std::vector<double>& values, const FrfPoints& points,
                          const std::vector<double>& frequency_hz, double level, NormalSource& noise, double mass = 0.0,
                          const std::string& name = "synthetic");

// The "true" tyre behind data/mobility (data/mobility/README.md): the passenger 205/55 R16 of
// models/tyres/passenger_205_55R16.toml, with its 256 × 25 modes, and tension_x, bending_x,
// foundation_stiffness and loss_factor changed from the file's estimates.
PlateParameters example_tyre_truth();

}  // namespace rollnoise::testing
