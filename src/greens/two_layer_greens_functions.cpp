#include "greens/two_layer_greens_functions.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/real_fft_batch.hpp"
#include "greens/causal_modulus.hpp"
#include "greens/sinc.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using std::numbers::pi;


// Modes per batch of transforms: one plan serves every batch.
constexpr int batch_size = 64;
// The oversampling of the asymptote's own correction term (it falls like 1/ω²).
constexpr int asymptote_oversampling = 64;

// The sampling: K samples of step Δt, window σ; the spectrum at ω_J − iσ, ω_J = 2πJ/T.
struct Sampling {
  int samples;
  double dt, sigma;
  double period() const { return dt * samples; }
  cd omega(int j) const { return {2.0 * pi * j / period(), -sigma}; }
  // B(ω)/T: the step mean and the 1/T of the inverse DFT.
  cd filter(cd w) const {
    const cd x = cd(0.0, 1.0) * w * dt;  // never 0: σ > 0
    return (1.0 - std::exp(-x)) / x / period();
  }
  // Adds the spectrum value of fine frequency index J to the K bins of a real signal (the
  // positive frequency to bin J mod K, the negative one, conjugated, to −J mod K), keeping bins
  // 0 … K/2 (folding: the samples see every alias).
  template <class Bin>
  void fold(int j, cd value, Bin&& bin) const {
    const int r = j % samples;
    if (r <= samples / 2) bin(r) += value;
    if (j > 0) {
      const int mirror = (samples - r) % samples;
      if (mirror <= samples / 2) bin(mirror) += std::conj(value);
    }
  }
  // From the FFT's order (k < K/2: t = kΔt; else t = (k − K)Δt) to the centred record, undoing
  // the window.
  double centred(const double* field, int k_centred) const {
    const int signed_k = k_centred - samples / 2;
    const int k = signed_k >= 0 ? signed_k : signed_k + samples;
    return field[k] * std::exp(sigma * signed_k * dt);
  }
};

// The step means of S(ω) = 1/((iω + a)·Z(ω)) on the centred record.
std::vector<double> asymptote_samples(const Sampling& s, double a, double density, double c11,
                                      const CausalModulus& modulus) {
  const double z_inf = std::sqrt(density * c11 * modulus.high_frequency_factor());
  std::vector<double> out(static_cast<std::size_t>(s.samples), 0.0);
  // (1/Z∞)·e^{−at}H(t): the mean over (t − Δt, t] is (e^{−a(t−Δt)} − e^{−at})/(aΔt) for t ≥ Δt.
  for (int k = s.samples / 2 + 1; k < s.samples; ++k) {
    const double t = (k - s.samples / 2) * s.dt;
    out[static_cast<std::size_t>(k)] = (std::exp(-a * (t - s.dt)) - std::exp(-a * t)) / (a * s.dt) / z_inf;
  }
  // (1/Z(ω) − 1/Z∞)/(iω + a), folded from far beyond the Nyquist frequency.
  RealFftBatch fft(s.samples, 1);
  for (int j = 0; j <= s.samples / 2; ++j) fft.bin(0, j) = 0.0;
  const int fine = asymptote_oversampling * s.samples / 2;
  for (int j = 0; j < fine; ++j) {
    const cd w = s.omega(j);
    const cd d = 1.0 / std::sqrt(density * c11 * modulus.factor(w)) - 1.0 / z_inf;
    s.fold(j, d / (cd(0.0, 1.0) * w + a) * s.filter(w), [&](int bin) -> cd& { return fft.bin(0, bin); });
  }
  fft.backward();
  for (int k = 0; k < s.samples; ++k) out[static_cast<std::size_t>(k)] += s.centred(fft.field(), k);
  return out;
}

}  // namespace

