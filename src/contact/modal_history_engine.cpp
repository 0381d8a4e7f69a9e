#include "contact/modal_history_engine.hpp"

#include <fftw3.h>

#include <cstring>
#include <stdexcept>

#include <Eigen/LU>

#include "core/fftw_planner_lock.hpp"

namespace rollnoise {

// N transforms of length Nθ, real field ↔ Nθ/2 + 1 circumferential orders.
struct ModalHistoryEngine::Fft {
  int length;
  int count;
  double* field = nullptr;              // count × length
  fftw_complex* spectrum = nullptr;     // count × (length/2 + 1)
  fftw_plan forward = nullptr;          // field → spectrum
  fftw_plan backward = nullptr;         // spectrum → field (unnormalised)

  Fft(int n, int howmany) : length(n), count(howmany) {
    const int bins = n / 2 + 1;
    field = fftw_alloc_real(static_cast<std::size_t>(n) * howmany);
    spectrum = fftw_alloc_complex(static_cast<std::size_t>(bins) * howmany);
    if (!field || !spectrum) throw std::bad_alloc();
    const std::lock_guard lock(fftw_planner_mutex());
    forward = fftw_plan_many_dft_r2c(1, &n, howmany, field, nullptr, 1, n, spectrum, nullptr, 1, bins,
                                     FFTW_ESTIMATE);
    backward = fftw_plan_many_dft_c2r(1, &n, howmany, spectrum, nullptr, 1, bins, field, nullptr, 1, n,
                                      FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
    if (!forward || !backward) throw std::runtime_error("FFTW could not plan the modal transforms");
  }
  ~Fft() {
    const std::lock_guard lock(fftw_planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(field);
    fftw_free(spectrum);
  }
  Fft(const Fft&) = delete;
  Fft& operator=(const Fft&) = delete;
  std::complex<double>& bin(int n, int m) {
    return reinterpret_cast<std::complex<double>&>(spectrum[static_cast<std::size_t>(n) * (length / 2 + 1) + m]);
  }
  double& at(int n, int g) { return field[static_cast<std::size_t>(n) * length + g]; }
};

ModalHistoryEngine::ModalHistoryEngine(const RollingPlate& plate, const Eigen::VectorXd& preload)
    : plate_(plate),
      fft_(std::make_unique<Fft>(plate.grid().circumferential, plate.lateral_modes())) {
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
  std::memset(fft_->field, 0, sizeof(double) * static_cast<std::size_t>(fft_->length) * fft_->count);
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
  fftw_execute(fft_->forward);
  for (int n = 1; n <= plate_.lateral_modes(); ++n)
    for (int m = 0; m <= plate_.orders(); ++m) modal_force_[plate_.mode_index(m, n)] = fft_->bin(n - 1, m);
}

void ModalHistoryEngine::history(Eigen::Ref<Eigen::VectorXd> u0) const {
  const TyreGrid& grid = plate_.grid();
  Fft& fft = *fft_;
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
  fftw_execute(fft.backward);
  for (int n = 0; n < plate_.lateral_modes(); ++n)
    for (int i = 0; i < grid.window; ++i) window_modes_(i, n) = fft.at(n, grid.grid_index(i));
  window_field_.noalias() = window_modes_ * plate_.lateral_shapes().transpose();
  window_field_ /= plate_.modal_mass();
  u0 = Eigen::Map<const Eigen::VectorXd>(window_field_.data(), window_field_.size());
  // The backward transform overwrote the field buffer: clear it for the next projection.
  std::memset(fft.field, 0, sizeof(double) * static_cast<std::size_t>(fft.length) * fft.count);
}

void ModalHistoryEngine::advance(const Eigen::Ref<const Eigen::VectorXd>& force) {
  project(force);
  for (std::size_t r = 0; r < states_.size(); ++r) {
    states_[r] = step_[r] * states_[r] + input_[r] * modal_force_[r];
  }
}

}  // namespace rollnoise
