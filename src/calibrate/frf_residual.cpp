#include "calibrate/frf_residual.hpp"

#include <cmath>
#include <numbers>

namespace rollnoise {

void FitLayout::values(const double* x, std::vector<double>& model_values, double& mass) const {
  model_values.resize(parameters.size());
  for (std::size_t k = 0; k < parameters.size(); ++k) model_values[k] = parameters[k].value;
  for (std::size_t j = 0; j < free.size(); ++j) {
    const FitParameter& p = parameters[free[j]];
    model_values[free[j]] = p.log_scale ? std::exp(x[j]) : x[j];
  }
  mass = fit_transducer_mass ? std::exp(x[free.size()]) : transducer_mass;
}

std::vector<double> FitLayout::unknowns_of(const std::vector<double>& model_values, double mass) const {
  std::vector<double> x;
  for (std::size_t k : free) x.push_back(parameters[k].log_scale ? std::log(model_values[k]) : model_values[k]);
  if (fit_transducer_mass) x.push_back(std::log(mass));
  return x;
}

double FitLayout::value_per_unknown(std::size_t j, const std::vector<double>& model_values, double mass) const {
  if (j == free.size()) return mass;  // the transducer mass, log-scaled
  return parameters[free[j]].log_scale ? model_values[free[j]] : 1.0;
}

FrfPointResidual::FrfPointResidual(const FitLayout& layout, const ReceptanceFunction& transfer,
                                   const ReceptanceFunction* at_response, double frequency_hz,
                                   std::complex<double> measured_mobility)
    : layout_(layout),
      transfer_(transfer),
      at_response_(at_response),
      omega_(2.0 * std::numbers::pi * frequency_hz),
      measured_(measured_mobility) {
  set_num_residuals(2);
  mutable_parameter_block_sizes()->push_back(static_cast<int>(layout.unknowns()));
}

std::complex<double> FrfPointResidual::measured_receptance(const double* x, std::complex<double>* gradient) const {
  thread_local std::vector<double> values;
  thread_local std::vector<std::complex<double>> d_transfer, d_point;
  double mass = 0.0;
  layout_.values(x, values, mass);
  const std::size_t n = layout_.parameters.size();
  d_transfer.assign(n, 0.0);
  const std::span<const std::size_t> wanted = gradient ? std::span<const std::size_t>(layout_.free)
                                                       : std::span<const std::size_t>();
  const std::complex<double> alpha = transfer_.evaluate(values, omega_, d_transfer.data(), wanted);
  if (!layout_.mass_loaded()) {
    if (gradient)
      for (std::size_t j = 0; j < layout_.free.size(); ++j)
        gradient[j] = d_transfer[layout_.free[j]] * layout_.value_per_unknown(j, values, mass);
    return alpha;
  }
  // α_meas = α_re/D with D = 1 − m_t ω² α_rr.
  std::complex<double> alpha_rr = alpha;
  const std::vector<std::complex<double>>* d_rr = &d_transfer;
  if (at_response_) {
    d_point.assign(n, 0.0);
    alpha_rr = at_response_->evaluate(values, omega_, d_point.data(), wanted);
    d_rr = &d_point;
  }
  const double w2 = omega_ * omega_;
  const std::complex<double> D = 1.0 - mass * w2 * alpha_rr;
  const std::complex<double> result = alpha / D;
  if (gradient) {
    for (std::size_t j = 0; j < layout_.free.size(); ++j) {
      const std::size_t k = layout_.free[j];
      const std::complex<double> d = d_transfer[k] / D + alpha * mass * w2 * (*d_rr)[k] / (D * D);
      gradient[j] = d * layout_.value_per_unknown(j, values, mass);
    }
    if (layout_.fit_transducer_mass)
      gradient[layout_.free.size()] = alpha * w2 * alpha_rr / (D * D) * mass;  // d/d(log m_t)
  }
  return result;
}

std::complex<double> FrfPointResidual::model_mobility(const double* x) const {
  return std::complex<double>(0.0, omega_) * measured_receptance(x, nullptr);
}

bool FrfPointResidual::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const double* x = parameters[0];
  const std::size_t unknowns = layout_.unknowns();
  thread_local std::vector<std::complex<double>> gradient;
  const bool want_jacobian = jacobians != nullptr && jacobians[0] != nullptr;
  gradient.assign(unknowns, 0.0);
  const std::complex<double> alpha = measured_receptance(x, want_jacobian ? gradient.data() : nullptr);
  const std::complex<double> ratio = std::complex<double>(0.0, omega_) * alpha / measured_;
  if (!std::isfinite(ratio.real()) || !std::isfinite(ratio.imag()) || ratio == 0.0) return false;
  residuals[0] = std::log(std::abs(ratio));
  residuals[1] = std::arg(ratio);  // (−π, π]
  if (want_jacobian) {
    // Row-major 2 × unknowns: d log(α)/dx = (dα/dx)/α.
    for (std::size_t j = 0; j < unknowns; ++j) {
      const std::complex<double> d = gradient[j] / alpha;
      jacobians[0][j] = d.real();
      jacobians[0][unknowns + j] = d.imag();
    }
  }
  return true;
}

}  // namespace rollnoise
