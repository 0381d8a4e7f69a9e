#include "road/random_road.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/random_spectrum.hpp"
#include "road/spectral_synthesis.hpp"

namespace rollnoise {
namespace {

[[noreturn]] void throw_bad(const char* key, const std::string& problem) {
  throw InputError("", key, problem);  // the factory names the file and the section
}

}  // namespace

RandomRoad::RandomRoad(const RandomRoadSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("RandomRoad: x_max must be finite");
  const SpectrumScales scales = check_spectrum_scales(spec, 16.0);
  const double std_dev = scales.std_dev;
  const bool gaussian = scales.gaussian;
  // The longest and shortest scales of the spectrum set the defaults and the grid.
  const double shortest = scales.shortest;
  const double longest = scales.longest;
  spacing_ = scales.spacing;
  lead_in_ = scales.lead_in;

  // Length of the periodic synthesis grid. Beyond [0, x_max] it keeps a margin, so that the
  // periodic wrap does not correlate the end of the run with its start (Gaussian: R(5 lc) =
  // e^-25), and it is long enough to hold many modes of the spectrum even for a short run.
  const double cover = std::max(spec.x_max, 0.0);
  double period = 0.0;
  if (gaussian) {
    period = std::max(cover + 5.0 * longest, 32.0 * longest);
  } else {
    const double bandwidth = 1.0 / shortest - 1.0 / longest;  // cycles/m
    period = std::max({cover + 4.0 * longest, 8.0 * longest, 16.0 / bandwidth});
  }
  // Compared as doubles: an absurd ratio must not overflow the conversion to an integer.
  const double needed = std::ceil(period / spacing_);
  if (!(needed <= static_cast<double>(max_grid_size))) {
    throw_bad("sample_spacing", "the road needs " + format_number(needed) +
                              " samples, more than the limit of 2^26; use a larger "
                              "sample_spacing or a shorter run");
  }
  const std::size_t n = fft_friendly_size(static_cast<std::size_t>(needed));
  grid_size_ = n;
  const std::size_t last = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(cover / spacing_)));

  // Random complex amplitudes for modes m = 1 .. (n-1)/2, wavenumber m/length (cycles/m):
  // a complex normal times the square root of the spectral density, up to a constant factor
  // that the scaling below removes (spectral_synthesis.hpp). The mean and the Nyquist mode of
  // an even grid are 0 (the latter is beyond both spectra).
  const double band_low = 1.0 / longest;
  const double band_high = 1.0 / shortest;
  const std::vector<double> grid = synthesise_periodic_profile(n, spacing_, spec.seed, [&](double wavenumber) {
    if (gaussian) {
      // Two-sided density of R(xi) = s^2 exp(-(xi/lc)^2) in k = 2 pi n is
      // s^2 lc / (2 sqrt(pi)) exp(-k^2 lc^2 / 4); its square root, up to a constant factor.
      const double a = std::numbers::pi * wavenumber * longest;
      return std::exp(-0.5 * a * a);
    }
    return (wavenumber >= band_low && wavenumber <= band_high) ? 1.0 : 0.0;
  });

  // Scale so that the sample standard deviation of the stationary profile over the grid points
  // covering [0, x_max] (j = 0 .. last) is exactly std_dev: sqrt(sum (r_j - mean)^2 / count),
  // the 1/count form, since these points are the whole road the run sees. The mean is not
  // removed: it is the road's own (near zero) mean over the run. The lead-in window is applied
  // afterwards, so it lowers the heights within lead_in and leaves the rest as scaled.
  const std::size_t count = last + 1;
  double mean = 0.0;
  for (std::size_t j = 0; j < count; ++j) mean += grid[j];
  mean /= static_cast<double>(count);
  double sum_sq = 0.0;
  for (std::size_t j = 0; j < count; ++j) sum_sq += (grid[j] - mean) * (grid[j] - mean);
  const double deviation = std::sqrt(sum_sq / static_cast<double>(count));
  if (!(deviation > 0.0) || !std::isfinite(deviation)) {
    throw std::logic_error("RandomRoad: the synthesised profile has no variance");
  }
  const double scale = std_dev / deviation;

  samples_.resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    double value = scale * grid[j];
    const double x = spacing_ * static_cast<double>(j);
    // Raised cosine: 0 with zero slope at x = 0, 1 with zero slope at lead_in, so the road
    // leaves the flat lead-in without a jump or a kink.
    if (x < lead_in_) value *= 0.5 * (1.0 - std::cos(std::numbers::pi * x / lead_in_));
    samples_[j] = value;
  }
}

std::string RandomRoad::type() const { return "random"; }

double RandomRoad::height(double x) const {
  if (x < 0.0) return 0.0;  // lead-in convention (road_profile.hpp)
  const double t = x / spacing_;
  const std::size_t last = samples_.size() - 1;
  if (!(t <= static_cast<double>(last))) {  // also NaN
    throw std::logic_error("RandomRoad::height: x = " + format_number(x) +
                           " m is beyond the generated range [0, " + format_number(end()) + "]");
  }
  const std::size_t i = std::min(static_cast<std::size_t>(t), last - 1);
  const double f = t - static_cast<double>(i);
  // (1-f) a + f b: exact at the grid points, including the last one (f = 1).
  return (1.0 - f) * samples_[i] + f * samples_[i + 1];
}

}  // namespace rollnoise
