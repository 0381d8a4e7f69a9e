#include "contact/modal_history_engine.hpp"

#include <cstring>
#include <stdexcept>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

namespace {
constexpr std::complex<double> kI(0.0, 1.0);
}

ModalHistoryEngine::ModalHistoryEngine(const RollingModes& modes, const Eigen::VectorXd& preload)
    : modes_(modes), fft_(std::make_unique<RealFftBatch>(modes.grid().circumferential, modes.lateral_modes())) {
  const TyreGrid& grid = modes.grid();
  if (preload.size() != grid.points()) throw std::invalid_argument("modal engine: preload has the wrong size");
  const auto count = static_cast<std::size_t>((modes.orders() + 1) * modes.lateral_modes());
  first_pole_.assign(count + 1, 0);
  direct_.assign(count, 0.0);
  residue_sum_.assign(count, 0.0);
  modal_force_.assign(count, 0.0);
  const double dt = modes.time_step();
  // Mode-index order (l outer, m inner), so each mode's poles are contiguous.
  for (int l = 0; l < modes.lateral_modes(); ++l) {
    for (int m = 0; m <= modes.orders(); ++m) {
      const auto r = static_cast<std::size_t>(modes.mode_index(m, l));
      const PoleResidueResponse& mode = modes.mode(static_cast<Eigen::Index>(r));
      direct_[r] = mode.direct;
      first_pole_[r] = rate_.size();
      for (std::size_t s = 0; s < mode.size(); ++s) {
        const std::complex<double> q = mode.poles[s] + kI * modes.passing_rate(m);
        rate_.push_back(q);
        decay_.push_back(std::exp(q * dt));
        // ρ·∫_0^Δt e^{qτ} dτ: the pole's share of the kernel's lag 0.
        PoleResidueResponse single;
        single.poles = {mode.poles[s]};
        single.residues = {mode.residues[s]};
        input_.push_back(single.phase_integral(modes.passing_rate(m), 0.0, dt));
        residue_sum_[r] += mode.residues[s];
      }
      first_pole_[r + 1] = rate_.size();
    }
  }
  states_.assign(decay_.size(), 0.0);
  predicted_.assign(decay_.size(), 0.0);
  window_modes_.resize(grid.window, modes.lateral_modes());
  window_field_.resize(grid.window, grid.lateral);
  std::memset(fft_->field(), 0, sizeof(double) * static_cast<std::size_t>(fft_->length()) * modes.lateral_modes());
  // Steady rolling under the preload for all t < 0: y = a·y + b·f, so y = b·f/(1 − a) = −ρf/q.
  project(preload);
  for (std::size_t r = 0; r < count; ++r)
    for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s)
      states_[s] = input_[s] / (1.0 - decay_[s]) * modal_force_[r];
}

ModalHistoryEngine::~ModalHistoryEngine() = default;

void ModalHistoryEngine::project(const Eigen::Ref<const Eigen::VectorXd>& force) {
  const TyreGrid& grid = modes_.grid();
  const Eigen::Map<const Eigen::MatrixXd> f(force.data(), grid.window, grid.lateral);
  window_modes_.noalias() = f * modes_.lateral_shapes();  // Nw × N
  for (int l = 0; l < modes_.lateral_modes(); ++l)
    for (int i = 0; i < grid.window; ++i) fft_->at(l, grid.grid_index(i)) = window_modes_(i, l);
  fft_->forward();
  for (int l = 0; l < modes_.lateral_modes(); ++l)
    for (int m = 0; m <= modes_.orders(); ++m) modal_force_[static_cast<std::size_t>(modes_.mode_index(m, l))] = fft_->bin(l, m);
}

std::complex<double> ModalHistoryEngine::amplitude(std::size_t r) const {
  std::complex<double> x = direct_[r] * modal_force_[r];
  for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s) x += states_[s];
  return x;
}

std::complex<double> ModalHistoryEngine::rate(std::size_t r) const {
  const std::complex<double> v = residue_sum_[r] * modal_force_[r];
  double re = v.real(), im = v.imag();
  for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s) {
    const double qr = rate_[s].real(), qi = rate_[s].imag(), yr = states_[s].real(), yi = states_[s].imag();
    re += qr * yr - qi * yi;
    im += qr * yi + qi * yr;
  }
  return {re, im};
}

void ModalHistoryEngine::history(Eigen::Ref<Eigen::VectorXd> u0) const {
  const TyreGrid& grid = modes_.grid();
  RealFftBatch& fft = *fft_;
  const int bins = grid.circumferential / 2 + 1;
  for (int l = 0; l < modes_.lateral_modes(); ++l) {
    for (int m = 0; m < bins; ++m) {
      std::complex<double> y = 0.0;
      if (m <= modes_.orders()) {
        const auto r = static_cast<std::size_t>(modes_.mode_index(m, l));
        // What the earlier forces leave at the end of the coming step: Σ a·y, kept per pole for
        // advance(). Written in reals: std::complex's product checks for infinities first.
        double sum_re = 0.0, sum_im = 0.0;
        for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s) {
          const double ar = decay_[s].real(), ai = decay_[s].imag(), yr = states_[s].real(), yi = states_[s].imag();
          const double pr = ar * yr - ai * yi, pi = ar * yi + ai * yr;
          predicted_[s] = {pr, pi};
          sum_re += pr;
          sum_im += pi;
        }
        y = {sum_re, sum_im};
      }
      // The c2r transform weighs bins 1 … Nθ/2−1 twice (their conjugates) and the Nyquist bin
      // once; the modes ±Nθ/2 are two physical modes that alias to it.
      if (m == grid.circumferential / 2) y *= 2.0;
      fft.bin(l, m) = y;
    }
  }
  fft.backward();
  for (int l = 0; l < modes_.lateral_modes(); ++l)
    for (int i = 0; i < grid.window; ++i) window_modes_(i, l) = fft.at(l, grid.grid_index(i));
  window_field_.noalias() = window_modes_ * modes_.lateral_shapes().transpose();
  u0 = Eigen::Map<const Eigen::VectorXd>(window_field_.data(), window_field_.size());
  // The backward transform overwrote the field buffer: clear it for the next projection.
  std::memset(fft.field(), 0, sizeof(double) * static_cast<std::size_t>(fft.length()) * modes_.lateral_modes());
  predicted_valid_ = true;
}

void ModalHistoryEngine::advance(const Eigen::Ref<const Eigen::VectorXd>& force) {
  project(force);
  const std::size_t count = modal_force_.size();
  if (!predicted_valid_)
    for (std::size_t s = 0; s < states_.size(); ++s) predicted_[s] = decay_[s] * states_[s];
  for (std::size_t r = 0; r < count; ++r) {
    const double fr = modal_force_[r].real(), fi = modal_force_[r].imag();
    for (std::size_t s = first_pole_[r]; s < first_pole_[r + 1]; ++s) {
      const double br = input_[s].real(), bi = input_[s].imag();
      states_[s] = {predicted_[s].real() + br * fr - bi * fi, predicted_[s].imag() + br * fi + bi * fr};
    }
  }
  predicted_valid_ = false;
}

}  // namespace rollnoise
