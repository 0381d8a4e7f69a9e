// Texture spectrum in third-octave bands (ISO 13473-4): the band set, a sine's level, and the
// level of a white profile against Parseval's theorem.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "road/portable_normal.hpp"
#include "road/texture_spectrum.hpp"

namespace rollnoise {
namespace {

constexpr double pi = std::numbers::pi;

TEST(TextureSpectrum, DefaultBandSetIsTheNominalThirdOctaveSeries) {
  const std::vector<double> expected_mm = {0.5, 0.63, 0.8, 1, 1.25, 1.6, 2, 2.5, 3.15, 4, 5, 6.3, 8,
                                           10, 12.5, 16, 20, 25, 31.5, 40, 50, 63, 80, 100, 125, 160,
                                           200, 250, 315, 400, 500};
  const auto bands = texture_band_nominal_wavelengths();
  ASSERT_EQ(bands.size(), expected_mm.size());
  for (std::size_t i = 0; i < bands.size(); ++i) {
    EXPECT_NEAR(bands[i], expected_mm[i] * 1e-3, 1e-12 * bands[i]) << i;
  }
  // Bounds given by exact centres include their bands too; a sub-range.
  const auto sub = texture_band_nominal_wavelengths(3.1623e-3, 10e-3);
  ASSERT_EQ(sub.size(), 6u);
  EXPECT_NEAR(sub.front(), 3.15e-3, 1e-15);
  EXPECT_NEAR(sub.back(), 10e-3, 1e-15);
  EXPECT_THROW(texture_band_nominal_wavelengths(10e-3, 1e-3), InputError);
  EXPECT_THROW(texture_band_nominal_wavelengths(0.0, 1e-3), InputError);
  EXPECT_THROW(texture_band_nominal_wavelengths(1e-300, 1e300), InputError);
}

TEST(TextureSpectrum, CentreWavelengthsAreBaseTenExact) {
  EXPECT_NEAR(texture_band_centre_wavelength(31.5e-3), 1e-3 * std::pow(10.0, 1.5), 1e-15);
  EXPECT_NEAR(texture_band_centre_wavelength(0.63e-3), 1e-3 * std::pow(10.0, -0.2), 1e-18);
  EXPECT_NEAR(texture_band_centre_wavelength(80e-3), 1e-3 * std::pow(10.0, 1.9), 1e-15);
  EXPECT_NEAR(texture_band_centre_wavelength(1e-3), 1e-3, 1e-18);
  EXPECT_THROW(texture_band_centre_wavelength(-1.0), InputError);
  EXPECT_THROW(texture_band_centre_wavelength(std::numeric_limits<double>::quiet_NaN()), InputError);
}

const TextureBand* band_at(const std::vector<TextureBand>& bands, double nominal) {
  for (const auto& b : bands)
    if (std::abs(b.nominal_wavelength_m - nominal) < 1e-3 * nominal) return &b;
  return nullptr;
}

TEST(TextureSpectrum, ASineLandsInItsBandAtItsRmsLevel) {
  // 1 m at 0.5 mm. The Hann window spreads a sine over its main lobe, ±2 bins (±2 cycles/m)
  // around it; the 10 mm band is 89.1 … 112.2 cycles/m wide, so wavelengths 9.5 … 10.5 mm keep
  // the lobe inside. With the window's power correction the band holds A²/2 (Parseval): the
  // level is 20 lg(A/√2 / 1 µm). What leaks beyond ±2 bins (Hann's side lobes fall as k^-3)
  // and the trend removal's share are < 1e-3 of the power: 0.1 dB is generous.
  const double spacing = 0.5e-3;
  const std::size_t n = 2000;
  for (double wavelength : {10e-3, 9.5e-3, 10.5e-3, 10.0137e-3}) {
    for (double phase : {0.0, 1.0, 2.5}) {
      const double amplitude = 0.3e-3;
      std::vector<double> z(n);
      for (std::size_t i = 0; i < n; ++i) z[i] = amplitude * std::sin(2 * pi * static_cast<double>(i) * spacing / wavelength + phase);
      const auto bands = texture_spectrum(z, spacing);
      const TextureBand* band = band_at(bands, 10e-3);
      ASSERT_NE(band, nullptr);
      const double expected = 20 * std::log10(amplitude / std::sqrt(2.0) / 1e-6);
      EXPECT_NEAR(band->level_db, expected, 0.1) << wavelength << " " << phase;
      EXPECT_NEAR(band->centre_wavelength_m, 10e-3, 1e-15);
      // Neighbouring bands see only the window's side lobes.
      EXPECT_LT(band_at(bands, 8e-3)->level_db, expected - 30) << wavelength;
      EXPECT_LT(band_at(bands, 12.5e-3)->level_db, expected - 30) << wavelength;
    }
  }
}

TEST(TextureSpectrum, BandsResolvedAreBetweenTwiceTheSpacingAndAFractionOfTheLength) {
  // 1 m at 0.5 mm: shortest band edge >= 1 mm (the 1.25 mm band, edge 1.12 mm; the 1 mm band's
  // edge 0.89 mm is out), longest edge <= 1 m / 12 = 83 mm (the 63 mm band, edge 70.8 mm; the
  // 80 mm band's edge 89 mm is out).
  std::vector<double> z(2000);
  for (std::size_t i = 0; i < z.size(); ++i) z[i] = 1e-4 * std::sin(0.37 * static_cast<double>(i * i % 1000));
  const auto bands = texture_spectrum(z, 0.5e-3);
  ASSERT_FALSE(bands.empty());
  EXPECT_NEAR(bands.front().nominal_wavelength_m, 1.25e-3, 1e-12);
  EXPECT_NEAR(bands.back().nominal_wavelength_m, 63e-3, 1e-12);
}

TEST(TextureSpectrum, WhiteProfileGivesTheLevelParsevalPredicts) {
  // White noise of variance σ² at spacing Δ has the one-sided PSD 2σ²Δ (m²/(cycles/m)), so a
  // band [f_lo, f_hi) holds a_rms² = 2σ²Δ(f_hi - f_lo). The estimate of a band of m DFT bins,
  // Hann-windowed, scatters with relative standard deviation sqrt(1.94/m) (neighbouring bins
  // are correlated: |ρ|² = 4/9 at one bin, 1/36 at two, so the variance is m(1 + 8/9 + 1/18));
  // averaged over S profiles, sqrt(1.94/(m S)). The bin count differs from L(f_hi - f_lo) by
  // up to one bin. Tolerance: 4 standard deviations + 1/m, for bands of m >= 8 bins.
  const double spacing = 0.5e-3;
  const std::size_t n = 1 << 15;  // 16.4 m
  const double sigma = 0.2e-3;
  const int seeds = 16;
  std::vector<double> mean_square;
  std::vector<TextureBand> last;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(1000 + static_cast<unsigned>(seed));
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; i += 2) {
      const auto [a, b] = portable::standard_normal_pair(rng);
      z[i] = sigma * a;
      z[i + 1] = sigma * b;
    }
    last = texture_spectrum(z, spacing);
    if (mean_square.empty()) mean_square.assign(last.size(), 0.0);
    for (std::size_t b = 0; b < last.size(); ++b) mean_square[b] += std::pow(10.0, last[b].level_db / 10) * 1e-12 / seeds;
  }
  const double length = static_cast<double>(n) * spacing;
  int tested = 0;
  for (std::size_t b = 0; b < last.size(); ++b) {
    const double f_hi = 1.0 / (last[b].centre_wavelength_m / std::pow(10.0, 0.05));
    const double f_lo = 1.0 / (last[b].centre_wavelength_m * std::pow(10.0, 0.05));
    const double bins = length * (f_hi - f_lo);
    if (bins < 8) continue;
    const double expected = 2 * sigma * sigma * spacing * (f_hi - f_lo);
    const double tolerance = 4 * std::sqrt(1.94 / (bins * seeds)) + 1 / bins;
    EXPECT_NEAR(mean_square[b] / expected, 1.0, tolerance) << last[b].nominal_wavelength_m;
    ++tested;
  }
  EXPECT_GE(tested, 15);
}

TEST(TextureSpectrum, BadInputIsAnInputError) {
  auto key_of = [](std::vector<double> z, double spacing) -> std::string {
    try {
      texture_spectrum(z, spacing);
    } catch (const InputError& e) {
      return e.key();
    }
    return "no error";
  };
  EXPECT_EQ(key_of(std::vector<double>(100, 0.0), 0.0), "spacing");
  EXPECT_EQ(key_of(std::vector<double>(100, 0.0), std::numeric_limits<double>::infinity()), "spacing");
  EXPECT_EQ(key_of({0.0, 1.0}, 1e-3), "profile");
  std::vector<double> with_nan(100, 0.0);
  with_nan[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(key_of(with_nan, 1e-3), "profile");
  // Too short for any band: an empty spectrum, not an error.
  EXPECT_TRUE(texture_spectrum(std::vector<double>(8, 0.0), 1e-3).empty());
}

}  // namespace
}  // namespace rollnoise
