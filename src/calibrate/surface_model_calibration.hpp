#pragma once
// Calibration of a tyre model known by its surface receptance (surface_receptance_model.hpp:
// the two-layer tyre) through that interface alone: the model is rebuilt from its model file's
// table with the trial values, and derivatives are central differences. The FRF positions are
// points of the tread surface; since an elastic surface's point-to-point receptance diverges like
// 1/r (Boussinesq), force and response are taken over a 10 mm × 10 mm square, the footprint of an
// impact hammer's tip and of an accelerometer's base.
#include <toml++/toml.h>

#include "calibrate/calibration_model.hpp"

namespace rollnoise {

class SurfaceModelCalibration : public CalibrationModel {
 public:
  // The side of the square over which force and response are taken, m.
  static constexpr double kTransducerSize = 0.010;

  // `model`: a model file's keys; `source` names it in messages.
  SurfaceModelCalibration(toml::table model, std::string source);

  std::string name() const override { return name_; }
  const std::vector<FitParameter>& parameters() const override { return parameters_; }
  // The belt's in-plane moduli, the tensions, the foundation, the tread modulus and the loss
  // factors (issue 11): what no catalogue gives and a mobility measurement sees.
  std::vector<std::string> default_free_parameters() const override;
  bool needs_positions() const override { return true; }
  std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const override;
  // The modal sum resolves waves down to L/M: the tread's shear wave reaches that length at
  // c_s·M/L, above which the sum has lost the local response.
  double highest_frequency_hz() const override { return highest_hz_; }

 private:
  toml::table model_;
  std::string source_;
  std::string name_;
  double circumference_ = 0.0;
  double width_ = 0.0;
  double highest_hz_ = 0.0;
  std::vector<FitParameter> parameters_;
};

}  // namespace rollnoise
