#pragma once
// The paper's §4 point models: one SDOF with a contact spring (eq. 6, corrected), and points
// whose Green's functions are that SDOF's scaled by a coupling matrix (eq. 7:
// g11 = g22 = g, g12 = g21 = c·g). g(t) = δ(t)/s + h(t) with h the SDOF impulse response.
#include <string>
#include <vector>

#include "greens/greens_model.hpp"
#include "greens/sdof_oscillator.hpp"

namespace rollnoise {

struct SdofParameters {
  double mass;               // m, kg
  double damping;            // r, N·s/m
  double stiffness;          // k, N/m
  double contact_stiffness;  // s, N/m
};

class SdofModel : public GreensModel {
 public:
  // A single contact point.
  explicit SdofModel(const SdofParameters& parameters);
  // Two points, the second trailing the first by `spacing` (m), with g12 = g21 = c·g11.
  SdofModel(const SdofParameters& parameters, double coupling, double spacing);

  std::string name() const override;
  Eigen::Index point_count() const override { return coupling_.rows(); }
  Eigen::MatrixXd local_compliance() const override;
  Eigen::MatrixXd smooth_response(double t) const override;
  Eigen::MatrixXd smooth_integral(double t0, double t1) const override;
  Eigen::MatrixXcd receptance(double omega) const override;
  double slowest_decay_rate() const override;
  double fastest_rate() const override;
  std::vector<double> contact_point_offsets() const override { return offsets_; }

  const SdofParameters& parameters() const noexcept { return parameters_; }
  const SdofOscillator& oscillator() const noexcept { return oscillator_; }
  // The coupling matrix M: g = M·(δ/s + h).
  const Eigen::MatrixXd& coupling_matrix() const noexcept { return coupling_; }

 private:
  SdofParameters parameters_;
  SdofOscillator oscillator_;
  Eigen::MatrixXd coupling_;
  std::vector<double> offsets_;
};

}  // namespace rollnoise
