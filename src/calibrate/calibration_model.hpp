#pragma once
// What the fit needs from a Green's-function model (MODEL.md §6): its fittable parameters
// (model-file keys, values from the file, physical bounds) and its receptance between two
// points as a function of them, with derivatives.
//
// sdof and coupled_sdof differentiate automatically (ceres::Jet), the plate analytically;
// any other GreensModel that make_greens_model builds is calibrated through its receptance(ω)
// with central differences (greens_model_calibration.hpp). Every kind is checked against
// finite differences in tests/calibrate.
#include <complex>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "calibrate/measured_frf.hpp"

namespace rollnoise {

struct FitParameter {
  std::string name;     // the model-file key, such as "tension_x"
  std::string unit;     // SI unit, for reports
  double value = 0.0;   // from the model file
  double lower = 0.0;   // physical bounds of the fit
  double upper = 0.0;
  bool log_scale = true;  // fitted as log(value); false: as the value (a coupling may be negative)
};

// Where an FRF was measured: a force at `excitation`, the response at `response`.
struct FrfPoints {
  BeltPosition response;
  BeltPosition excitation;
};

// The model's receptance between two fixed points as a function of its parameters.
class ReceptanceFunction {
 public:
  virtual ~ReceptanceFunction() = default;
  // α(ω) in m/N for `values` (one per CalibrationModel::parameters(), in that order). When
  // `gradient` is not null, gradient[k] receives ∂α/∂values[k] for every k in `wanted` (other
  // entries may be left untouched).
  virtual std::complex<double> evaluate(std::span<const double> values, double omega,
                                        std::complex<double>* gradient,
                                        std::span<const std::size_t> wanted) const = 0;
};

class CalibrationModel {
 public:
  virtual ~CalibrationModel() = default;

  // The model-file `model` value: "sdof", "coupled_sdof", "plate", ...
  virtual std::string name() const = 0;
  // Every parameter a fit may free, with its value from the model file.
  virtual const std::vector<FitParameter>& parameters() const = 0;
  // The parameters freed when the user names none.
  virtual std::vector<std::string> default_free_parameters() const = 0;
  // True when an FRF must say where it was measured (tyre models); point models take the
  // first contact point when it does not.
  virtual bool needs_positions() const = 0;
  // The receptance from a force at points.excitation to the response at points.response.
  // Positions the model cannot place are an InputError with an empty source (the caller
  // names the FRF).
  virtual std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const = 0;
  // The highest frequency (Hz) at which the model is valid (the reach of its modal
  // truncation); +infinity when unlimited.
  virtual double highest_frequency_hz() const = 0;
  // The top of the first band of a fit by frequency continuation (calibration.hpp), Hz; 0: the
  // model's cost is smooth enough to fit the whole band at once (the default).
  virtual double first_stage_hz() const { return 0.0; }
  // The relative change of the cost below which a fit stops. It must lie above the rounding of
  // the model's cost and the error of its derivatives, or the fit goes on stepping in that
  // noise until its trust region collapses.
  virtual double function_tolerance() const { return 1e-12; }
  // The starts a fit makes when the user names none (`rollnoise calibrate` without --starts).
  virtual int default_starts() const { return 8; }

  // The index of a parameter by name; -1 when the model has no such parameter.
  std::ptrdiff_t index_of(const std::string& name) const;
  // The values of all parameters from the model file.
  std::vector<double> file_values() const;
};

// ∂α/∂values[k] for k in `wanted` by central differences (relative step 1e-6 in log-scaled
// parameters, 1e-6·max(1, |value|) in the others): for models that offer no derivatives.
void central_difference_gradient(const ReceptanceFunction& function, const std::vector<FitParameter>& parameters,
                                 std::span<const double> values, double omega, std::complex<double>* gradient,
                                 std::span<const std::size_t> wanted);

// Bounds for a positive parameter fitted in log space: three decades either side of the
// file's value, within [floor, ceiling].
FitParameter log_parameter(std::string name, std::string unit, double value, double floor = 0.0,
                           double ceiling = 1e300);

}  // namespace rollnoise
