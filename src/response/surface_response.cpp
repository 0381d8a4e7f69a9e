#include "response/surface_response.hpp"

#include <stdexcept>

#include "contact/modal_history_engine.hpp"
#include "core/real_fft_batch.hpp"

namespace rollnoise {
SurfaceResponse::SurfaceResponse(const RollingPlate& plate, const Eigen::VectorXd& preload, int lateral_points)
    : plate_(plate),
      modes_(std::make_unique<ModalHistoryEngine>(plate, preload)),
      fft_(std::make_unique<RealFftBatch>(plate.grid().circumferential, plate.lateral_modes())) {
  if (lateral_points < 1) throw std::invalid_argument("surface response: lateral_points must be >= 1");
  shapes_.resize(lateral_points, plate.lateral_modes());
  for (int j = 0; j < lateral_points; ++j) {
    const double y = (j + 0.5) * plate.plate().parameters().width / lateral_points;
    for (int n = 1; n <= plate.lateral_modes(); ++n) shapes_(j, n - 1) = std::sin(plate.plate().wavenumber_y(n) * y);
  }
  around_.resize(plate.lateral_modes(), plate.grid().circumferential);
}

SurfaceResponse::~SurfaceResponse() = default;

double SurfaceResponse::lateral_position(int j) const {
  return (j + 0.5) * plate_.plate().parameters().width / static_cast<double>(shapes_.rows());
}

void SurfaceResponse::add_out_of_roundness(int order, int lateral_mode, double amplitude, double phase) {
  if (order < 0 || order > plate_.orders() || lateral_mode < 1 || lateral_mode > plate_.lateral_modes()) {
    throw std::invalid_argument("surface response: out-of-roundness order or lateral mode outside the plate's modes");
  }
  const auto modes = static_cast<std::size_t>((plate_.orders() + 1) * plate_.lateral_modes());
  if (out_of_round_.empty()) {
    out_of_round_.assign(modes, 0.0);
    out_of_round_step_.resize(modes);
    for (int n = 1; n <= plate_.lateral_modes(); ++n)
      for (int m = 0; m <= plate_.orders(); ++m)
        out_of_round_step_[static_cast<std::size_t>(plate_.mode_index(m, n))] =
            std::polar(1.0, plate_.passing_rate(m) * plate_.time_step());
  }
  // u = (1/M)·w_m·Re(e^{i k_m x}·X)·sin(k_n y) (rolling_plate.hpp), so X = M·a·e^{iφ}/w_m.
  out_of_round_[static_cast<std::size_t>(plate_.mode_index(order, lateral_mode))] +=
      std::polar(amplitude * plate_.modal_mass() / plate_.weight(order), phase);
}

void SurfaceResponse::step(const Eigen::Ref<const Eigen::VectorXd>& force, Eigen::MatrixXd& displacement,
                           Eigen::MatrixXd& velocity) {
  modes_->advance(force);
  for (std::size_t r = 0; r < out_of_round_.size(); ++r) out_of_round_[r] *= out_of_round_step_[r];
  const auto& states = modes_->states();
  const int big_n = plate_.grid().circumferential;
  const int bins = big_n / 2 + 1;
  RealFftBatch& fft = *fft_;
  for (int component = 0; component < 2; ++component) {
    for (int n = 1; n <= plate_.lateral_modes(); ++n) {
      for (int m = 0; m < bins; ++m) {
        std::complex<double> value = 0.0;
        if (m <= plate_.orders()) {
          const auto r = static_cast<std::size_t>(plate_.mode_index(m, n));
          std::complex<double> amplitude = states[r](0);
          // The out-of-roundness is a shape fixed in the material: no rate of its own.
          std::complex<double> material_rate = states[r](1);
          if (!out_of_round_.empty()) amplitude += out_of_round_[r];
          value = component == 0 ? amplitude : fixed_position_rate(amplitude, material_rate, plate_.passing_rate(m));
        }
        // c2r weighs the Nyquist bin once; the modes ±Nθ/2 both alias to it.
        if (m == big_n / 2) value *= 2.0;
        fft.bin(n - 1, m) = value;
      }
    }
    fft.backward();
    for (int n = 0; n < plate_.lateral_modes(); ++n)
      for (int g = 0; g < big_n; ++g) around_(n, g) = fft.at(n, g);
    Eigen::MatrixXd& out = component == 0 ? displacement : velocity;
    out.noalias() = shapes_ * around_;
    out /= plate_.modal_mass();
  }
}

}  // namespace rollnoise
