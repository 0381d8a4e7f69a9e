#pragma once
// The fast history engine of the rolling tyre (history = "modal"): every pole of every mode is
// advanced by its exact one-state recursion (rolling_modes.hpp),
//   y_r ← a_r·y_r + b_r·f_ml,   a_r = e^{q_r Δt},   b_r = ρ_r (e^{q_r Δt} − 1)/q_r,
// and the circumferential orders are taken to and from the window by FFTs over the whole
// circumference. Per step: 2·N FFTs of length Nθ, one pass over the poles (pole_recursion.hpp:
// the advance, which also leaves Σ a·y per mode for the next step's u⁰) and two small products
// with the lateral shapes. All buffers and FFTW plans are made in the
// constructor; nothing is allocated in the step loop. FFTW_ESTIMATE plans, so results do not
// depend on run-time timing.
#include <complex>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "contact/history_engine.hpp"
#include "contact/pole_recursion.hpp"
#include "contact/rolling_modes.hpp"

namespace rollnoise {

class RealFftBatch;

class ModalHistoryEngine : public HistoryEngine {
 public:
  // `preload`: the steady force on each window point for all t < 0 (steady rolling).
  ModalHistoryEngine(const RollingModes& modes, const Eigen::VectorXd& preload);
  ~ModalHistoryEngine() override;
  ModalHistoryEngine(const ModalHistoryEngine&) = delete;
  ModalHistoryEngine& operator=(const ModalHistoryEngine&) = delete;

  std::string name() const override { return "modal"; }
  void history(Eigen::Ref<Eigen::VectorXd> u0) const override;
  void advance(const Eigen::Ref<const Eigen::VectorXd>& force) override;

  // After the last advance, mode r (RollingModes::mode_index) in the fixed frame: its amplitude
  // X = Σ y + d·f, and ∂X/∂t at fixed positions, Σ q·y + (Σρ)·f (ẏ = q·y + ρ·f: the
  // deformation swept past the fixed point and the material's own motion together).
  std::complex<double> amplitude(std::size_t r) const;
  std::complex<double> rate(std::size_t r) const;

 private:
  // f_ml = Σ_q φ_l(y_q) e^{−i k_m x_q} F_q into modal_force_.
  void project(const Eigen::Ref<const Eigen::VectorXd>& force);

  const RollingModes& modes_;
  std::unique_ptr<RealFftBatch> fft_;
  // Poles of mode r at recursion_.first_pole(r) … first_pole(r + 1) − 1: a = e^{qΔt},
  // b = ρ(e^{qΔt} − 1)/q and the states y.
  PoleRecursion recursion_;
  std::vector<std::complex<double>> rate_;  // q
  // Σ a·y per mode for the u⁰ of the coming step: what the earlier forces leave at its end.
  // Made by advance() in its pass once history() has been asked for (the response stage's
  // engine never asks), else by history() from the states.
  mutable std::vector<std::complex<double>> coming_;
  mutable bool coming_valid_ = false;
  mutable bool predict_in_advance_ = false;
  std::vector<double> direct_;                      // d per mode
  std::vector<std::complex<double>> residue_sum_;  // Σρ per mode
  std::vector<std::complex<double>> modal_force_;
  mutable Eigen::MatrixXd window_modes_;  // Nw × N
  mutable Eigen::MatrixXd window_field_;  // Nw × Ny
};

}  // namespace rollnoise
