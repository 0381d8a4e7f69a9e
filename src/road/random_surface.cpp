#include "road/random_surface.hpp"

#include "road/sampled_road.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>
#include <stdexcept>

#include <fftw3.h>

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

void RandomSurface::FftwFree::operator()(double* p) const noexcept { fftw_free(p); }

RandomSurface::RandomSurface(const RandomSurfaceSpec& spec) {
  if (!std::isfinite(spec.x_max)) throw std::invalid_argument("RandomSurface: x_max must be finite");
  if (!(spec.half_width >= 0.0) || !std::isfinite(spec.half_width)) {
    throw std::invalid_argument("RandomSurface: half_width must be finite and >= 0");
  }
  const SpectrumScales scales = check_spectrum_scales(spec, 8.0);
  const double std_dev = scales.std_dev;
  const bool gaussian = scales.gaussian;
  const double shortest = scales.shortest;
  const double longest = scales.longest;
  spacing_ = scales.spacing;
  lead_in_ = scales.lead_in;
  const double length = require_positive_scale("length", spec.length);
  const double width = require_positive_scale("width", spec.width);
  if (spec.half_width > width / 2.0) {
    throw_bad("width", "the surface is " + format_number(width) +
                     " m wide (y from -width/2 to width/2), but the tyre's contact grid reaches "
                     "|y| = " + format_number(spec.half_width) +
                     " m; set width to at least " + format_number(2.0 * spec.half_width) + " m");
  }

  // Covered extents, in samples. Compared as doubles first: an absurd ratio must not overflow
  // the conversion to an integer.
  const double cover_x = std::max(length, spec.x_max);
  const double last_x_d = std::max(1.0, std::ceil(cover_x / spacing_));
  const double half_y_d = std::max(1.0, std::ceil(width / 2.0 / spacing_));
  // The periodic wrap must not correlate the far edge of the stored grid with its near edge
  // (Gaussian: 5 lc, R = e^-25; band: 4 max_wavelength), and the periods hold many modes of the
  // spectrum even for a small surface.
  const double margin = (gaussian ? 5.0 : 4.0) * longest;
  const double min_period = (gaussian ? 16.0 : 8.0) * longest;
  const double margin_samples = std::ceil(margin / spacing_);
  const double min_samples = std::ceil(min_period / spacing_);
  const double needed_x = std::max(last_x_d + margin_samples, min_samples);
  const double needed_y = std::max(2.0 * half_y_d + margin_samples, min_samples);
  const double limit = static_cast<double>(max_grid_points);
  const auto too_big = [&](double points) {
    throw_bad("sample_spacing", "the surface needs a synthesis grid of " + format_number(points) +
                              " samples, more than the limit of 2^26; use a larger "
                              "sample_spacing, a shorter length or run, or a smaller width");
  };
  if (!(needed_x * needed_y <= limit)) too_big(needed_x * needed_y);
  const std::size_t n0 = fft_friendly_size(static_cast<std::size_t>(needed_x));
  const std::size_t n1 = fft_friendly_size(static_cast<std::size_t>(needed_y));
  if (static_cast<double>(n0) * static_cast<double>(n1) > limit) {
    too_big(static_cast<double>(n0) * static_cast<double>(n1));
  }
  grid_x_ = n0;
  grid_y_ = n1;
  x_count_ = static_cast<std::size_t>(last_x_d) + 1;
  const auto half_y = static_cast<std::size_t>(half_y_d);
  y_count_ = 2 * half_y + 1;

  // In-place real-to-complex layout: n0 rows of n1/2+1 complex numbers, read back as n0 rows
  // of n1 real numbers with a stride of 2 (n1/2+1).
  const std::size_t half = n1 / 2 + 1;
  stride_ = 2 * half;
  data_.reset(fftw_alloc_real(n0 * stride_));
  if (!data_) throw std::bad_alloc();

  // Random complex amplitudes: a complex normal times the square root of the spectral density
  // at wavenumber (nx, ny), up to a constant factor that the scaling removes
  // (spectral_synthesis.hpp: mean, Nyquist row and column 0, column k = 0 Hermitian).
  const double period_x = spacing_ * static_cast<double>(n0);
  const double period_y = spacing_ * static_cast<double>(n1);
  const double band_low = 1.0 / longest;
  const double band_high = 1.0 / shortest;
  synthesise_periodic_surface(data_.get(), n0, n1, period_x, period_y, spec.seed, [&](double nx, double ny) {
    const double n2 = nx * nx + ny * ny;
    if (gaussian) {
      // 2-D density of R = s^2 exp(-(r/lc)^2): pi s^2 lc^2 exp(-pi^2 lc^2 |n|^2) (n in
      // cycles/m); its square root up to a constant factor that the scaling removes.
      return std::exp(-0.5 * std::numbers::pi * std::numbers::pi * longest * longest * n2);
    }
    const double magnitude = std::sqrt(n2);
    return (magnitude >= band_low && magnitude <= band_high) ? 1.0 : 0.0;
  });

  // Scale so that the standard deviation over the stored grid (every point of [0, end_x()] x
  // [-half_extent_y(), half_extent_y()]) is exactly std_dev, population form, mean not removed:
  // these points are the whole surface any run sees. Then the lead-in window.
  double* const r = data_.get();
  const double count = static_cast<double>(x_count_) * static_cast<double>(y_count_);
  double mean = 0.0;
  for (std::size_t i = 0; i < x_count_; ++i) {
    for (std::size_t j = 0; j < y_count_; ++j) mean += r[i * stride_ + j];
  }
  mean /= count;
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < x_count_; ++i) {
    for (std::size_t j = 0; j < y_count_; ++j) {
      const double d = r[i * stride_ + j] - mean;
      sum_sq += d * d;
    }
  }
  const double deviation = std::sqrt(sum_sq / count);
  if (!(deviation > 0.0) || !std::isfinite(deviation)) {
    throw std::logic_error("RandomSurface: the synthesised surface has no variance");
  }
  const double scale = std_dev / deviation;
  for (std::size_t i = 0; i < x_count_; ++i) {
    double factor = scale;
    const double x = spacing_ * static_cast<double>(i);
    // Raised cosine: 0 with zero slope at x = 0, 1 with zero slope at lead_in.
    if (x < lead_in_) factor *= 0.5 * (1.0 - std::cos(std::numbers::pi * x / lead_in_));
    for (std::size_t j = 0; j < y_count_; ++j) r[i * stride_ + j] *= factor;
  }
}

std::string RandomSurface::type() const { return "random_surface"; }

double RandomSurface::height(double x, double y) const {
  return grid_height(data_.get(), stride_, x_count_, y_count_, spacing_, x, y, "random_surface");
}

}  // namespace rollnoise
