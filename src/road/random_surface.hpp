#pragma once
// A normally distributed, isotropic, stationary random road surface r(x, y) (MODEL.md §7), made
// by 2-D spectral synthesis from a seed, so that a case file always describes the same surface:
// a texture-like road for a tyre that rolls several lateral lines over it.
//
// Two isotropic spectra (functions of the wavenumber magnitude |n| = sqrt(nx^2 + ny^2) only):
//  - Gaussian autocorrelation R(dx, dy) = std_dev^2 exp(-(dx^2 + dy^2) / correlation_length^2),
//    i.e. a 2-D spectral density proportional to exp(-pi^2 correlation_length^2 |n|^2);
//  - band limited: a 2-D spectral density that is constant for 1/max_wavelength <= |n| <=
//    1/min_wavelength (|n| in cycles/m) and zero elsewhere. A 1-D transect of such a surface
//    has wavenumbers from 0 up to 1/min_wavelength: the annulus projects onto the whole disc.
//
// Grid. Samples at x = i h (i = 0 .. nx - 1, covering [0, max(length, x_max)]) and y = j h
// (|j| <= ceil(width / (2 h)), covering [-width/2, width/2]), h = sample_spacing, cut from one
// periodic synthesis grid whose periods exceed the covered extents by a margin (Gaussian:
// 5 correlation_length, R = e^-25 across the wrap; band: 4 max_wavelength), so that the two
// ends of the surface are not correlated through the periodic wrap. Bilinear interpolation
// in between.
//
// Independence of the run. The grid, and so the surface, depends only on the spectrum,
// sample_spacing, seed, `length` and `width`: runs of different duration (x_max <= length) and
// tyres of different width (half_width <= width/2) see the same surface. A run longer than
// `length` gets a longer, and therefore different, surface; a tyre wider than `width` is an
// InputError.
//
// Scaling. The surface is scaled so that the standard deviation of its samples over the whole
// stored grid ([0, end_x()] x [-half_extent_y(), half_extent_y()], all points, population form
// sqrt(sum (r - mean)^2 / count), the mean not removed) is exactly std_dev. A raised-cosine
// window in x over the first lead_in metres is applied afterwards (so r(0, y) = 0, joining the
// flat lead-in x < 0 without a jump or kink); it lowers the heights within lead_in only.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "road/road_surface.hpp"

namespace rollnoise {

struct RandomSurfaceSpec {
  enum class Spectrum { gaussian, band };

  double std_dev = 0.0;  // m, > 0
  Spectrum spectrum = Spectrum::gaussian;
  double correlation_length = 0.0;  // m, > 0 (gaussian)
  double min_wavelength = 0.0;      // m, > 0, < max_wavelength (band)
  double max_wavelength = 0.0;      // m (band)
  // m, > 0, <= correlation_length / 2 or min_wavelength / 2; default a quarter of that limit
  // (correlation_length / 8 or min_wavelength / 8).
  std::optional<double> sample_spacing;
  // m, >= 0; default 2 correlation_length or 2 max_wavelength.
  std::optional<double> lead_in;
  std::uint64_t seed = 1;
  double length = 20.0;  // m, > 0: the surface covers x in [0, max(length, x_max)]
  double width = 0.5;    // m, > 0: the surface covers y in [-width/2, width/2]
  double x_max = 0.0;    // the run's largest x (m)
  double half_width = 0.0;  // the run's largest |y| (m), <= width / 2
};

class RandomSurface final : public RoadSurface {
 public:
  // Generates the surface. Bad parameters are InputErrors whose key is the bare key name
  // ("sample_spacing", "width") and whose source is empty: make_road_surface adds both.
  explicit RandomSurface(const RandomSurfaceSpec& spec);

  std::string type() const override;  // "random_surface"
  // Bilinear interpolation between grid points; 0 for x < 0. x > end_x() or
  // |y| > half_extent_y() (or NaN) is a std::logic_error.
  double height(double x, double y) const override;

  double spacing() const noexcept { return spacing_; }
  double lead_in() const noexcept { return lead_in_; }
  // Stored grid: x = i spacing, i = 0 .. x_count()-1; y = (j - (y_count()-1)/2) spacing,
  // j = 0 .. y_count()-1 (y_count() odd, y = 0 is a grid line).
  std::size_t x_count() const noexcept { return x_count_; }
  std::size_t y_count() const noexcept { return y_count_; }
  double end_x() const noexcept { return spacing_ * static_cast<double>(x_count_ - 1); }
  double half_extent_y() const noexcept {
    return spacing_ * static_cast<double>((y_count_ - 1) / 2);
  }
  // The stored sample at grid point (i, j), as height() returns it there.
  double sample(std::size_t i, std::size_t j) const noexcept { return data_[i * stride_ + j]; }
  // Size of the periodic synthesis grid (FFT-friendly sizes).
  std::size_t grid_x() const noexcept { return grid_x_; }
  std::size_t grid_y() const noexcept { return grid_y_; }

  // Largest synthesis grid accepted, in points (2^26: 0.5 GiB for its one work array).
  static constexpr std::size_t max_grid_points = std::size_t{1} << 26;

 private:
  struct FftwFree {
    void operator()(double* p) const noexcept;
  };

  double spacing_ = 0.0;
  double lead_in_ = 0.0;
  std::size_t grid_x_ = 0;
  std::size_t grid_y_ = 0;
  std::size_t x_count_ = 0;
  std::size_t y_count_ = 0;
  std::size_t stride_ = 0;  // doubles between rows (the FFTW in-place padding)
  // The FFTW work array of the synthesis, kept as the storage: row i (x) starts at i stride_.
  std::unique_ptr<double[], FftwFree> data_;
};

}  // namespace rollnoise
