#pragma once
// The residual of one measured frequency line (MODEL.md §6): the complex log of the model's
// mobility over the measured one,
//
//   r = log(Y_model/Y_measured) = ln|Y_model/Y_measured| + i·arg(Y_model/Y_measured),
//
// split into its real part (the log-magnitude ratio; 0.1 ≈ 0.87 dB) and its imaginary part
// (the phase difference in rad, wrapped to (−π, π]). Magnitude and phase are both fitted, a
// factor of two reads the same at every level (the data's scale drops out), and measurement
// noise that is a fraction of the value gives residuals of the same size everywhere.
//
// With a transducer of mass m_t at the response point (mass loading), the response of the
// structure with the mass attached is u_r = α_re F + α_rr m_t ω² u_r, so the measured
// receptance is α_re/(1 − m_t ω² α_rr) (for a point FRF Y/(1 + iω m_t Y)).
//
// The fit's unknowns x are the free parameters in their fit coordinates: log(p) for
// log-scaled parameters (FitParameter::log_scale), p for the others. d r/dx = (dα/dx)/α: the
// Jacobian is exact wherever the model's gradient is.
#include <complex>
#include <cstddef>
#include <vector>

#include <ceres/cost_function.h>

#include "calibrate/calibration_model.hpp"

namespace rollnoise {

// Which parameters the fit frees and how they map from the unknowns x.
struct FitLayout {
  std::vector<FitParameter> parameters;  // all of the model's, values from the model file
  std::vector<std::size_t> free;         // indices into parameters, in the order of x
  // The transducer mass at the response points (kg): fixed at `transducer_mass`, or the last
  // unknown of x (fitted in log space) when `fit_transducer_mass`.
  double transducer_mass = 0.0;
  bool fit_transducer_mass = false;

  std::size_t unknowns() const { return free.size() + (fit_transducer_mass ? 1 : 0); }
  // The model's parameter values for unknowns x (fixed ones from the file), and the mass.
  void values(const double* x, std::vector<double>& model_values, double& mass) const;
  // x for model values and mass.
  std::vector<double> unknowns_of(const std::vector<double>& model_values, double mass) const;
  // d(value)/dx of unknown j: value for log-scaled, 1 for linear.
  double value_per_unknown(std::size_t j, const std::vector<double>& model_values, double mass) const;
  bool mass_loaded() const { return fit_transducer_mass || transducer_mass > 0.0; }
};

class FrfPointResidual : public ceres::CostFunction {
 public:
  // `transfer`: the model's receptance from the excitation to the response; `at_response`:
  // the point receptance at the response (for mass loading), nullptr when it is `transfer`
  // itself (a point FRF). Both must outlive this object.
  FrfPointResidual(const FitLayout& layout, const ReceptanceFunction& transfer, const ReceptanceFunction* at_response,
                   double frequency_hz, std::complex<double> measured_mobility);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  // The model's mobility as measured (with the transducer's mass), m/(N·s), for unknowns x.
  std::complex<double> model_mobility(const double* x) const;

 private:
  // α as measured, and when `gradient` is given its derivative per unknown.
  std::complex<double> measured_receptance(const double* x, std::complex<double>* gradient) const;

  const FitLayout& layout_;
  const ReceptanceFunction& transfer_;
  const ReceptanceFunction* at_response_;
  double omega_;
  std::complex<double> measured_;
};

}  // namespace rollnoise
