#pragma once
// The fast history engine for the rolling plate (history = "modal"): every mode is advanced by
// the exact recursion of its sampled kernel, X ← Φ̃·X + Γ̃·f (rolling_plate.hpp), and the
// circumferential orders are taken to and from the window by FFTs over the whole
// circumference. Per step: 2·N FFTs of length Nθ, one 2×2 update per mode and two small
// products with the lateral shapes. All buffers and FFTW plans are made in the constructor;
// nothing is allocated in the step loop. FFTW_ESTIMATE plans, so results do not depend on
// run-time timing.
#include <complex>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "contact/history_engine.hpp"
#include "contact/rolling_plate.hpp"

namespace rollnoise {

class RealFftBatch;

class ModalHistoryEngine : public HistoryEngine {
 public:
  // `preload`: the steady force on each window point for all t < 0 (steady rolling).
  ModalHistoryEngine(const RollingPlate& plate, const Eigen::VectorXd& preload);
  ~ModalHistoryEngine() override;
  ModalHistoryEngine(const ModalHistoryEngine&) = delete;
  ModalHistoryEngine& operator=(const ModalHistoryEngine&) = delete;

  std::string name() const override { return "modal"; }
  void history(Eigen::Ref<Eigen::VectorXd> u0) const override;
  void advance(const Eigen::Ref<const Eigen::VectorXd>& force) override;

  // Modal displacement and velocity, x_mn and ẋ_mn after the last advance (mode index as in
  // RollingPlate::mode_index), in the rotating window frame.
  const std::vector<Eigen::Vector2cd>& states() const noexcept { return states_; }

 private:
  // f_mn = Σ_q sin(k_n y_q) e^{−i k_m x_q} F_q into modal_force_.
  void project(const Eigen::Ref<const Eigen::VectorXd>& force);

  const RollingPlate& plate_;
  std::unique_ptr<RealFftBatch> fft_;
  std::vector<Eigen::Matrix2cd> step_;      // Φ̃ per mode
  std::vector<Eigen::Vector2cd> input_;     // Γ̃ per mode
  std::vector<Eigen::RowVector2cd> output_; // c·Φ̃ per mode: history from the previous state
  std::vector<Eigen::Vector2cd> states_;
  std::vector<std::complex<double>> modal_force_;
  mutable Eigen::MatrixXd window_modes_;    // Nw × N
  mutable Eigen::MatrixXd window_field_;    // Nw × Ny
};

}  // namespace rollnoise
