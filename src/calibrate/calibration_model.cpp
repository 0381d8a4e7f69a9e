#include "calibrate/calibration_model.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rollnoise {

std::ptrdiff_t CalibrationModel::index_of(const std::string& name) const {
  const auto& p = parameters();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i].name == name) return static_cast<std::ptrdiff_t>(i);
  return -1;
}

std::vector<double> CalibrationModel::file_values() const {
  std::vector<double> values;
  for (const FitParameter& p : parameters()) values.push_back(p.value);
  return values;
}

void central_difference_gradient(const ReceptanceFunction& function, const std::vector<FitParameter>& parameters,
                                 std::span<const double> values, double omega, std::complex<double>* gradient,
                                 std::span<const std::size_t> wanted) {
  std::vector<double> shifted(values.begin(), values.end());
  for (std::size_t k : wanted) {
    // A relative step of 1e-6 balances truncation (∝ h²) against rounding (∝ ε/h) for
    // receptances that are smooth in the parameter.
    const double v = values[k];
    const double h = parameters[k].log_scale ? 1e-6 * std::abs(v) : 1e-6 * std::max(1.0, std::abs(v));
    shifted[k] = v + h;
    const std::complex<double> up = function.evaluate(shifted, omega, nullptr, {});
    shifted[k] = v - h;
    const std::complex<double> down = function.evaluate(shifted, omega, nullptr, {});
    shifted[k] = v;
    gradient[k] = (up - down) / (2.0 * h);
  }
}

FitParameter log_parameter(std::string name, std::string unit, double value, double floor, double ceiling) {
  FitParameter p;
  p.name = std::move(name);
  p.unit = std::move(unit);
  p.value = value;
  p.log_scale = true;
  // A thousand either way spans what a first estimate can be off by, and keeps the modal
  // frequencies of the plate (∝ √stiffness) within a factor of 32 of the file's.
  p.lower = std::max(value * 1e-3, floor);
  p.upper = std::max(std::min(value * 1e3, ceiling), value);
  return p;
}

}  // namespace rollnoise
