#include "greens/sdof_model.hpp"

#include <algorithm>
#include <cmath>

namespace rollnoise {

SdofModel::SdofModel(const SdofParameters& parameters)
    : parameters_(parameters),
      oscillator_{parameters.mass, parameters.damping, parameters.stiffness},
      coupling_(Eigen::MatrixXd::Ones(1, 1)),
      offsets_{0.0} {}

SdofModel::SdofModel(const SdofParameters& parameters, double coupling, double spacing)
    : parameters_(parameters),
      oscillator_{parameters.mass, parameters.damping, parameters.stiffness},
      coupling_((Eigen::MatrixXd(2, 2) << 1.0, coupling, coupling, 1.0).finished()),
      offsets_{0.0, spacing} {}

std::string SdofModel::name() const { return point_count() == 1 ? "sdof" : "coupled_sdof"; }

Eigen::MatrixXd SdofModel::local_compliance() const {
  return coupling_ / parameters_.contact_stiffness;
}

Eigen::MatrixXd SdofModel::smooth_response(double t) const {
  return coupling_ * oscillator_.impulse_response(t);
}

Eigen::MatrixXd SdofModel::smooth_integral(double t0, double t1) const {
  return coupling_ * (oscillator_.step_response(t1) - oscillator_.step_response(t0));
}

Eigen::MatrixXcd SdofModel::receptance(double omega) const {
  const std::complex<double> alpha = 1.0 / parameters_.contact_stiffness + oscillator_.receptance(omega);
  return coupling_.cast<std::complex<double>>() * alpha;
}

double SdofModel::slowest_decay_rate() const { return oscillator_.slowest_decay_rate(); }

double SdofModel::fastest_rate() const {
  // In contact the contact spring adds to k: the mass then moves on m λ² + r λ + (k + s).
  const SdofOscillator in_contact{parameters_.mass, parameters_.damping,
                                  parameters_.stiffness + parameters_.contact_stiffness};
  return std::max(oscillator_.fastest_rate(), in_contact.fastest_rate());
}

}  // namespace rollnoise
