#include "road/texture_spectrum.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <string>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/least_squares_line.hpp"

namespace rollnoise {
namespace {

// Nominal centres of one decade (ISO 266 / ISO 13473-4 third-octave series), times 10^m mm.
constexpr std::array<double, 10> decade = {1.0, 1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0};
// Half a third-octave band in base-10 steps: band edges are centre · 10^(±1/20).
const double half_band = std::pow(10.0, 1.0 / 20.0);
// The nominal values differ from the exact ones by at most 1.3 % (3.15 vs 3.162): a bound
// this close to a band's centre includes the band. Neighbouring bands are 26 % apart.
constexpr double bound_slack = 1.02;

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

void check_wavelength(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError("", "wavelength",
                     std::string(what) + " must be a finite wavelength > 0 m (is " + format_number(value) + ")");
  }
}

// Band number k: exact centre 1 mm · 10^(k/10).
long band_index(double wavelength_m) { return std::lround(10.0 * std::log10(wavelength_m / 1e-3)); }
double exact_centre(long k) { return 1e-3 * std::pow(10.0, static_cast<double>(k) / 10.0); }
double nominal_centre(long k) {
  const long decade_index = k >= 0 ? k / 10 : -((-k + 9) / 10);  // floor(k / 10)
  const long step = k - 10 * decade_index;
  return 1e-3 * decade[static_cast<std::size_t>(step)] * std::pow(10.0, static_cast<double>(decade_index));
}

}  // namespace

std::vector<double> texture_band_nominal_wavelengths(double shortest_m, double longest_m) {
  check_wavelength(shortest_m, "the shortest band");
  check_wavelength(longest_m, "the longest band");
  if (!(shortest_m <= longest_m)) {
    throw InputError("", "wavelength", "the shortest band (" + format_number(shortest_m) +
                                           " m) must not be longer than the longest (" +
                                           format_number(longest_m) + " m)");
  }
  const double first = std::ceil(10.0 * std::log10(shortest_m / bound_slack / 1e-3));
  const double last = std::floor(10.0 * std::log10(longest_m * bound_slack / 1e-3));
  if (last - first > 400) {  // 40 decades: no texture question needs more
    throw InputError("", "wavelength", "the band set from " + format_number(shortest_m) + " to " +
                                           format_number(longest_m) + " m has too many bands");
  }
  std::vector<double> bands;
  for (auto k = static_cast<long>(first); k <= static_cast<long>(last); ++k) bands.push_back(nominal_centre(k));
  return bands;
}

double texture_band_centre_wavelength(double nominal_m) {
  check_wavelength(nominal_m, "the nominal band centre");
  return exact_centre(band_index(nominal_m));
}

std::vector<TextureBand> texture_spectrum(std::span<const double> z, double spacing_m) {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0)) {
    throw InputError("", "spacing", "the sample spacing must be a finite number > 0 m (is " +
                                        format_number(spacing_m) + ")");
  }
  const std::size_t n = z.size();
  if (n < 4) throw InputError("", "profile", "a texture spectrum needs at least 4 samples");
  if (n > (std::size_t{1} << 28)) throw InputError("", "profile", "more than 2^28 samples: too long for one DFT");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(z[i])) {
      throw InputError("", "profile",
                       "sample " + std::to_string(i) + " is not a finite height; clean the profile first");
    }
  }
  const double length = static_cast<double>(n) * spacing_m;

  // Detrend (least-squares line) and window (periodic Hann, mean(w²) = 3/8).
  const double nd = static_cast<double>(n);
  const LeastSquaresLine trend = least_squares_line(z);
  std::unique_ptr<double[], FftwFree> x(fftw_alloc_real(n));
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  if (!x || !spectrum) throw std::bad_alloc();
  const FftwPlan plan([&] {
    return fftw_plan_dft_r2c_1d(static_cast<int>(n), x.get(), spectrum.get(), FFTW_ESTIMATE);
  });
  double window_power = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / nd));
    window_power += w * w;
    x[i] = w * (z[i] - trend.at(i));
  }
  window_power /= nd;
  plan.execute();
  // One-sided mean square per bin: 2|X_k|² / (N² mean(w²)), the Nyquist bin once.
  auto bin_power = [&](std::size_t k) {
    const double re = spectrum[k][0];
    const double im = spectrum[k][1];
    const double two_sided = (re * re + im * im) / (nd * nd * window_power);
    return (2 * k == n) ? two_sided : 2.0 * two_sided;
  };

  std::vector<TextureBand> bands;
  const double a_ref = 1e-6;
  for (double nominal : texture_band_nominal_wavelengths()) {
    const double centre = texture_band_centre_wavelength(nominal);
    const double shortest = centre / half_band;
    const double longest = centre * half_band;
    if (shortest < 2.0 * spacing_m || longest > length / texture_band_length_factor) continue;
    // Bins k with 1/longest <= k/L < 1/shortest.
    const auto k_first = static_cast<std::size_t>(std::ceil(length / longest));
    const auto k_end = std::min(static_cast<std::size_t>(std::ceil(length / shortest)), n / 2 + 1);
    double mean_square = 0.0;
    for (std::size_t k = k_first; k < k_end; ++k) mean_square += bin_power(k);
    bands.push_back({nominal, centre, 10.0 * std::log10(mean_square / (a_ref * a_ref))});
  }
  return bands;
}

}  // namespace rollnoise
