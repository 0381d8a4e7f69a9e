#include "contact/modal_history_engine.hpp"

#include <cstring>
#include <stdexcept>

#include "core/real_fft_batch.hpp"

namespace rollnoise {

namespace {
constexpr std::complex<double> kI(0.0, 1.0);

// Every pole of every mode in mode-index order (each mode's poles contiguous) with its rate
// shifted by the passing rate, q = p + iω_m: a = e^{qΔt} and b = ρ·∫_0^Δt e^{qτ} dτ, the
// pole's share of the kernel's lag 0.
PoleRecursion recursion_of(const RollingModes& modes) {
  const auto count = static_cast<std::size_t>((modes.orders() + 1) * modes.lateral_modes());
  std::vector<std::size_t> first_pole(count + 1, 0);
  std::vector<std::complex<double>> decay, input;
  const double dt = modes.time_step();
  for (int l = 0; l < modes.lateral_modes(); ++l) {
    for (int m = 0; m <= modes.orders(); ++m) {
      const auto r = static_cast<std::size_t>(modes.mode_index(m, l));
      const PoleResidueResponse& mode = modes.mode(static_cast<Eigen::Index>(r));
      first_pole[r] = decay.size();
      for (std::size_t s = 0; s < mode.size(); ++s) {
        const std::complex<double> q = mode.poles[s] + kI * modes.passing_rate(m);
        decay.push_back(std::exp(q * dt));
        PoleResidueResponse single;
        single.poles = {mode.poles[s]};
        single.residues = {mode.residues[s]};
        input.push_back(single.phase_integral(modes.passing_rate(m), 0.0, dt));
      }
      first_pole[r + 1] = decay.size();
    }
  }
  return PoleRecursion(std::move(first_pole), std::move(decay), std::move(input));
}
}  // namespace

ModalHistoryEngine::ModalHistoryEngine(const RollingModes& modes, const Eigen::VectorXd& preload)
    : modes_(modes),
      fft_(std::make_unique<RealFftBatch>(modes.grid().circumferential, modes.lateral_modes())),
      recursion_(recursion_of(modes)) {
  const TyreGrid& grid = modes.grid();
  if (preload.size() != grid.points()) throw std::invalid_argument("modal engine: preload has the wrong size");
  const std::size_t count = recursion_.modes();
  direct_.assign(count, 0.0);
  residue_sum_.assign(count, 0.0);
  modal_force_.assign(count, 0.0);
  coming_.assign(count, 0.0);
  rate_.reserve(recursion_.poles());
  for (int l = 0; l < modes.lateral_modes(); ++l) {
    for (int m = 0; m <= modes.orders(); ++m) {
      const auto r = static_cast<std::size_t>(modes.mode_index(m, l));
      const PoleResidueResponse& mode = modes.mode(static_cast<Eigen::Index>(r));
      direct_[r] = mode.direct;
      for (std::size_t s = 0; s < mode.size(); ++s) {
        rate_.push_back(mode.poles[s] + kI * modes.passing_rate(m));
        residue_sum_[r] += mode.residues[s];
      }
    }
  }
  window_modes_.resize(grid.window, modes.lateral_modes());
  window_field_.resize(grid.window, grid.lateral);
  std::memset(fft_->field(), 0, sizeof(double) * static_cast<std::size_t>(fft_->length()) * modes.lateral_modes());
  // Steady rolling under the preload for all t < 0: y = a·y + b·f, so y = b·f/(1 − a) = −ρf/q.
  project(preload);
  std::vector<std::complex<double>>& states = recursion_.states();
  for (std::size_t r = 0; r < count; ++r)
    for (std::size_t s = recursion_.first_pole(r); s < recursion_.first_pole(r + 1); ++s)
      states[s] = recursion_.input()[s] / (1.0 - recursion_.decay()[s]) * modal_force_[r];
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
  const std::vector<std::complex<double>>& states = recursion_.states();
  for (std::size_t s = recursion_.first_pole(r); s < recursion_.first_pole(r + 1); ++s) x += states[s];
  return x;
}

std::complex<double> ModalHistoryEngine::rate(std::size_t r) const {
  const std::complex<double> v = residue_sum_[r] * modal_force_[r];
  double re = v.real(), im = v.imag();
  const std::vector<std::complex<double>>& states = recursion_.states();
  for (std::size_t s = recursion_.first_pole(r); s < recursion_.first_pole(r + 1); ++s) {
    const double qr = rate_[s].real(), qi = rate_[s].imag(), yr = states[s].real(), yi = states[s].imag();
    re += qr * yr - qi * yi;
    im += qr * yi + qi * yr;
  }
  return {re, im};
}

void ModalHistoryEngine::history(Eigen::Ref<Eigen::VectorXd> u0) const {
  const TyreGrid& grid = modes_.grid();
  RealFftBatch& fft = *fft_;
  const int bins = grid.circumferential / 2 + 1;
  // What the earlier forces leave at the end of the coming step, Σ a·y per mode: from the last
  // advance's pass, or (the first time) from the states; from now on each advance makes it.
  if (!coming_valid_) recursion_.predict(coming_.data());
  coming_valid_ = predict_in_advance_ = true;
  for (int l = 0; l < modes_.lateral_modes(); ++l) {
    for (int m = 0; m < bins; ++m) {
      std::complex<double> y = 0.0;
      if (m <= modes_.orders()) y = coming_[static_cast<std::size_t>(modes_.mode_index(m, l))];
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
}

void ModalHistoryEngine::advance(const Eigen::Ref<const Eigen::VectorXd>& force) {
  project(force);
  recursion_.advance(modal_force_.data(), predict_in_advance_ ? coming_.data() : nullptr);
  coming_valid_ = predict_in_advance_;
}

}  // namespace rollnoise
