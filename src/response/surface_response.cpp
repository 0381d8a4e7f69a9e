#include "response/surface_response.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "contact/modal_history_engine.hpp"
#include "core/real_fft_batch.hpp"

namespace rollnoise {
SurfaceResponse::SurfaceResponse(const RollingModes& modes, const Eigen::VectorXd& preload, int lateral_points)
    : modes_(modes),
      engine_(std::make_unique<ModalHistoryEngine>(modes, preload)),
      fft_(std::make_unique<RealFftBatch>(modes.grid().circumferential, modes.lateral_modes())) {
  if (lateral_points < 1) throw std::invalid_argument("surface response: lateral_points must be >= 1");
  shapes_.resize(lateral_points, modes.lateral_modes());
  for (int j = 0; j < lateral_points; ++j) {
    const double y = (j + 0.5) * modes.tyre().width() / lateral_points;
    for (int l = 0; l < modes.lateral_modes(); ++l) shapes_(j, l) = modes.tyre().lateral_shape(l, y);
  }
  const int big_n = modes.grid().circumferential;
  twiddle_.resize(static_cast<std::size_t>(big_n));
  for (int k = 0; k < big_n; ++k) twiddle_[static_cast<std::size_t>(k)] = std::polar(1.0, 2.0 * std::numbers::pi * k / big_n);
}

SurfaceResponse::~SurfaceResponse() = default;

double SurfaceResponse::lateral_position(int j) const {
  return (j + 0.5) * modes_.tyre().width() / static_cast<double>(shapes_.rows());
}

void SurfaceResponse::add_out_of_roundness(int order, int lateral, double amplitude, double phase) {
  if (order < 0 || order > modes_.orders() || lateral < 0 || lateral >= modes_.lateral_modes()) {
    throw std::invalid_argument("surface response: out-of-roundness order or lateral shape outside the tyre's modes");
  }
  const auto count = static_cast<std::size_t>((modes_.orders() + 1) * modes_.lateral_modes());
  if (out_of_round_.empty()) {
    out_of_round_.assign(count, 0.0);
    out_of_round_step_.resize(count);
    for (int l = 0; l < modes_.lateral_modes(); ++l)
      for (int m = 0; m <= modes_.orders(); ++m)
        out_of_round_step_[static_cast<std::size_t>(modes_.mode_index(m, l))] =
            std::polar(1.0, modes_.passing_rate(m) * modes_.time_step());
  }
  // u = w_m·Re(e^{i k_m x}·X)·φ_l(y) (rolling_modes.hpp), so X = a·e^{iφ}/w_m.
  out_of_round_[static_cast<std::size_t>(modes_.mode_index(order, lateral))] +=
      std::polar(amplitude / modes_.weight(order), phase);
}

void SurfaceResponse::step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd* displacement,
                           Eigen::MatrixXd& velocity) {
  engine_->advance(force);
  for (std::size_t r = 0; r < out_of_round_.size(); ++r) out_of_round_[r] *= out_of_round_step_[r];
  const int big_n = modes_.grid().circumferential;
  const int bins = big_n / 2 + 1;
  RealFftBatch& fft = *fft_;
  const int orders = std::min(modes_.orders(), big_n / 2);
  for (int component = displacement ? 0 : 1; component < 2; ++component) {
    for (int l = 0; l < modes_.lateral_modes(); ++l) {
      // Written as two reals: a complex sum stored from the engine's return registers and
      // reloaded whole stalled on store forwarding (perf: 40 % of this function's own time).
      auto* bin = reinterpret_cast<double*>(&fft.bin(l, 0));
      for (int m = 0; m <= orders; ++m) {
        const auto r = static_cast<std::size_t>(modes_.mode_index(m, l));
        // The out-of-roundness is a shape fixed in the material: it passes a fixed point at
        // ω_m and has no rate of its own. Without one, + 0.0 is what adding i·ω_m·0 did (it
        // only turns −0 into +0).
        std::complex<double> value;
        if (component == 0) value = displacement_bin(r);
        else if (out_of_round_.empty()) value = engine_->rate(r);
        else value = engine_->rate(r) + std::complex<double>(0.0, modes_.passing_rate(m)) * out_of_round_[r];
        double re = value.real(), im = value.imag();
        if (component == 1 && out_of_round_.empty()) re += 0.0, im += 0.0;
        // c2r weighs the Nyquist bin once; the modes ±Nθ/2 both alias to it.
        if (m == big_n / 2) re *= 2.0, im *= 2.0;
        bin[2 * m] = re;
        bin[2 * m + 1] = im;
      }
      // The bins above the orders: the backward transform overwrote them (FFTW_DESTROY_INPUT).
      std::fill(bin + 2 * (orders + 1), bin + 2 * bins, 0.0);
    }
    fft.backward();
    // The transforms' fields are the rows of an N × Nθ row-major matrix: the product reads them
    // in place (the same product, bit for bit, as from a column-major copy: test_surface_response).
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> around(
        fft.field(), modes_.lateral_modes(), big_n);
    Eigen::MatrixXd& out = component == 0 ? *displacement : velocity;
    out.noalias() = shapes_ * around;
  }
}

std::complex<double> SurfaceResponse::out_of_round(std::size_t r) const {
  return out_of_round_.empty() ? 0.0 : out_of_round_[r];
}

std::complex<double> SurfaceResponse::displacement_bin(std::size_t r) const { return engine_->amplitude(r) + out_of_round(r); }

double SurfaceResponse::displacement_at(int j, int g) const {
  const int big_n = modes_.grid().circumferential;
  if (j < 0 || j >= shapes_.rows() || g < 0 || g >= big_n) throw std::out_of_range("surface response: no such point");
  // FFTW's c2r at g: X_0 + 2·Σ Re(X_m·e^{2πimg/N}) (0 < m < N/2) + X_{N/2}·(−1)^g, real parts,
  // with step()'s bins (the Nyquist bin doubled there, as here).
  double u = 0.0;
  const int orders = std::min(modes_.orders(), big_n / 2);
  for (int l = 0; l < modes_.lateral_modes(); ++l) {
    double around = 0.0;
    // The twiddle's index m·g mod Nθ, stepped by g (a division per term had been most of the
    // call's cost: callgrind).
    std::size_t k = 0;
    for (int m = 0; m <= orders; ++m, k += static_cast<std::size_t>(g)) {
      if (k >= static_cast<std::size_t>(big_n)) k -= static_cast<std::size_t>(big_n);
      const auto r = static_cast<std::size_t>(modes_.mode_index(m, l));
      const std::complex<double> value = displacement_bin(r);
      if (m == 0) around += value.real();
      else if (2 * m == big_n) around += (g % 2 == 0 ? 2.0 : -2.0) * value.real();
      else around += 2.0 * (value * twiddle_[k]).real();
    }
    u += shapes_(j, l) * around;
  }
  return u;
}

}  // namespace rollnoise
