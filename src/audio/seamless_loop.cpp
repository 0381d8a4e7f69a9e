#include "audio/seamless_loop.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {
namespace {

void check_rate(double sample_rate) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    throw std::invalid_argument("seamless loop: the sample rate must be positive");
}

std::size_t samples_of(double seconds, double sample_rate) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) return 0;
  return static_cast<std::size_t>(std::llround(seconds * sample_rate));
}

// Normalised correlation of x[a .. a+L) and x[b .. b+L).
double correlation(const Eigen::VectorXd& x, Eigen::Index a, Eigen::Index b, Eigen::Index length) {
  const auto u = x.segment(a, length);
  const auto v = x.segment(b, length);
  const double uu = u.squaredNorm();
  const double vv = v.squaredNorm();
  if (!(uu > 0.0) || !(vv > 0.0)) return 0.0;
  return u.dot(v) / std::sqrt(uu * vv);
}

}  // namespace

Eigen::VectorXd make_loopable(const Eigen::VectorXd& signal, double sample_rate,
                              const LoopOptions& options) {
  check_rate(sample_rate);
  const Eigen::Index n = signal.size();
  if (n == 0) throw std::invalid_argument("seamless loop: empty signal");
  if (n < 8) return signal;

  // Crossfade L and loop-point search range D, with P = n - L - d >= 2L for every d < D.
  auto length = static_cast<Eigen::Index>(samples_of(options.crossfade_s, sample_rate));
  length = std::clamp<Eigen::Index>(length, 1, n / 4);
  auto search = static_cast<Eigen::Index>(samples_of(options.search_s, sample_rate));
  search = std::clamp<Eigen::Index>(search, 1, std::max<Eigen::Index>(1, n - 3 * length));

  // The loop point: the tail x[P .. P+L) most like the head x[0 .. L).
  Eigen::Index best_period = n - length;
  double best_rho = -2.0;
  for (Eigen::Index d = 0; d < search; ++d) {
    const Eigen::Index period = n - length - d;
    const double rho = correlation(signal, period, 0, length);
    if (rho > best_rho + 1e-12) {
      best_rho = rho;
      best_period = period;
    }
  }
  const double rho = std::clamp(best_rho, 0.0, 1.0);

  Eigen::VectorXd looped = signal.head(best_period);
  for (Eigen::Index i = 0; i < length; ++i) {
    const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(length);
    const double s = 0.5 * (1.0 - std::cos(std::numbers::pi * u));
    const double g = 1.0 / std::sqrt((1.0 - s) * (1.0 - s) + s * s + 2.0 * rho * s * (1.0 - s));
    looped[i] = g * ((1.0 - s) * signal[best_period + i] + s * signal[i]);
  }
  // The period leaves out the last L + d samples; its mean power is brought back to that of
  // the whole signal (a few hundredths of a dB for noise; at most ±0.5 dB, so a transient
  // lost with the tail does not lift the rest).
  const double power_in = signal.squaredNorm() / static_cast<double>(n);
  const double power_out = looped.squaredNorm() / static_cast<double>(looped.size());
  if (power_in > 0.0 && power_out > 0.0) {
    const double max_gain = std::pow(10.0, 0.5 / 20.0);
    looped *= std::clamp(std::sqrt(power_in / power_out), 1.0 / max_gain, max_gain);
  }
  return looped;
}

Eigen::VectorXd loop_to_duration(const Eigen::VectorXd& signal, double sample_rate,
                                 double min_duration_s, const LoopOptions& options) {
  check_rate(sample_rate);
  if (signal.size() == 0) throw std::invalid_argument("seamless loop: empty signal");
  if (!std::isfinite(min_duration_s) || min_duration_s * sample_rate > 1e10)
    throw std::invalid_argument("seamless loop: duration out of range");
  const auto target =
      static_cast<Eigen::Index>(std::max(0.0, std::ceil(min_duration_s * sample_rate - 1e-9)));
  if (signal.size() >= target) return signal;

  const Eigen::VectorXd period = make_loopable(signal, sample_rate, options);
  const Eigen::Index p = period.size();
  const Eigen::Index repeats = (target + p - 1) / p;
  Eigen::VectorXd out(repeats * p);
  for (Eigen::Index k = 0; k < repeats; ++k) out.segment(k * p, p) = period;
  return out;
}

}  // namespace rollnoise
