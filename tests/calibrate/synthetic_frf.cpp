#include "calibrate/synthetic_frf.hpp"

#include <cmath>
#include <numbers>

namespace rollnoise::testing {

double NormalSource::next() {
  if (have_spare_) {
    have_spare_ = false;
    return spare_;
  }
  // Box-Muller with u1 in (0, 1] so the log is finite.
  const double u1 = (static_cast<double>(rng_() >> 11U) + 1.0) * 0x1.0p-53;
  const double u2 = static_cast<double>(rng_() >> 11U) * 0x1.0p-53;
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(2.0 * std::numbers::pi * u2);
  have_spare_ = true;
  return r * std::cos(2.0 * std::numbers::pi * u2);
}

std::vector<double> linear_frequencies(double first, double last, double step) {
  std::vector<double> f;
  for (int k = 0;; ++k) {
    const double hz = first + step * k;
    if (hz > last * (1.0 + 1e-12)) break;
    f.push_back(hz);
  }
  return f;
}

MeasuredFrf synthetic_frf(const CalibrationModel& model, const std::vector<double>& values, const FrfPoints& points,
                          const std::vector<double>& frequency_hz, double level, NormalSource& noise, double mass,
                          const std::string& name) {
  const auto transfer = model.receptance(points);
  const auto at_response = model.receptance({points.response, points.response});
  MeasuredFrf frf;
  frf.source = name;
  frf.response = points.response;
  frf.excitation = points.excitation;
  const auto n = static_cast<Eigen::Index>(frequency_hz.size());
  frf.frequency_hz.resize(n);
  frf.mobility.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double hz = frequency_hz[static_cast<std::size_t>(k)];
    const double omega = 2.0 * std::numbers::pi * hz;
    std::complex<double> alpha = transfer->evaluate(values, omega, nullptr, {});
    if (mass > 0.0) alpha /= 1.0 - mass * omega * omega * at_response->evaluate(values, omega, nullptr, {});
    const double a = noise.next();
    const double b = noise.next();
    const std::complex<double> epsilon = level * std::complex<double>(a, b) / std::sqrt(2.0);
    frf.frequency_hz[k] = hz;
    frf.mobility[k] = std::complex<double>(0.0, omega) * alpha * (1.0 + epsilon);
  }
  return frf;
}

PlateParameters example_tyre_truth() {
  PlateParameters p;
  p.radius = 0.316;
  p.width = 0.18;
  p.mass_per_area = 12.0;
  p.tension_x = 5.2e4;
  p.tension_y = 9.0e3;
  p.bending_x = 5.5;
  p.bending_y = 3.0;
  p.bending_xy = 4.6;
  p.foundation_stiffness = 2.7e6;
  p.loss_factor = 0.08;
  p.circumferential_modes = 256;
  p.lateral_modes = 25;
  return p;
}

}  // namespace rollnoise::testing
