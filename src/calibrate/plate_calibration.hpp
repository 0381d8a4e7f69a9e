#pragma once
// Kropp's plate (MODEL.md §4, greens/kropp_plate.hpp) for calibration. The receptance between
// a force at (x0, y0) and the response at (x, y) is the modal sum
//
//   α = Σ_n Σ_m c_m s_n / (M u_mn),   u_mn = ω_mn² − ω² + iω·η·ω_mn,   ω_mn² = K_mn/m'',
//
// c_m = w_m cos(k_m (x − x0)) (w_0 = 1, w_m = 2), s_n = sin(k_n y) sin(k_n y0), M = m''·L·b/2,
// and K_mn linear in the stiffnesses: Bx k_m⁴ + 2Bxy k_m²k_n² + By k_n⁴ + Tx k_m² + Ty k_n² + s_f.
// Its derivatives are modal sums too (exact, analytic): for a stiffness p with ∂K/∂p = a_mn,
//   ∂α/∂p = −Σ c_m s_n a_mn (1 + iωη/(2ω_mn)) / (M m'' u_mn²),
//   ∂α/∂η = −Σ c_m s_n iω ω_mn / (M u_mn²),
//   ∂α/∂m'' = −α/m'' + Σ c_m s_n ω_mn² (1 + iωη/(2ω_mn)) / (M m'' u_mn²).
// The value equals KroppPlate::receptance (checked in tests/calibrate).
//
// Fittable: mass_per_area, tension_x, tension_y, bending_x, bending_y, bending_xy,
// foundation_stiffness, loss_factor. Geometry (radius, width) and mode counts stay as in the
// file. The tread's local compliance is not part of the fit: a transducer on the tread sees
// the belt through it, which matters only where the tread's own resonances begin (kHz).
#include <memory>

#include "calibrate/calibration_model.hpp"
#include "greens/kropp_plate.hpp"

namespace rollnoise {

class PlateCalibration : public CalibrationModel {
 public:
  explicit PlateCalibration(const PlateParameters& parameters);

  std::string name() const override { return "plate"; }
  const std::vector<FitParameter>& parameters() const override { return parameters_; }
  // tension_x, bending_x, foundation_stiffness, loss_factor.
  std::vector<std::string> default_free_parameters() const override;
  bool needs_positions() const override { return true; }
  // Positions (x, y) on the belt: y within [0, width].
  std::unique_ptr<ReceptanceFunction> receptance(const FrfPoints& points) const override;
  // Half the frequency of the lowest mode the truncation leaves out (modes well above a
  // frequency act as a static compliance that the truncated sum lacks).
  double highest_frequency_hz() const override;

  // The plate with `values` (one per parameters()) in place of the file's.
  PlateParameters with_values(std::span<const double> values) const;

  struct ModeCache;

 private:
  PlateParameters plate_;
  std::vector<FitParameter> parameters_;
  std::shared_ptr<ModeCache> cache_;  // modal frequencies of the last values, shared by the receptances
};

}  // namespace rollnoise
