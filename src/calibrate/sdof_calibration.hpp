#pragma once
// The point models of MODEL.md §3 for calibration: sdof (mass, damping, stiffness,
// contact_stiffness) and coupled_sdof (the same and coupling). Their receptance is
//
//   α_ij(ω) = M_ij·(1/s + 1/(k − mω² + iωr)),   M = [[1, c], [c, 1]],
//
// differentiated automatically with ceres::Jet (the receptance is written once, as a
// template, for doubles and Jets). An FRF's points are contact points: its x positions must be
// the contact point offsets along the road (0, and `spacing` for the second point); with no
// positions, an FRF is the point receptance of the first contact point.
#include "calibrate/calibration_model.hpp"
#include "greens/sdof_model.hpp"

namespace rollnoise {

class SdofCalibration : public CalibrationModel {
 public:
  // A single point (coupling = 0, spacing = 0) or two coupled points.
  SdofCalibration(const SdofParameters& parameters, bool coupled, double coupling, double spacing);

  std::string name() const override { return coupled_ ? "coupled_sdof" : "sdof"; }
  const std::vector<FitParameter>& parameters() const override { return parameters_; }
  std::vector<std::string> default_free_parameters() const override;
  bool needs_positions() const override { return false; }
  std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const override;
  double highest_frequency_hz() const override;

 private:
  bool coupled_;
  double spacing_;
  std::vector<FitParameter> parameters_;
};

}  // namespace rollnoise
