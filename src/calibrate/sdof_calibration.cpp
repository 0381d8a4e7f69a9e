#include "calibrate/sdof_calibration.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include <ceres/jet.h>

#include "core/error.hpp"

namespace rollnoise {
namespace {

// Parameter order: mass, damping, stiffness, contact_stiffness, coupling (coupled only).
constexpr std::size_t max_parameters = 5;
using Jet = ceres::Jet<double, static_cast<int>(max_parameters)>;

// α = factor·(1/s + 1/(a + ib)) with a = k − mω², b = ωr, as real and imaginary parts.
template <typename T>
void sdof_receptance(const T& m, const T& r, const T& k, const T& s, const T& factor, double omega, T& re, T& im) {
  const T a = k - m * (omega * omega);
  const T b = r * omega;
  const T inv = T(1.0) / (a * a + b * b);
  re = factor * (T(1.0) / s + a * inv);
  im = factor * (-b * inv);
}

class SdofReceptance : public ReceptanceFunction {
 public:
  // `transfer`: the receptance between the two points (scaled by the coupling).
  explicit SdofReceptance(bool transfer) : transfer_(transfer) {}

  std::complex<double> evaluate(std::span<const double> values, double omega, std::complex<double>* gradient,
                                std::span<const std::size_t> wanted) const override {
    if (gradient == nullptr || wanted.empty()) {
      double re = 0.0, im = 0.0;
      sdof_receptance(values[0], values[1], values[2], values[3], transfer_ ? values[4] : 1.0, omega, re, im);
      return {re, im};
    }
    Jet v[max_parameters];
    for (std::size_t i = 0; i < values.size() && i < max_parameters; ++i)
      v[i] = Jet(values[i], static_cast<int>(i));
    Jet re, im;
    sdof_receptance(v[0], v[1], v[2], v[3], transfer_ ? v[4] : Jet(1.0), omega, re, im);
    for (std::size_t k : wanted) gradient[k] = {re.v[static_cast<Eigen::Index>(k)], im.v[static_cast<Eigen::Index>(k)]};
    return {re.a, im.a};
  }

 private:
  bool transfer_;
};

}  // namespace

SdofCalibration::SdofCalibration(const SdofParameters& p, bool coupled, double coupling, double spacing)
    : coupled_(coupled), spacing_(spacing) {
  parameters_.push_back(log_parameter("mass", "kg", p.mass));
  parameters_.push_back(log_parameter("damping", "N*s/m", p.damping));
  parameters_.push_back(log_parameter("stiffness", "N/m", p.stiffness));
  parameters_.push_back(log_parameter("contact_stiffness", "N/m", p.contact_stiffness));
  if (coupled_) {
    // May be negative; G[0] stays positive definite for |c| < 1 (fitted linearly, not in log space).
    parameters_.push_back(FitParameter{"coupling", "1", coupling, -0.99, 0.99, false});
  }
}

std::vector<std::string> SdofCalibration::default_free_parameters() const {
  std::vector<std::string> names;
  for (const auto& p : parameters_) names.push_back(p.name);
  return names;
}

std::unique_ptr<ReceptanceFunction> SdofCalibration::receptance(const FrfPoints& points) const {
  // Which contact point a position is: x = 0 the first, x = spacing the second.
  const double tolerance = 1e-9 + 1e-6 * std::abs(spacing_);
  const auto point_of = [&](const BeltPosition& position, const char* what) {
    if (std::abs(position.x) <= tolerance) return 0;
    if (coupled_ && std::abs(position.x - spacing_) <= tolerance) return 1;
    std::ostringstream problem;
    problem << "the " << what << " position x = " << position.x << " m is not a contact point of the " << name()
            << " model; its points are at x = 0" << (coupled_ ? " and x = spacing = " : "");
    if (coupled_) problem << spacing_;
    problem << " m";
    throw InputError("", "", problem.str());
  };
  const int response = point_of(points.response, "response");
  const int excitation = point_of(points.excitation, "excitation");
  return std::make_unique<SdofReceptance>(response != excitation);
}

double SdofCalibration::highest_frequency_hz() const { return std::numeric_limits<double>::infinity(); }

}  // namespace rollnoise
