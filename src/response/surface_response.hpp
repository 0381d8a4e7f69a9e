#pragma once
// The tyre's response (the stage between contact and radiation): from the contact forces of
// a rolling run, the radial displacement and velocity of the whole belt surface, all Nθ × Ny
// points around and across, at every step.
//
// Positions are fixed in space (angle around the axle), so the field is what a microphone
// beside the tyre sees. The velocity is that of the material passing each position (its modal
// state's rate, MODEL.md §4), which is the normal velocity that radiates. Only the belt (the
// plate) is included: the local tread deformation is instantaneous and confined to the patch.
#include <memory>

#include <Eigen/Core>

#include "contact/rolling_plate.hpp"

namespace rollnoise {

class ModalHistoryEngine;
class RealFftBatch;

class SurfaceResponse {
 public:
  // Starts from steady rolling under the window forces `preload` (as the contact run does).
  // Lateral positions: the plate's, y_j = (j + ½)·b/Ny over the whole belt width.
  SurfaceResponse(const RollingPlate& plate, const Eigen::VectorXd& preload, int lateral_points);
  ~SurfaceResponse();
  SurfaceResponse(const SurfaceResponse&) = delete;
  SurfaceResponse& operator=(const SurfaceResponse&) = delete;

  // Applies the window forces of the next step and evaluates the surface: displacement (m) and
  // velocity (m/s), each Ny × Nθ (row j: lateral position y_j; column g: position g·dx around
  // from the bottom of the tyre, in the direction of travel).
  void step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& displacement, Eigen::MatrixXd& velocity);

  double lateral_position(int j) const;

 private:
  const RollingPlate& plate_;
  std::unique_ptr<ModalHistoryEngine> modes_;
  std::unique_ptr<RealFftBatch> fft_;
  Eigen::MatrixXd shapes_;  // sin(k_n y_j): Ny × N
  Eigen::MatrixXd around_;  // N × Nθ scratch
};

}  // namespace rollnoise
