#include "contact/modal_history_engine.hpp"

#include <cstring>
#include <stdexcept>

#include <Eigen/LU>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

ModalHistoryEngine::ModalHistoryEngine(const RollingPlate& plate, const Eigen::VectorXd& preload)
    : plate_(plate),
      fft_(std::make_unique<RealFftBatch>(plate.grid().circumferential, plate.lateral_modes())) {
  const TyreGrid& grid = plate.grid();
  if (preload.size() != grid.points()) throw std::invalid_argument("modal engine: preload has the wrong size");
  const int modes = (plate.orders() + 1) * plate.lateral_modes();
  step_.resize(modes);
  input_.resize(modes);
  output_.resize(modes);
  states_.assign(modes, Eigen::Vector2cd::Zero());
  modal_force_.assign(modes, 0.0);
  window_modes_.resize(grid.window, plate.lateral_modes());
  window_field_.resize(grid.window, grid.lateral);
  std::memset(fft_->field(), 0, sizeof(double) * static_cast<std::size_t>(fft_->length()) * plate.lateral_modes());
  for (int n = 1; n <= plate.lateral_modes(); ++n) {
    for (int m = 0; m <= plate.orders(); ++m) {
      const Eigen::Index r = plate.mode_index(m, n);
      const TravellingRecursion& rec = plate.recursion(r);
      step_[r] = rec.transition;
      input_[r] = rec.input;
      output_[r] = step_[r].row(0);
    }
  }
  // Steady rolling under the preload for all t < 0: X = Φ̃·X + Γ̃·f, so X = (I − Φ̃)⁻¹·Γ̃·f.
  project(preload);
  for (int r = 0; r < modes; ++r) {
    states_[r] = (Eigen::Matrix2cd::Identity() - step_[r]).partialPivLu().solve(input_[r]) * modal_force_[r];
  }
}

ModalHistoryEngine::~ModalHistoryEngine() = default;

void ModalHistoryEngine::project(const Eigen::Ref<const Eigen::VectorXd>& force) {
  const TyreGrid& grid = plate_.grid();
  const Eigen::Map<const Eigen::MatrixXd> f(force.data(), grid.window, grid.lateral);
  window_modes_.noalias() = f * plate_.lateral_shapes();  // Nw × N
  for (int n = 0; n < plate_.lateral_modes(); ++n)
    for (int i = 0; i < grid.window; ++i) fft_->at(n, grid.grid_index(i)) = window_modes_(i, n);
  fft_->forward();
  for (int n = 1; n <= plate_.lateral_modes(); ++n)
    for (int m = 0; m <= plate_.orders(); ++m) modal_force_[plate_.mode_index(m, n)] = fft_->bin(n - 1, m);
}

void ModalHistoryEngine::history(Eigen::Ref<Eigen::VectorXd> u0) const {
  const TyreGrid& grid = plate_.grid();
  RealFftBatch& fft = *fft_;
  const int bins = grid.circumferential / 2 + 1;
  for (int n = 1; n <= plate_.lateral_modes(); ++n) {
    for (int m = 0; m < bins; ++m) {
      std::complex<double> y = 0.0;
      if (m <= plate_.orders()) {
        const Eigen::Index r = plate_.mode_index(m, n);
        y = output_[r] * states_[r];
      }
      // The c2r transform weighs bins 1 … Nθ/2−1 twice (their conjugates) and the Nyquist bin
      // once; the modes ±Nθ/2 are two physical modes that alias to it.
      if (m == grid.circumferential / 2) y *= 2.0;
      fft.bin(n - 1, m) = y;
    }
  }
  fft.backward();
  for (int n = 0; n < plate_.lateral_modes(); ++n)
    for (int i = 0; i < grid.window; ++i) window_modes_(i, n) = fft.at(n, grid.grid_index(i));
  window_field_.noalias() = window_modes_ * plate_.lateral_shapes().transpose();
  window_field_ /= plate_.modal_mass();
  u0 = Eigen::Map<const Eigen::VectorXd>(window_field_.data(), window_field_.size());
  // The backward transform overwrote the field buffer: clear it for the next projection.
  std::memset(fft.field(), 0, sizeof(double) * static_cast<std::size_t>(fft.length()) * plate_.lateral_modes());
}

void ModalHistoryEngine::advance(const Eigen::Ref<const Eigen::VectorXd>& force) {
  project(force);
  for (std::size_t r = 0; r < states_.size(); ++r) {
    states_[r] = step_[r] * states_[r] + input_[r] * modal_force_[r];
  }
}

}  // namespace rollnoise
