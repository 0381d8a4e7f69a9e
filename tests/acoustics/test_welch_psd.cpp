// The Welch PSD: its scaling by Parseval (exactly, and against the plain mean square within the
// statistical tolerance the window implies), white-noise level, and a sine's line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "acoustics/welch_psd.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

// Seeded Gaussian white noise (Box-Muller on mt19937_64, whose output the standard fixes).
std::vector<double> white_noise(std::size_t n, double sigma, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; i += 2) {
    const double u1 = (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine() >> 11) * 0x1.0p-53;
    const double r = sigma * std::sqrt(-2.0 * std::log(u1));
    x[i] = r * std::cos(2.0 * std::numbers::pi * u2);
    if (i + 1 < n) x[i + 1] = r * std::sin(2.0 * std::numbers::pi * u2);
  }
  return x;
}

double hann(std::size_t i, std::size_t n) {
  return 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n)));
}

// Parseval, exactly: Σ P Δf is the segments' mean of Σ(w x)²/Σw².
TEST(WelchPsd, ParsevalIdentityHoldsToRounding) {
  const std::vector<double> x = white_noise(50000, 0.3, 11);
  const std::size_t n = 1024;
  const PowerSpectralDensity psd = welch_psd(x, 25600.0, n);
  const std::size_t hop = n / 2;
  ASSERT_EQ(psd.segments, 1 + (x.size() - n) / hop);
  ASSERT_EQ(psd.density.size(), n / 2 + 1);
  double expected = 0.0;
  double window_power = 0.0;
  for (std::size_t i = 0; i < n; ++i) window_power += hann(i, n) * hann(i, n);
  for (std::size_t m = 0; m < psd.segments; ++m) {
    for (std::size_t i = 0; i < n; ++i) {
      const double v = hann(i, n) * x[m * hop + i];
      expected += v * v;
    }
  }
  expected /= window_power * static_cast<double>(psd.segments);
  EXPECT_NEAR(total_power(psd), expected, 1e-12 * expected);
  EXPECT_NEAR(integrate_psd(psd, -INFINITY, INFINITY), expected, 1e-12 * expected);
  EXPECT_DOUBLE_EQ(psd.resolution(), 25.0);
  EXPECT_DOUBLE_EQ(psd.equivalent_noise_bandwidth(), 37.5);
}

// Against the plain mean square of the record. Σ P Δf = Σ_n c_n x_n² with weights
// c_n = Σ_m w²[n − m N/2] / (K Σ w²) (Σ c_n = 1), the mean square Σ x_n²/L: for Gaussian white
// noise of variance σ² their difference has mean 0 and standard deviation
// σ² √(2 Σ (c_n − 1/L)²). The tolerance is 5 of those, computed for this configuration.
TEST(WelchPsd, IntegralEqualsTheMeanSquareWithinTheWindowsStatisticalTolerance) {
  const std::size_t length = std::size_t{1} << 20;
  const std::size_t n = 4096;
  const double sigma = 0.5;
  const std::vector<double> x = white_noise(length, sigma, 2024);
  const PowerSpectralDensity psd = welch_psd(x, 48000.0, n);

  // The weights c_n.
  std::vector<double> c(length, 0.0);
  double window_power = 0.0;
  for (std::size_t i = 0; i < n; ++i) window_power += hann(i, n) * hann(i, n);
  for (std::size_t m = 0; m < psd.segments; ++m) {
    for (std::size_t i = 0; i < n; ++i) c[m * n / 2 + i] += hann(i, n) * hann(i, n);
  }
  double spread = 0.0;
  double ms = 0.0;
  for (std::size_t k = 0; k < length; ++k) {
    c[k] /= window_power * static_cast<double>(psd.segments);
    const double d = c[k] - 1.0 / static_cast<double>(length);
    spread += d * d;
    ms += x[k] * x[k];
  }
  ms /= static_cast<double>(length);
  const double relative_sigma = std::sqrt(2.0 * spread);  // of the difference, relative to σ²
  const double relative_error = (total_power(psd) - ms) / (sigma * sigma);
  std::printf("[measured] Welch Parseval, white noise 2^20 samples, N = 4096: (integral - mean square)/sigma^2 = "
              "%+.2e (1 sigma = %.2e; %+.4f dB)\n",
              relative_error, relative_sigma, 10.0 * std::log10(total_power(psd) / ms));
  EXPECT_LT(std::abs(relative_error), 5.0 * relative_sigma);

  // White noise: flat density σ²/(fs/2), each bin within the χ² spread of 2K degrees of freedom
  // on average; the mean over the interior bins to 1 %.
  double mean_density = 0.0;
  for (std::size_t k = 1; k + 1 < psd.density.size(); ++k) mean_density += psd.density[k];
  mean_density /= static_cast<double>(psd.density.size() - 2);
  EXPECT_NEAR(mean_density, sigma * sigma / 24000.0, 0.01 * sigma * sigma / 24000.0);
}

