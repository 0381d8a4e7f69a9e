#include "audio/pass_by.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/real_fft_batch.hpp"

namespace rollnoise {
namespace {

[[noreturn]] void reject(const char* parameter, const char* requirement, double value) {
  char number[32];
  std::snprintf(number, sizeof number, "%g", value);
  std::string message = "pass_by: ";
  message += parameter;
  message += " must be ";
  message += requirement;
  message += " (got ";
  message += number;
  message += ')';
  throw std::invalid_argument(message);
}

void check(const Eigen::VectorXd& source, double sample_rate, const PassBySettings& s) {
  if (source.size() == 0) throw std::invalid_argument("pass_by: source is empty");
  if (!source.allFinite()) throw std::invalid_argument("pass_by: source has non-finite samples");
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    reject("sample_rate", "positive and finite", sample_rate);
  if (!(s.sound_speed > 0.0) || !std::isfinite(s.sound_speed))
    reject("settings.sound_speed", "positive and finite", s.sound_speed);
  if (!(s.speed > 0.0) || !(s.speed < 0.3 * s.sound_speed))
    reject("settings.speed", "in (0, 0.3 · sound_speed)", s.speed);
  if (!(s.receiver_distance > 0.0) || !std::isfinite(s.receiver_distance))
    reject("settings.receiver_distance", "positive and finite", s.receiver_distance);
  if (!(s.receiver_height >= 0.0) || !std::isfinite(s.receiver_height))
    reject("settings.receiver_height", "non-negative and finite", s.receiver_height);
  if (!(s.source_height >= 0.0) || !std::isfinite(s.source_height))
    reject("settings.source_height", "non-negative and finite", s.source_height);
  if (!(s.ground_reflection >= 0.0) || !(s.ground_reflection <= 1.0))
    reject("settings.ground_reflection", "in [0, 1]", s.ground_reflection);
  if (s.ground_reflection_factor && s.ground_reflection != 1.0)
    reject("settings.ground_reflection", "1 with a ground_reflection_factor", s.ground_reflection);
  // 2^34 samples (4 days at 48 kHz) also keeps llround below in range.
  if (!(s.duration > 0.0) || !(s.duration * sample_rate <= 0x1p34))
    reject("settings.duration", "positive and at most 2^34 samples", s.duration);
  if (std::llround(s.duration * sample_rate) < 1)
    reject("settings.duration", "at least one sample long", s.duration);
}

// One propagation path (direct or via the image source): the squared distance between the
// receiver and the path's source line at the closest approach, and the gain on q/r.
struct Path {
  double lateral_sq;
  double gain;
};

// x mod n in [0, n) for any sign of x (n > 0).
Eigen::Index wrap(Eigen::Index x, Eigen::Index n) {
  const Eigen::Index m = x % n;
  return m < 0 ? m + n : m;
}

// The looped source at fractional sample position u, by 6-point Lagrange interpolation on
// samples floor(u) − 2 ... floor(u) + 3. Six points rather than four: the error for a tone of
// frequency f is at most about 5e−3·(2π f/fs)^6 (mid-interval) (1.7e−5, −95 dB, for 3 kHz
// at 48 kHz), against 1e−3 (−60 dB) for Catmull-Rom, for two more multiply-adds.
double interpolate(const Eigen::VectorXd& x, double u) {
  const Eigen::Index n = x.size();
  const double period = static_cast<double>(n);
  double v = u - period * std::floor(u / period);  // [0, n], n only by rounding
  if (v >= period) v = 0.0;
  const auto i0 = static_cast<Eigen::Index>(v);
  const double f = v - static_cast<double>(i0);

  // w_k = Π_{m ≠ k} (f − m) / (k − m) for nodes m = −2 ... 3, from prefix and suffix products
  // of (f − m) so an integer f needs no division by zero.
  constexpr std::array<double, 6> denominator{-120.0, 24.0, -12.0, 12.0, -24.0, 120.0};
  std::array<double, 6> d{};
  for (int k = 0; k < 6; ++k) d[static_cast<std::size_t>(k)] = f - static_cast<double>(k - 2);
  std::array<double, 6> prefix{};
  double product = 1.0;
  for (std::size_t k = 0; k < 6; ++k) {
    prefix[k] = product;
    product *= d[k];
  }
  double sum = 0.0;
  product = 1.0;  // suffix product
  for (std::size_t k = 6; k-- > 0;) {
    const double w = prefix[k] * product / denominator[k];
    sum += w * x[wrap(i0 + static_cast<Eigen::Index>(k) - 2, n)];
    product *= d[k];
  }
  return sum;
}

// The looped source filtered by Q: each bin m of its discrete Fourier transform (frequency
// m·fs/N) times Q(m·fs/N), the circular convolution, exact for the periodic signal the pass-by
// reads. FFTW's forward transform has e^{−iωt}, so a bin is the amplitude of e^{+iωt}, the
// convention of Q. The mean (bin 0) is kept; Nyquist's bin of an even N must stay real.
Eigen::VectorXd filtered_by(const Eigen::VectorXd& source, double sample_rate,
                            const std::function<std::complex<double>(double)>& factor) {
  const auto n = static_cast<int>(source.size());
  RealFftBatch fft(n, 1);
  for (int i = 0; i < n; ++i) fft.at(0, i) = source[i];
  fft.forward();
  for (int m = 1; m < fft.bins(); ++m) {
    const std::complex<double> q = factor(m * sample_rate / n);
    if (!std::isfinite(q.real()) || !std::isfinite(q.imag()))
      throw std::invalid_argument("pass_by: settings.ground_reflection_factor must be finite");
    fft.bin(0, m) *= (2 * m == n) ? std::complex<double>(q.real(), 0.0) : q;
  }
  fft.backward();
  Eigen::VectorXd out(n);
  for (int i = 0; i < n; ++i) out[i] = fft.at(0, i) / n;
  return out;
}

}  // namespace

Eigen::VectorXd pass_by(const Eigen::VectorXd& source, double sample_rate,
                        const PassBySettings& settings) {
  check(source, sample_rate, settings);
  const double c = settings.sound_speed;
  const double v = settings.speed;
  const double d = settings.receiver_distance;
  const double above = settings.receiver_height - settings.source_height;
  const double below = settings.receiver_height + settings.source_height;
  const double r1_0 = std::sqrt(d * d + above * above);
  const double r2_0 = std::sqrt(d * d + below * below);
  const double reflection = settings.ground_reflection;

  // q = source / (1/r1_0 + R/r2_0): the two paths abeam add up to the source at low frequency.
  const double norm = 1.0 / (1.0 / r1_0 + reflection / r2_0);
  const std::array<Path, 2> paths{Path{r1_0 * r1_0, norm}, Path{r2_0 * r2_0, reflection * norm}};
  const int path_count = reflection > 0.0 ? 2 : 1;  // R = 0: the image adds nothing
  // What each path reads: the source, or for the image over an absorbing road the source
  // filtered by Q (made once, before the time loop).
  const Eigen::VectorXd image_source =
      settings.ground_reflection_factor ? filtered_by(source, sample_rate, settings.ground_reflection_factor) : Eigen::VectorXd();
  const std::array<const Eigen::VectorXd*, 2> read{&source, settings.ground_reflection_factor ? &image_source : &source};

  // Emission time in closed form rather than by iteration: with τ = t − T/2 and the source at
  // x = V τ_e, t = t_e + r(t_e)/c squared is (c² − V²) τ_e² − 2c² τ τ_e + c² τ² − D² = 0, and
  // the root before τ gives the travel time
  //     τ − τ_e = r/c = (√(c² V² τ² + (c² − V²) D²) − V² τ) / (c² − V²),
  // exact for uniform straight motion and free of cancellation for V ≤ 0.3 c (the square root
  // is at least c/V times V² |τ|).
  const double c2 = c * c;
  const double v2 = v * v;
  const double a = c2 - v2;
  const double half = 0.5 * settings.duration;
  const double lag_0 = r1_0 / c;  // the time alignment: abeam and direct, source(t) comes back

  const auto n_out = static_cast<Eigen::Index>(std::llround(settings.duration * sample_rate));
  Eigen::VectorXd out(n_out);
  for (Eigen::Index n = 0; n < n_out; ++n) {
    if (n % 65536 == 0) settings.cancel.throw_if_cancelled();  // an hour's pass-by is 1.7e8 samples
    const double tau = static_cast<double>(n) / sample_rate - half;
    double p = 0.0;
    for (int k = 0; k < path_count; ++k) {
      const Path& path = paths[static_cast<std::size_t>(k)];
      const double lag = (std::sqrt(c2 * v2 * tau * tau + a * path.lateral_sq) - v2 * tau) / a;
      const double r = c * lag;
      // Source sample position of the emission time: n − (r/c − r1_0/c) · fs, formed from the
      // integer n so that long outputs keep their sub-sample precision.
      const double u = static_cast<double>(n) - (lag - lag_0) * sample_rate;
      p += path.gain * interpolate(*read[static_cast<std::size_t>(k)], u) / r;
    }
    out[n] = p;
  }
  return out;
}

}  // namespace rollnoise
