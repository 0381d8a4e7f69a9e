#include "road/spectral_synthesis.hpp"

#include <cmath>
#include <memory>
#include <new>
#include <numbers>
#include <random>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/portable_normal.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

}  // namespace

std::size_t synthesis_grid_size(double needed, double needed_total) {
  // Compared as doubles: an absurd ratio must not overflow the conversion to an integer.
  if (!(needed_total <= static_cast<double>(max_synthesis_points))) {
    throw InputError("", "sample_spacing",
                     "the road needs a synthesis grid of " + format_number(needed_total) +
                         " points, more than the limit of 2^26; use a larger sample_spacing or a "
                         "shorter length (or a smaller width)");
  }
  return fft_friendly_size(static_cast<std::size_t>(std::ceil(needed)));
}

std::vector<double> synthesise_periodic_profile(std::size_t n, double spacing, std::uint64_t seed,
                                                const std::function<double(double)>& amplitude,
                                                SynthesisAmplitudes kind) {
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  std::unique_ptr<double[], FftwFree> grid(fftw_alloc_real(n));
  if (!spectrum || !grid) throw std::bad_alloc();
  const FftwPlan plan(
      [&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum.get(), grid.get(), FFTW_ESTIMATE); });
  for (std::size_t m = 0; m <= n / 2; ++m) {
    spectrum[m][0] = 0.0;
    spectrum[m][1] = 0.0;
  }
  const double period = spacing * static_cast<double>(n);
  std::mt19937_64 engine(seed);
  for (std::size_t m = 1; 2 * m < n; ++m) {
    const auto [re, im] = kind == SynthesisAmplitudes::gaussian ? portable::standard_normal_pair(engine)
                                                                 : portable::random_phasor(engine);
    const double a = (kind == SynthesisAmplitudes::gaussian ? 1.0 : std::numbers::sqrt2) *
                     amplitude(static_cast<double>(m) / period);
    spectrum[m][0] = a * re;
    spectrum[m][1] = a * im;
  }
  plan.execute();
  return std::vector<double>(grid.get(), grid.get() + n);
}

void synthesise_periodic_surface(double* data, std::size_t n0, std::size_t n1, double period_x,
                                 double period_y, std::uint64_t seed,
                                 const std::function<double(double, double)>& amplitude) {
  const std::size_t half = n1 / 2 + 1;
  auto* spectrum = reinterpret_cast<fftw_complex*>(data);
  const FftwPlan plan([&] {
    return fftw_plan_dft_c2r_2d(static_cast<int>(n0), static_cast<int>(n1), spectrum, data, FFTW_ESTIMATE);
  });
  std::mt19937_64 engine(seed);
  for (std::size_t i = 0; i < n0; ++i) {
    const double signed_i = 2 * i <= n0 ? static_cast<double>(i) : static_cast<double>(i) - static_cast<double>(n0);
    const double nx = signed_i / period_x;
    for (std::size_t k = 0; k < half; ++k) {
      const auto [re, im] = portable::standard_normal_pair(engine);
      const double ny = static_cast<double>(k) / period_y;
      const double a = ((i == 0 && k == 0) || 2 * i == n0 || 2 * k == n1) ? 0.0 : amplitude(nx, ny);
      spectrum[i * half + k][0] = a * re;
      spectrum[i * half + k][1] = a * im;
    }
  }
  for (std::size_t i = 1; 2 * i < n0; ++i) {
    spectrum[(n0 - i) * half][0] = spectrum[i * half][0];
    spectrum[(n0 - i) * half][1] = -spectrum[i * half][1];
  }
  plan.execute();
}

}  // namespace rollnoise
