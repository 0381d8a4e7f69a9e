#include "response/surface_response.hpp"

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
  around_.resize(modes.lateral_modes(), modes.grid().circumferential);
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
  for (int component = displacement ? 0 : 1; component < 2; ++component) {
    for (int l = 0; l < modes_.lateral_modes(); ++l) {
      for (int m = 0; m < bins; ++m) {
        std::complex<double> value = 0.0;
        if (m <= modes_.orders()) {
          const auto r = static_cast<std::size_t>(modes_.mode_index(m, l));
          // The out-of-roundness is a shape fixed in the material: it passes a fixed point at
          // ω_m and has no rate of its own.
          value = component == 0 ? displacement_bin(r)
                                 : engine_->rate(r) + std::complex<double>(0.0, modes_.passing_rate(m)) * out_of_round(r);
        }
        // c2r weighs the Nyquist bin once; the modes ±Nθ/2 both alias to it.
        if (m == big_n / 2) value *= 2.0;
        fft.bin(l, m) = value;
      }
    }
    fft.backward();
    for (int l = 0; l < modes_.lateral_modes(); ++l)
      for (int g = 0; g < big_n; ++g) around_(l, g) = fft.at(l, g);
    Eigen::MatrixXd& out = component == 0 ? *displacement : velocity;
    out.noalias() = shapes_ * around_;
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
  for (int l = 0; l < modes_.lateral_modes(); ++l) {
    double around = 0.0;
    for (int m = 0; m <= std::min(modes_.orders(), big_n / 2); ++m) {
      const auto r = static_cast<std::size_t>(modes_.mode_index(m, l));
      const std::complex<double> value = displacement_bin(r);
      if (m == 0) around += value.real();
      else if (2 * m == big_n) around += (g % 2 == 0 ? 2.0 : -2.0) * value.real();
      else around += 2.0 * (value * twiddle_[static_cast<std::size_t>((static_cast<long>(m) * g) % big_n)]).real();
    }
    u += shapes_(j, l) * around;
  }
  return u;
}

}  // namespace rollnoise
