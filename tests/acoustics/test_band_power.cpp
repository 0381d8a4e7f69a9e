// Band powers of the energy budget (acoustics/band_power.hpp): Parseval over the band range for
// a broadband signal, the per-point average against welch_psd of whole records, band sums of
// per-bin values.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <fftw3.h>
#include <gtest/gtest.h>

#include "acoustics/band_power.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

// Σ over the bands of the band mean squares of a broadband (white) signal equals the variance
// of the signal within the range [lower edge of the first band, upper edge of the last], which
// the record's own DFT gives exactly (one-sided: 2|X_k|²/N² per bin inside the range).
TEST(BandPower, SumOfBandPowersIsTheVarianceWithinTheBandRange) {
  const double fs = 5730.0;  // the contact steps at 80 km/h on a 512-point tyre
  const std::size_t n = 1 << 16;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(3200.0, 50.0);  // a force: a mean and a fluctuation
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  const std::vector<FractionalOctaveBand> bands = fractional_octave_bands(3, 100.0, 2500.0);
  const std::vector<double> ms = fluctuation_band_mean_squares(x, fs, bands, 1024);
  double sum = 0.0;
  for (double m : ms) sum += m;

  // The variance of the record within the band range, exactly: its DFT (FFTW), one-sided.
  double mean = 0.0;
  for (double v : x) mean += v / static_cast<double>(n);
  std::vector<double> centred(n);
  for (std::size_t t = 0; t < n; ++t) centred[t] = x[t] - mean;
  std::vector<fftw_complex> spectrum(n / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), centred.data(), spectrum.data(), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  const double lo = bands.front().lower, hi = bands.back().upper;
  double expected = 0.0;
  for (std::size_t k = 1; k < n / 2; ++k) {
    const double f = fs * static_cast<double>(k) / static_cast<double>(n);
    if (f >= lo && f < hi)
      expected += 2.0 * (spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1]) /
                  (static_cast<double>(n) * static_cast<double>(n));
  }
  // The two differ by (a) the Hann main lobe at the two outer edges of the range (±2 bins of
  // 5.6 Hz, against a range of 2.7 kHz: for a flat spectrum what leaks out is matched by what
  // leaks in, so ≪ 0.3 %), and (b) the Hann weighting of the segments against the plain record
  // (the same data weighted differently: a random difference ≈ 1/√(bins·segments) ≈ 0.3 %).
  // Tolerance 1 %.
  EXPECT_NEAR(sum, expected, 0.01 * expected);
  std::printf("Parseval: sum of bands %.6g, variance in range %.6g, relative error %.2e\n", sum, expected,
              sum / expected - 1.0);
}

TEST(BandPower, PointAverageEqualsTheWeightedMeanOfWelchPsds) {
  const double fs = 1000.0;
  const std::size_t n = 700, points = 3, segment = 128;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<std::vector<double>> signal(points, std::vector<double>(n));
  for (std::size_t p = 0; p < points; ++p)
    for (std::size_t t = 0; t < n; ++t) signal[p][t] = normal(rng) * static_cast<double>(p + 1);
  PointAveragedPsd average(points, fs, segment, {{1.0, 1.0, 2.0}, {0.0, 1.0, 0.0}});
  std::vector<double> sample(points);
  for (std::size_t t = 0; t < n; ++t) {
    for (std::size_t p = 0; p < points; ++p) sample[p] = signal[p][t];
    average.push(sample);
  }
  std::vector<PowerSpectralDensity> each;
  for (std::size_t p = 0; p < points; ++p) each.push_back(welch_psd(signal[p], fs, segment));
  EXPECT_EQ(average.segments(), each[0].segments);
  const PowerSpectralDensity a = average.average(0), b = average.average(1);
  for (std::size_t k = 0; k < a.density.size(); ++k) {
    const double expected = 0.25 * each[0].density[k] + 0.25 * each[1].density[k] + 0.5 * each[2].density[k];
    // The buffer holds single precision: 6e-8 relative per sample.
    EXPECT_NEAR(a.density[k], expected, 1e-6 * expected + 1e-12) << k;
    EXPECT_NEAR(b.density[k], each[1].density[k], 1e-6 * each[1].density[k] + 1e-12) << k;
  }
}

