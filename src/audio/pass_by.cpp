#include "audio/pass_by.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "audio/looped_lagrange.hpp"
#include "audio/moving_image_filter.hpp"
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

// The source with the two paths' interference at the closest approach divided out, so that the
// pass-by gives it back there: the stationary signal already holds the road's reflection, and
// the paths below apply it again. Bin m times
//     E(f) = (1/r1 + R/r2) / (1/r1 + Q0(f)·e^{−ikΔr}/r2),  Δr = r2 − r1,
// Q0 = R over a rigid road, the reflection factor at the closest approach over an absorbing one
// (there R = 1 in the normalisation), e^{−ikΔr} the image path's delay behind the direct one.
// E = 1 at zero frequency (Q0 → 1, or R); the mean is kept. Where direct and image nearly
// cancel (a source a metre up at 550 Hz), E is large: it undoes the dip the source has.
Eigen::VectorXd abeam_equalised(const Eigen::VectorXd& source, double sample_rate, double r1, double r2, double sound_speed,
                                double reflection, const std::vector<std::complex<double>>& q0) {
  const auto n = static_cast<int>(source.size());
  RealFftBatch fft(n, 1);
  const double normalisation = 1.0 / r1 + reflection / r2;
  return filtered_loop(fft, looped_spectrum(fft, source), [&](int m) -> std::complex<double> {
    if (m == 0) return 1.0;
    const double k = 2.0 * std::numbers::pi * m * sample_rate / n / sound_speed;
    const std::complex<double> q = q0.empty() ? std::complex<double>(reflection) : q0[static_cast<std::size_t>(m)];
    return normalisation / (1.0 / r1 + q * std::polar(1.0, -k * (r2 - r1)) / r2);
  });
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
  // The emission time's lag of a path at output time tau (below).
  const auto lag_of = [&](const Path& path, double tau) {
    return (std::sqrt(c2 * v2 * tau * tau + a * path.lateral_sq) - v2 * tau) / a;
  };
  // What the paths read: the source with the closest approach's interference divided out.
  const Eigen::VectorXd equalised =
      reflection > 0.0 ? abeam_equalised(source, sample_rate, r1_0, r2_0, c, reflection,
                                         settings.ground_reflection_factor
                                             ? response_on_bins(static_cast<int>(source.size()), sample_rate,
                                                                [&](double f) { return settings.ground_reflection_factor(f, d); })
                                             : std::vector<std::complex<double>>())
                       : source;
  // Over an absorbing road, the image filtered along the stretch of road the pass-by hears it
  // emitted from: from the first output sample's emission to the last's.
  std::optional<MovingImageFilter> image;
  if (settings.ground_reflection_factor) {
    const auto emitted_at = [&](double tau) { return v * (tau - lag_of(paths[1], tau)); };
    const MovingImageFilter::Geometry geometry{d, emitted_at(-half), emitted_at(static_cast<double>(n_out - 1) / sample_rate - half),
                                               below, v / c};
    image.emplace(equalised, sample_rate, geometry, settings.ground_reflection_factor);
  }

  Eigen::VectorXd out(n_out);
  for (Eigen::Index n = 0; n < n_out; ++n) {
    if (n % 65536 == 0) settings.cancel.throw_if_cancelled();  // an hour's pass-by is 1.7e8 samples
    const double tau = static_cast<double>(n) / sample_rate - half;
    double p = 0.0;
    for (int k = 0; k < path_count; ++k) {
      const Path& path = paths[static_cast<std::size_t>(k)];
      const double lag = lag_of(path, tau);
      const double r = c * lag;
      // Source sample position of the emission time: n − (r/c − r1_0/c) · fs, formed from the
      // integer n so that long outputs keep their sub-sample precision.
      const double u = static_cast<double>(n) - (lag - lag_0) * sample_rate;
      const double signal = k == 1 && image ? image->at(v * (tau - lag), u)
                                            : read_looped(equalised, looped_lagrange_taps(u, equalised.size()));
      p += path.gain * signal / r;
    }
    out[n] = p;
  }
  return out;
}

}  // namespace rollnoise
