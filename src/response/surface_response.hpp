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
// it has no radial velocity at all. In the modal form of rolling_modes.hpp each fixed-frame
// mode amplitude is a sum of pole states y with ẏ = q·y + ρ·f, q = p + iω_m, ω_m = k_m·v: the
// iω_m part is the deformation swept past, the rest the material's own rate
// (ModalHistoryEngine::rate). Only the structure's own modes are included: a separate tread's
// local deformation is instantaneous and confined to the patch.
#include <complex>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "contact/rolling_modes.hpp"

namespace rollnoise {

class ModalHistoryEngine;
class RealFftBatch;

class SurfaceResponse {
 public:
  // Starts from steady rolling under the window forces `preload` (as the contact run does).
  // Lateral positions: y_j = (j + ½)·b/Ny over the whole width of the tyre's lateral shapes.
  SurfaceResponse(const RollingModes& modes, const Eigen::VectorXd& preload, int lateral_points);
  ~SurfaceResponse();
  SurfaceResponse(const SurfaceResponse&) = delete;
  SurfaceResponse& operator=(const SurfaceResponse&) = delete;

  // A radial out-of-roundness of the tread that rotates with the tyre (a geometric deviation,
  // not a deformation: it has no dynamics of its own), added to the surface:
  //   ε(θ, y) = amplitude·cos(k_m θ + phase)·φ_l(y),  θ the material coordinate at t = 0.
  // Order 0 ≤ m ≤ M, lateral shape 0 ≤ l < N (φ_l of the tyre model). It radiates at the passing rate m·Ω. The contact
  // solver does not see it: use it on a tyre out of contact, or for deviations small against
  // the texture.
  void add_out_of_roundness(int order, int lateral, double amplitude, double phase);

  // Applies the window forces of the next step and evaluates the surface: displacement (m) and
  // velocity ∂u/∂t at fixed positions (m/s), each Ny × Nθ (row j: lateral position y_j; column
  // g: position g·dx around from the bottom of the tyre, in the direction of travel).
  void step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& displacement, Eigen::MatrixXd& velocity) {
    step(force, &displacement, velocity);
  }
  // The same, the displacement evaluated only when asked for (not null): the velocity alone is
  // half the transforms, and a run needs the whole displacement field only for contact.h5's
  // "all" fields (issue 12). The velocity is the same bit for bit either way.
  void step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd* displacement, Eigen::MatrixXd& velocity);

  // The displacement (m) at row j, position g around, after the last step: the sum step()'s
  // transform makes there, taken directly (L·M terms instead of the whole field), equal to
  // step()'s field to round-off. The revolution of Fig. 5b needs one point a step; the whole
  // field, a second transform and product, had doubled the response's work on those steps.
  double displacement_at(int j, int g) const;

  double lateral_position(int j) const;

 private:
  // Mode r's out-of-roundness (0 without one), and its displacement in the fixed frame: the bin
  // both step()'s transform and displacement_at() sum.
  std::complex<double> out_of_round(std::size_t r) const;
  std::complex<double> displacement_bin(std::size_t r) const;
  const RollingModes& modes_;
  std::unique_ptr<ModalHistoryEngine> engine_;
  std::unique_ptr<RealFftBatch> fft_;
  Eigen::MatrixXd shapes_;  // φ_l(y_j): Ny × N
  // Out-of-roundness per mode, in the engine's fixed-frame modal amplitude (÷ weight),
  // advanced by e^{iω_m Δt} each step; empty when there is none.
  std::vector<std::complex<double>> out_of_round_;
  std::vector<std::complex<double>> out_of_round_step_;
  std::vector<std::complex<double>> twiddle_;  // e^{2πik/Nθ}, k < Nθ: the backward transform's factors
};

}  // namespace rollnoise
