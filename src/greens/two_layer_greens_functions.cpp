#include "greens/two_layer_greens_functions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/real_fft_batch.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;

double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

// Modes per batch of transforms: one plan serves every batch.
constexpr int batch_size = 64;

}  // namespace

TwoLayerGreensFunctions::TwoLayerGreensFunctions(const TwoLayerTyre& tyre, double time_step, int samples)
    : tyre_(&tyre), dt_(time_step), samples_(samples) {
  if (!std::isfinite(time_step) || !(time_step > 0.0)) throw std::invalid_argument("two_layer: time step must be > 0");
  if (samples < 4 || samples % 2 != 0) throw std::invalid_argument("two_layer: the number of samples must be even and >= 4");
  const double period = dt_ * samples_;
  sigma_ = std::log(1e4) / period;
  const int columns = tyre.parameters().circumferential_modes + 1;
  const int first = tyre.first_lateral_order();
  const int count = columns * tyre.parameters().lateral_modes;
  modes_.assign(static_cast<std::size_t>(count), std::vector<double>(static_cast<std::size_t>(samples_)));

  const int bins = samples_ / 2 + 1;
  // Frequencies ω_j − iσ and the step-mean filter B at each.
  std::vector<cd> omega(static_cast<std::size_t>(bins)), filter(static_cast<std::size_t>(bins));
  for (int j = 0; j < bins; ++j) {
    const cd w(2.0 * std::numbers::pi * j / period, -sigma_);
    const cd x = cd(0.0, 1.0) * w * dt_;  // iωΔt, never 0 since σ > 0
    omega[static_cast<std::size_t>(j)] = w;
    filter[static_cast<std::size_t>(j)] = (1.0 - std::exp(-x)) / x / period;
  }
  const int batch = std::min(batch_size, count);
  RealFftBatch fft(samples_, batch);
  for (int start = 0; start < count; start += batch) {
    const int used = std::min(batch, count - start);
    for (int b = 0; b < batch; ++b) {
      const int index = start + b;
      for (int j = 0; j < bins; ++j) {
        cd value = 0.0;
        if (b < used && j < bins - 1) {
          const int m = index % columns, n = first + index / columns;
          value = tyre.wavenumber_compliance(tyre.wavenumber_x(m), tyre.wavenumber_y(n),
                                             omega[static_cast<std::size_t>(j)])(2, 2) *
                  filter[static_cast<std::size_t>(j)];
        }
        fft.bin(b, j) = value;
      }
    }
    fft.backward();
    for (int b = 0; b < used; ++b) {
      std::vector<double>& out = modes_[static_cast<std::size_t>(start + b)];
      for (int k = 0; k < samples_; ++k) {
        // FFT order: k < K/2 is t = kΔt, the rest t = (k − K)Δt; store centred.
        const int signed_k = k < samples_ / 2 ? k : k - samples_;
        out[static_cast<std::size_t>(signed_k + samples_ / 2)] = fft.at(b, k) * std::exp(sigma_ * signed_k * dt_);
      }
    }
  }
}

const std::vector<double>& TwoLayerGreensFunctions::mode(int m, int n) const {
  const int columns = tyre_->parameters().circumferential_modes + 1;
  const int row = n - tyre_->first_lateral_order();
  if (m < 0 || m >= columns || row < 0 || row >= tyre_->parameters().lateral_modes) {
    throw std::out_of_range("two_layer: mode (" + std::to_string(m) + ", " + std::to_string(n) + ") is not tabulated");
  }
  return modes_[static_cast<std::size_t>(row * columns + m)];
}

std::vector<double> TwoLayerGreensFunctions::between(const SurfaceLocation& receiver,
                                                     const SurfaceLocation& source) const {
  const TwoLayerTyre& t = *tyre_;
  const double dx = std::remainder(receiver.x - source.x, t.circumference());
  std::vector<double> g(static_cast<std::size_t>(samples_), 0.0);
  for (int n = t.first_lateral_order(); n <= t.last_lateral_order(); ++n) {
    const double ky = t.wavenumber_y(n);
    const double lateral = t.lateral_shape(SurfaceDirection::z, n, receiver.y) * sinc(0.5 * ky * receiver.width) *
                           t.lateral_shape(SurfaceDirection::z, n, source.y) * sinc(0.5 * ky * source.width) /
                           t.modal_norm(n);
    for (int m = 0; m <= t.parameters().circumferential_modes; ++m) {
      const double k = t.wavenumber_x(m);
      const double weight = lateral * (m == 0 ? 1.0 : 2.0 * std::cos(k * dx)) * sinc(0.5 * k * receiver.length) *
                            sinc(0.5 * k * source.length);
      const std::vector<double>& h = mode(m, n);
      for (std::size_t i = 0; i < g.size(); ++i) g[i] += weight * h[i];
    }
  }
  return g;
}

}  // namespace rollnoise
