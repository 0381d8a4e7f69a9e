#pragma once
// Transfer functions from surface velocities to receiver pressures over a band of frequencies,
// solved at a few anchor frequencies and interpolated between them (an equivalent-source solve
// costs seconds per frequency on a tyre mesh; a time signal needs hundreds of bins).
//
// The propagation delay to each receiver, τ = |x_r − x_0|/c from a reference point x_0 on the
// body, makes T(ω) turn through 2π every 1/τ Hz (45 Hz at 7.5 m). It is taken out before
// interpolating, T̃ = T·e^{iωτ}, and put back after: what is left varies on the scale of the
// body's own size, and is interpolated linearly in frequency.
#include <vector>

#include <Eigen/Core>

#include "radiation/equivalent_sources.hpp"

namespace rollnoise {

// τ_r = |x_r − reference|/c for each receiver (s).
Eigen::VectorXd propagation_delays(const Eigen::Matrix3Xd& receivers, const Eigen::Vector3d& reference,
                                   double sound_speed);

class TransferTable {
 public:
  // anchors_hz: increasing, > 0. `reference`: a point on or in the body (the wheel centre).
  TransferTable(const EquivalentSources& model, const Eigen::Matrix3Xd& receivers, std::vector<double> anchors_hz,
                const Eigen::Vector3d& reference, double sound_speed, double regularisation = 1e-10);

  // From transfers already solved at the anchors (R × M each, delay not removed), for callers
  // that solve the anchors themselves (in parallel, or with more from each solve).
  TransferTable(std::vector<double> anchors_hz, std::vector<Eigen::MatrixXcd> transfers, Eigen::VectorXd delays);

  // R × M at frequency f (Hz), within [first anchor, last anchor].
  Eigen::MatrixXcd at(double frequency_hz) const;
  // The same with the propagation delay left out, T·e^{iωτ}: the transfer to retarded time.
  Eigen::MatrixXcd reduced_at(double frequency_hz) const;
  // The same into `out` (resized to R × M if it is not), without allocating when it is: for a
  // caller that takes many bins in turn (TyreRadiationStream's blocks).
  void reduced_at(double frequency_hz, Eigen::MatrixXcd& out) const;
  const Eigen::VectorXd& delays() const noexcept { return delay_; }

  const std::vector<double>& anchors() const noexcept { return anchors_; }

 private:
  std::vector<double> anchors_;
  Eigen::VectorXd delay_;                  // τ per receiver, s
  std::vector<Eigen::MatrixXcd> reduced_;  // T̃ at each anchor
};

}  // namespace rollnoise