// A sine of amplitude a puts a²/2 into its line: exactly for a frequency on a bin (the window's
// w² and the sine's cos(2ωn) are orthogonal over a segment), and within 1e-4 when off a bin,
// summing ±6 bins (the Hann main lobe is ±2 bins; its side lobes beyond 6 bins hold < 1e-5 of the
// power).
TEST(WelchPsd, SinePeakIntegratesToItsMeanSquare) {
  const double fs = 48000.0;
  const std::size_t n = 8192;
  const double df = fs / static_cast<double>(n);
  const double a = 1.7;
  for (double bins : {200.0, 200.37, 850.5}) {
    const double f = bins * df;
    std::vector<double> x(200000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = a * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / fs + 0.3);
    const PowerSpectralDensity psd = welch_psd(x, fs, n);
    const double line = integrate_psd(psd, f - 6.5 * df, f + 6.5 * df);
    const double tolerance = bins == std::round(bins) ? 1e-12 : 1e-4;
    EXPECT_NEAR(line / (a * a / 2.0), 1.0, tolerance) << bins << " bins";
    std::printf("[measured] sine at %.2f bins: line integral / (a^2/2) - 1 = %+.2e; whole PSD: %+.2e\n", bins,
                line / (a * a / 2.0) - 1.0, total_power(psd) / (a * a / 2.0) - 1.0);
  }
}

TEST(WelchPsd, IntegrationCountsPartialBins) {
  PowerSpectralDensity psd;
  psd.sample_rate = 100.0;
  psd.segment_length = 10;  // 10 Hz bins
  psd.segments = 1;
  psd.density = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};  // k = 0..5
  // [12, 27]: bin 1 ([5, 15]) 3 Hz of it, bin 2 ([15, 25]) whole, bin 3 ([25, 35]) 2 Hz.
  EXPECT_NEAR(integrate_psd(psd, 12.0, 27.0), 2.0 * 3.0 + 3.0 * 10.0 + 4.0 * 2.0, 1e-12);
  EXPECT_NEAR(total_power(psd), 210.0, 1e-12);
  EXPECT_DOUBLE_EQ(psd.frequency(3), 30.0);
}

TEST(WelchPsd, RejectsBadArguments) {
  const std::vector<double> x(1000, 0.0);
  EXPECT_THROW(welch_psd(x, 48000.0, 1001), InputError);
  EXPECT_THROW(welch_psd(x, 48000.0, 255), InputError);
  EXPECT_THROW(welch_psd(x, 48000.0, 4), InputError);
  EXPECT_THROW(welch_psd(x, 0.0, 256), InputError);
  EXPECT_THROW(welch_psd(x, NAN, 256), InputError);
  try {
    welch_psd(x, 48000.0, 2000);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "segment_length");
  }
  const PowerSpectralDensity psd = welch_psd(x, 48000.0, 1000);
  EXPECT_EQ(psd.segments, 1u);
}

}  // namespace
}  // namespace rollnoise