TwoLayerGreensFunctions::TwoLayerGreensFunctions(const TwoLayerTyre& tyre, double time_step, int samples,
                                                 int oversampling, unsigned threads)
    : tyre_(&tyre), dt_(time_step), samples_(samples) {
  if (!std::isfinite(time_step) || !(time_step > 0.0)) throw std::invalid_argument("two_layer: time step must be > 0");
  if (samples < 4 || samples % 2 != 0) throw std::invalid_argument("two_layer: the number of samples must be even and >= 4");
  if (oversampling < 1) throw std::invalid_argument("two_layer: oversampling must be >= 1");
  sigma_ = std::log(1e4) / (dt_ * samples_);
  const Sampling s{samples_, dt_, sigma_};
  const int columns = tyre.parameters().circumferential_modes + 1;
  const int first = tyre.first_lateral_order();
  const int count = columns * tyre.parameters().lateral_modes;
  modes_.assign(static_cast<std::size_t>(count), std::vector<double>(static_cast<std::size_t>(samples_)));

  // The dashpot asymptote shared by every mode (see the header).
  const ElasticLayer& tread = tyre.stack().tread();
  const CausalModulus tread_modulus(tread.loss_factor);
  const double a = pi / (4.0 * dt_);
  const std::vector<double> asymptote = asymptote_samples(s, a, tread.density, tread.stiffness.c11, tread_modulus);

  const int fine = oversampling * samples_ / 2;
  std::vector<cd> omega(static_cast<std::size_t>(fine)), filter(static_cast<std::size_t>(fine)),
      subtract(static_cast<std::size_t>(fine));
  for (int j = 0; j < fine; ++j) {
    const cd w = s.omega(j);
    omega[static_cast<std::size_t>(j)] = w;
    filter[static_cast<std::size_t>(j)] = s.filter(w);
    subtract[static_cast<std::size_t>(j)] =
        1.0 / ((cd(0.0, 1.0) * w + a) * std::sqrt(tread.density * tread.stiffness.c11 * tread_modulus.factor(w)));
  }
  // Batches of modes, each taken by the next free thread with its own transform buffers (plans
  // are made under FFTW's planner lock): a mode's values do not depend on who computed them or
  // on the other modes of its batch, so the result is the same with any number of threads.
  const int batch = std::min(batch_size, count);
  const int batches = (count + batch - 1) / batch;
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const int workers = std::min(batches, static_cast<int>(threads == 0 ? hardware : threads));
  std::atomic<int> next{0};
  std::vector<std::exception_ptr> failures(static_cast<std::size_t>(workers));
  const auto work = [&](int worker) {
    try {
      RealFftBatch fft(samples_, batch);
      for (int taken = next++; taken < batches; taken = next++) {
        const int start = taken * batch;
        const int used = std::min(batch, count - start);
        for (int b = 0; b < batch; ++b) {
          for (int j = 0; j <= samples_ / 2; ++j) fft.bin(b, j) = 0.0;
          if (b >= used) continue;
          const int index = start + b;
          const int m = index % columns, n = first + index / columns;
          const double kx = tyre.wavenumber_x(m), ky = tyre.wavenumber_y(n);
          for (int j = 0; j < fine; ++j) {
            const std::size_t i = static_cast<std::size_t>(j);
            const cd remainder = tyre.wavenumber_compliance(kx, ky, omega[i])(2, 2) - subtract[i];
            s.fold(j, remainder * filter[i], [&](int bin) -> cd& { return fft.bin(b, bin); });
          }
        }
        fft.backward();
        for (int b = 0; b < used; ++b) {
          std::vector<double>& out = modes_[static_cast<std::size_t>(start + b)];
          const double* field = fft.field() + static_cast<std::size_t>(b) * samples_;
          for (int k = 0; k < samples_; ++k) {
            out[static_cast<std::size_t>(k)] = s.centred(field, k) + asymptote[static_cast<std::size_t>(k)];
          }
        }
      }
    } catch (...) {
      failures[static_cast<std::size_t>(worker)] = std::current_exception();
      next = batches;  // the others stop too
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
  }  // joined here
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
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
