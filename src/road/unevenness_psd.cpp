#include "road/unevenness_psd.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

constexpr std::size_t min_segment = 64;
constexpr std::size_t first_fit_bin = 3;

}  // namespace

double iso8608_class_gd_n0(char cls) {
  if (cls < 'A' || cls > 'H') {
    throw InputError("", "class", std::string("ISO 8608 classes are A to H (is '") + cls + "')");
  }
  return 16e-6 * std::pow(4.0, static_cast<double>(cls - 'A'));
}

std::string iso8608_class_of(double gd_n0) {
  if (!(std::isfinite(gd_n0) && gd_n0 > 0.0)) {
    throw InputError("", "gd_n0", "G_d(n0) must be a finite number > 0 m³ (is " + format_number(gd_n0) + ")");
  }
  // Upper limit of class c is 2·gm(c) = 32e-6 · 4^c.
  char cls = 'A';
  while (cls < 'H' && gd_n0 >= 2.0 * iso8608_class_gd_n0(cls)) ++cls;
  return std::string(1, cls);
}

UnevennessPsd unevenness_psd(std::span<const double> z, double spacing_m) {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0)) {
    throw InputError("", "spacing", "the sample spacing must be a finite number > 0 m (is " +
                                        format_number(spacing_m) + ")");
  }
  const std::size_t n = z.size();
  if (n > (std::size_t{1} << 28)) throw InputError("", "profile", "more than 2^28 samples");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(z[i])) {
      throw InputError("", "profile",
                       "sample " + std::to_string(i) + " is not a finite height; clean the profile first");
    }
  }
  std::size_t ls = 1;
  while (2 * ls <= n / 4) ls *= 2;
  if (ls < min_segment) ls = n;
  if (ls < 2 * first_fit_bin + 2) throw InputError("", "profile", "too few samples for a PSD");
  const double lsd = static_cast<double>(ls);

  std::unique_ptr<double[], FftwFree> x(fftw_alloc_real(ls));
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(ls / 2 + 1));
  if (!x || !spectrum) throw std::bad_alloc();
  const FftwPlan plan([&] {
    return fftw_plan_dft_r2c_1d(static_cast<int>(ls), x.get(), spectrum.get(), FFTW_ESTIMATE);
  });
  std::vector<double> window(ls);
  double window_power = 0.0;
  for (std::size_t i = 0; i < ls; ++i) {
    window[i] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / lsd));
    window_power += window[i] * window[i];
  }
  window_power /= lsd;

  UnevennessPsd result;
  result.gd.assign(ls / 2, 0.0);
  result.n.resize(ls / 2);
  for (std::size_t k = 1; k <= ls / 2; ++k) result.n[k - 1] = static_cast<double>(k) / (lsd * spacing_m);
  const std::size_t hop = std::max<std::size_t>(ls / 2, 1);
  std::size_t count = 0;
  const double t_mean = (lsd - 1.0) / 2.0;
  for (std::size_t start = 0; start + ls <= n; start += hop) {
    double z_mean = 0.0;
    for (std::size_t i = 0; i < ls; ++i) z_mean += z[start + i];
    z_mean /= lsd;
    double stt = 0.0, stz = 0.0;
    for (std::size_t i = 0; i < ls; ++i) {
      const double t = static_cast<double>(i) - t_mean;
      stt += t * t;
      stz += t * (z[start + i] - z_mean);
    }
    const double slope = stz / stt;
    for (std::size_t i = 0; i < ls; ++i) {
      x[i] = window[i] * (z[start + i] - z_mean - slope * (static_cast<double>(i) - t_mean));
    }
    plan.execute();
    for (std::size_t k = 1; k <= ls / 2; ++k) {
      const double p = spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1];
      const double one_sided = (2 * k == ls) ? 1.0 : 2.0;
      result.gd[k - 1] += one_sided * p * spacing_m / (lsd * window_power);
    }
    ++count;
  }
  for (double& g : result.gd) g /= static_cast<double>(count);

  // Fit G_d(n0) with w = 2 over the standard's band, third-octave bands of equal weight.
  const double n_low = std::max(iso8608_n_min, static_cast<double>(first_fit_bin) / (lsd * spacing_m));
  const double n_high = std::min(iso8608_n_max, 0.25 / spacing_m);
  const double third = std::pow(10.0, 0.1);
  double band_sum = 0.0;
  std::size_t bands = 0;
  for (double lo = iso8608_n_min; lo < n_high; lo *= third) {
    const double hi = lo * third;
    double sum = 0.0;
    std::size_t bins = 0;
    for (std::size_t k = 0; k < result.n.size(); ++k) {
      const double f = result.n[k];
      if (f >= lo && f < hi && f >= n_low && f <= n_high) {
        sum += result.gd[k] * std::pow(f / iso8608_n0, result.waviness);
        ++bins;
      }
    }
    if (bins > 0) {
      band_sum += sum / static_cast<double>(bins);
      ++bands;
    }
  }
  if (bands == 0) {
    throw InputError("", "profile",
                     "the profile (" + format_number(static_cast<double>(n) * spacing_m) + " m at " +
                         format_number(spacing_m) + " m) resolves no spatial frequency of ISO 8608's band "
                         "0.011 to 2.83 cycles/m");
  }
  result.gd_n0 = band_sum / static_cast<double>(bands);
  result.iso8608_class = result.gd_n0 > 0.0 ? iso8608_class_of(result.gd_n0) : "A";
  return result;
}

}  // namespace rollnoise
