#pragma once
// Calibration of any Green's-function model that make_greens_model builds, through the model
// interface alone (GreensModel::receptance(ω), contact_point_offsets()): the fittable
// parameters are the model file's top-level keys with positive real values (fitted in log
// space), the model is rebuilt from the file's table with the trial values, and derivatives
// are central differences. This is how a model added to the factory later is calibrated
// before it gets derivatives of its own; sdof and plate have faster, exact ones.
#include <toml++/toml.h>

#include "calibrate/calibration_model.hpp"

namespace rollnoise {

class GreensModelCalibration : public CalibrationModel {
 public:
  // `model`: a model file's keys (what a [tyre] table holds); `source` names it in messages.
  GreensModelCalibration(toml::table model, std::string source);

  std::string name() const override { return name_; }
  const std::vector<FitParameter>& parameters() const override { return parameters_; }
  std::vector<std::string> default_free_parameters() const override;
  bool needs_positions() const override { return false; }
  // Positions are contact points: x must be one of the model's contact point offsets.
  std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const override;
  double highest_frequency_hz() const override;

 private:
  toml::table model_;
  std::string source_;
  std::string name_;
  std::vector<double> offsets_;
  std::vector<FitParameter> parameters_;
};

}  // namespace rollnoise
