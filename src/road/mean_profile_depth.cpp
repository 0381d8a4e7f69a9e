#include "road/mean_profile_depth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "road/least_squares_line.hpp"

namespace rollnoise {
namespace {

// Relative slack for comparing lengths computed in floating point (a 100 mm profile at
// 0.5 mm is exactly one segment, whatever the rounding of 200 · 0.5e-3).
constexpr double slack = 1e-9;

void check_spacing(double spacing_m) {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0 && spacing_m <= mpd_max_spacing_m * (1 + slack))) {
    throw InputError("", "spacing",
                     "ISO 13473-1 needs a sample spacing > 0 and at most 1 mm (is " +
                         format_number(spacing_m) + " m)");
  }
}

// First index of the bin [k·ratio, (k+1)·ratio) in units of the input spacing.
std::size_t bin_begin(std::size_t k, double ratio) {
  return static_cast<std::size_t>(std::ceil(static_cast<double>(k) * ratio - slack));
}

// Step 1: averages over consecutive bins of `target` metres.
std::vector<double> resample(std::span<const double> z, double spacing_m, double target_m) {
  const double ratio = target_m / spacing_m;  // input samples per bin (> 1)
  const auto bins = static_cast<std::size_t>(std::floor(static_cast<double>(z.size()) / ratio + slack));
  std::vector<double> out(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    const std::size_t begin = bin_begin(k, ratio);
    const std::size_t end = std::min(bin_begin(k + 1, ratio), z.size());
    double sum = 0.0;
    for (std::size_t i = begin; i < end; ++i) sum += z[i];
    out[k] = sum / static_cast<double>(end - begin);
  }
  return out;
}

struct Biquad {
  double b0, b1, b2, a1, a2;
};

// 2nd-order Butterworth low pass, bilinear transform pre-warped to the cut-off.
Biquad butterworth_lowpass(double spacing_m, double cutoff_wavelength_m) {
  const double k = std::tan(std::numbers::pi * spacing_m / cutoff_wavelength_m);
  const double norm = 1.0 + std::numbers::sqrt2 * k + k * k;
  const double b0 = k * k / norm;
  return {b0, 2.0 * b0, b0, 2.0 * (k * k - 1.0) / norm, (1.0 - std::numbers::sqrt2 * k + k * k) / norm};
}

// One pass in direct form II transposed, starting in the steady state of the first input.
void run(const Biquad& f, std::vector<double>& x) {
  const double x0 = x.front();
  double s2 = (f.b2 - f.a2) * x0;
  double s1 = (f.b1 - f.a1) * x0 + s2;
  for (double& v : x) {
    const double in = v;
    const double y = f.b0 * in + s1;
    s1 = f.b1 * in - f.a1 * y + s2;
    s2 = f.b2 * in - f.a2 * y;
    v = y;
  }
}

}  // namespace

std::vector<double> mpd_lowpass(std::span<const double> z, double spacing_m) {
  check_spacing(spacing_m);
  if (z.size() < 2) return {z.begin(), z.end()};
  const Biquad filter = butterworth_lowpass(spacing_m, mpd_lowpass_cutoff_m);
  // Odd reflection about each end over ten cut-off wavelengths and at least 64 samples, over
  // which the start-up transient decays (the poles' radius sqrt(a2) is 0.45 at 0.5 mm and 0.69
  // at 1 mm spacing: 0.69^64 < 1e-10). The reflection continues a line exactly, and a sinusoid
  // that ends at a zero crossing; elsewhere it leaves a step in curvature, whose filtered
  // transient reaches a few millimetres into the profile.
  const auto wanted = static_cast<std::size_t>(std::ceil(10.0 * mpd_lowpass_cutoff_m / spacing_m));
  const std::size_t pad = std::min(std::max<std::size_t>(wanted, 64), z.size() - 1);
  const std::size_t n = z.size();
  std::vector<double> x(n + 2 * pad);
  for (std::size_t i = 0; i < pad; ++i) {
    x[i] = 2.0 * z[0] - z[pad - i];
    x[pad + n + i] = 2.0 * z[n - 1] - z[n - 2 - i];
  }
  std::copy(z.begin(), z.end(), x.begin() + static_cast<std::ptrdiff_t>(pad));
  run(filter, x);
  std::reverse(x.begin(), x.end());
  run(filter, x);
  std::reverse(x.begin(), x.end());
  return {x.begin() + static_cast<std::ptrdiff_t>(pad), x.begin() + static_cast<std::ptrdiff_t>(pad + n)};
}

MpdResult mean_profile_depth(std::span<const double> z, double spacing_m) {
  check_spacing(spacing_m);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (!std::isfinite(z[i])) {
      throw InputError("", "profile",
                       "sample " + std::to_string(i) + " is not a finite height; clean the profile first");
    }
  }
  const double length = static_cast<double>(z.size()) * spacing_m;
  if (length < mpd_segment_length_m * (1 - slack)) {
    throw InputError("", "profile",
                     "the profile is " + format_number(length * 1e3) +
                         " mm long; the mean profile depth needs at least one 100 mm segment");
  }

  MpdResult result;
  std::vector<double> profile;
  if (spacing_m < mpd_resample_spacing_m * (1 - slack)) {
    profile = resample(z, spacing_m, mpd_resample_spacing_m);
    result.spacing_m = mpd_resample_spacing_m;
  } else {
    profile.assign(z.begin(), z.end());
    result.spacing_m = spacing_m;
  }
  profile = mpd_lowpass(profile, result.spacing_m);

  const double per_segment = mpd_segment_length_m / result.spacing_m;  // samples (may be fractional)
  const auto segments = static_cast<std::size_t>(
      std::floor(static_cast<double>(profile.size()) / per_segment + slack));
  if (segments == 0) {
    throw InputError("", "profile", "the profile is shorter than one 100 mm segment after resampling");
  }
  double msd_sum = 0.0;
  std::vector<double> segment;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t begin = bin_begin(s, per_segment);
    const std::size_t end = std::min(bin_begin(s + 1, per_segment), profile.size());
    const std::size_t half = bin_begin(2 * s + 1, per_segment / 2.0);  // first sample at x >= 50 mm
    segment.assign(profile.begin() + static_cast<std::ptrdiff_t>(begin),
                   profile.begin() + static_cast<std::ptrdiff_t>(end));
    // Slope suppression: subtract the least-squares line over the segment.
    const auto m = static_cast<double>(segment.size());
    const LeastSquaresLine trend = least_squares_line(segment);
    double level = 0.0;
    for (std::size_t i = 0; i < segment.size(); ++i) {
      segment[i] -= trend.at(i);
      level += segment[i];
    }
    level /= m;
    const auto split = static_cast<std::ptrdiff_t>(half - begin);
    const double peak1 = *std::max_element(segment.begin(), segment.begin() + split);
    const double peak2 = *std::max_element(segment.begin() + split, segment.end());
    msd_sum += 0.5 * (peak1 + peak2) - level;
  }
  result.segments = segments;
  result.mpd_m = msd_sum / static_cast<double>(segments);
  result.etd_m = 0.2e-3 + 0.8 * result.mpd_m;
  return result;
}

}  // namespace rollnoise
