#pragma once
// The tyre's response (the stage between contact and radiation): from the contact forces of
// a rolling run, the radial displacement and velocity of the whole belt surface, all Nθ × Ny
// points around and across, at every step.
//
// Positions are fixed in space (angle around the axle), so the field is what a microphone
// beside the tyre sees. The velocity handed on is the surface's own normal velocity at those
// fixed positions, ∂u/∂t|_x (Eulerian), not the radial velocity of the material passing them:
// the kinematic condition of the air on a moving boundary involves only how fast the boundary
// itself moves along its normal. Material sliding along a steady wavy surface moves
// tangentially and pushes no air (a tyre rolling steadily on a smooth road is silent), while a
// bump fixed on the tread radiates at the rotation harmonics although the material carrying
// it has no radial velocity at all. In the modal form of rolling_plate.hpp each fixed-frame
// mode carries the phase e^{iω_m t} of the material passing at ω_m = k_m·v:
//   X_mn = e^{iω_m t}·a_mn,   ∂X_mn/∂t = e^{iω_m t}·ȧ_mn + iω_m·X_mn,
// the first term being the material's own rate (the engine's second state) and the second the
// deformation swept past. Only the belt (the plate) is included: the local tread deformation is
// instantaneous and confined to the patch.
#include <complex>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "contact/rolling_plate.hpp"

namespace rollnoise {

class ModalHistoryEngine;
class RealFftBatch;

// ∂X/∂t at a fixed position of a mode that travels past at `passing_rate` ω (rad/s), from its
// fixed-frame amplitude X and the material's own rate e^{iωt}·ȧ.
inline std::complex<double> fixed_position_rate(std::complex<double> amplitude, std::complex<double> material_rate,
                                                double passing_rate) {
  return material_rate + std::complex<double>(0.0, passing_rate) * amplitude;
}

class SurfaceResponse {
 public:
  // Starts from steady rolling under the window forces `preload` (as the contact run does).
  // Lateral positions: the plate's, y_j = (j + ½)·b/Ny over the whole belt width.
  SurfaceResponse(const RollingPlate& plate, const Eigen::VectorXd& preload, int lateral_points);
  ~SurfaceResponse();
  SurfaceResponse(const SurfaceResponse&) = delete;
  SurfaceResponse& operator=(const SurfaceResponse&) = delete;

  // A radial out-of-roundness of the tread that rotates with the tyre (a geometric deviation,
  // not a deformation: it has no dynamics of its own), added to the surface:
  //   ε(θ, y) = amplitude·cos(k_m θ + phase)·sin(k_n y),  θ the material coordinate at t = 0.
  // Order 0 ≤ m ≤ M, lateral mode 1 ≤ n ≤ N. It radiates at the passing rate m·Ω. The contact
  // solver does not see it: use it on a tyre out of contact, or for deviations small against
  // the texture.
  void add_out_of_roundness(int order, int lateral_mode, double amplitude, double phase);

  // Applies the window forces of the next step and evaluates the surface: displacement (m) and
  // velocity ∂u/∂t at fixed positions (m/s), each Ny × Nθ (row j: lateral position y_j; column
  // g: position g·dx around from the bottom of the tyre, in the direction of travel).
  void step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& displacement, Eigen::MatrixXd& velocity);

  double lateral_position(int j) const;

 private:
  const RollingPlate& plate_;
  std::unique_ptr<ModalHistoryEngine> modes_;
  std::unique_ptr<RealFftBatch> fft_;
  Eigen::MatrixXd shapes_;  // sin(k_n y_j): Ny × N
  Eigen::MatrixXd around_;  // N × Nθ scratch
  // Out-of-roundness per mode, in the engine's fixed-frame modal scale (× modal mass / weight),
  // advanced by e^{iω_m Δt} each step; empty when there is none.
  std::vector<std::complex<double>> out_of_round_;
  std::vector<std::complex<double>> out_of_round_step_;
};

}  // namespace rollnoise