// push() reuses one window and one FFT plan (issue 12: a plan per point and segment was most of
// a tyre run's response stage). The sums must equal, bit for bit, what welch_psd gives for each
// buffered (single-precision) segment, weighted and added in the same order.
TEST(BandPower, PointAverageIsBitForBitTheSegmentsWelchPsds) {
  const double fs = 11700.0;
  const std::size_t n = 900, points = 5, segment = 256;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<std::vector<double>> signal(points, std::vector<double>(n));
  for (std::size_t p = 0; p < points; ++p)
    for (std::size_t t = 0; t < n; ++t) signal[p][t] = 1e-3 * normal(rng) * static_cast<double>(p + 1);
  const std::vector<std::vector<double>> weights{{1.0, 0.0, 3.0, 2.0, 0.5}, {0.0, 1.0, 0.0, 0.0, 0.0}};
  PointAveragedPsd average(points, fs, segment, weights);
  std::vector<double> sample(points);
  for (std::size_t t = 0; t < n; ++t) {
    for (std::size_t p = 0; p < points; ++p) sample[p] = signal[p][t];
    average.push(sample);
  }
  // The reference: welch_psd of each segment as the buffer holds it (floats), as push() used to.
  std::vector<std::vector<double>> sums(weights.size(), std::vector<double>(segment / 2 + 1, 0.0));
  std::size_t segments = 0;
  for (std::size_t start = 0; start + segment <= n; start += segment / 2, ++segments) {
    for (std::size_t p = 0; p < points; ++p) {
      std::vector<double> x(segment);
      for (std::size_t i = 0; i < segment; ++i) x[i] = static_cast<double>(static_cast<float>(signal[p][start + i]));
      const PowerSpectralDensity psd = welch_psd(x, fs, segment);
      for (std::size_t a = 0; a < weights.size(); ++a) {
        const double total = weights[a][0] + weights[a][1] + weights[a][2] + weights[a][3] + weights[a][4];
        const double w = weights[a][p] / total;
        if (w == 0.0) continue;
        for (std::size_t k = 0; k < psd.density.size(); ++k) sums[a][k] += w * psd.density[k];
      }
    }
  }
  ASSERT_EQ(average.segments(), segments);
  for (std::size_t a = 0; a < weights.size(); ++a) {
    const PowerSpectralDensity got = average.average(a);
    for (std::size_t k = 0; k < got.density.size(); ++k)
      EXPECT_EQ(got.density[k], sums[a][k] / static_cast<double>(segments)) << a << ' ' << k;
  }
}

TEST(BandPower, BandSumsTakeTheBinsInsideTheEdges) {
  const std::vector<FractionalOctaveBand> bands = fractional_octave_bands(3, 1000.0, 1250.0);
  // 1000 Hz band: [891.3, 1122.0); 1250 Hz band: [1122.0, 1412.5)
  const std::vector<double> f{890.0, 900.0, 1000.0, 1121.0, 1123.0, 1400.0, 1500.0};
  const std::vector<double> v{1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0};
  const std::vector<double> s = band_sums(f, v, bands);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], 14.0);
  EXPECT_EQ(s[1], 48.0);
}

TEST(BandPower, SegmentForShortAndLongRecords) {
  EXPECT_EQ(welch_segment_for(1146), 1024u);
  EXPECT_EQ(welch_segment_for(5730), 1024u);
  EXPECT_EQ(welch_segment_for(115), 64u);
  EXPECT_EQ(welch_segment_for(8), 8u);
  EXPECT_THROW(welch_segment_for(7), InputError);
}

}  // namespace
}  // namespace rollnoise
