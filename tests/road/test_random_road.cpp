// RandomRoad against the statistics it is specified to have: the target standard deviation,
// the Gaussian autocorrelation, a zero mean, the band limit, the lead-in, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fftw3.h>

#include "core/error.hpp"
#include "road/random_road.hpp"

namespace rollnoise {
namespace {

RandomRoadSpec gaussian_spec(double lc, double x_max, std::uint64_t seed) {
  RandomRoadSpec spec;
  spec.std_dev = 1e-3;
  spec.spectrum = RandomRoadSpec::Spectrum::gaussian;
  spec.correlation_length = lc;
  spec.x_max = x_max;
  spec.seed = seed;
  return spec;
}

// Heights at the grid points j * spacing, j = 0 .. count-1, read through height() only.
std::vector<double> grid_heights(const RandomRoad& road, std::size_t count) {
  std::vector<double> r(count);
  for (std::size_t j = 0; j < count; ++j) r[j] = road.height(road.spacing() * static_cast<double>(j));
  return r;
}

double mean_of(const std::vector<double>& r) {
  double sum = 0.0;
  for (double v : r) sum += v;
  return sum / static_cast<double>(r.size());
}

// Normalised sample autocorrelation at a lag of `lag` samples (mean removed).
double autocorrelation(const std::vector<double>& r, std::size_t lag) {
  const double m = mean_of(r);
  double c0 = 0.0;
  double ck = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) c0 += (r[i] - m) * (r[i] - m);
  for (std::size_t i = 0; i + lag < r.size(); ++i) ck += (r[i] - m) * (r[i + lag] - m);
  c0 /= static_cast<double>(r.size());
  ck /= static_cast<double>(r.size() - lag);
  return ck / c0;
}

TEST(RandomRoad, SameSeedGivesIdenticalProfileOtherSeedDiffers) {
  const RandomRoad a(gaussian_spec(0.1, 20.0, 7));
  const RandomRoad b(gaussian_spec(0.1, 20.0, 7));
  const RandomRoad c(gaussian_spec(0.1, 20.0, 8));
  EXPECT_EQ(a.type(), "random");
  double max_diff = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double x = 0.001 * i;
    ASSERT_EQ(a.height(x), b.height(x)) << "x = " << x;  // bitwise: same computation
    max_diff = std::max(max_diff, std::abs(a.height(x) - c.height(x)));
  }
  // Two independent roads of std 1 mm differ by several mm somewhere over 200 lc.
  EXPECT_GT(max_diff, 1e-3);
}

// Pins the generator (mt19937_64 + our Box-Muller + FFTW) so that a change of the road a seed
// describes does not go unnoticed. Not a correctness check: the values were recorded from this
// implementation. The tolerance allows for libm and FFTW rounding differences across platforms.
TEST(RandomRoad, RecordedValuesForSeedOne) {
  RandomRoadSpec spec = gaussian_spec(0.5, 10.0, 1);
  spec.lead_in = 0.0;
  const RandomRoad road(spec);
  EXPECT_EQ(road.grid_size(), 512u);  // period max(10 + 5 lc, 32 lc) = 16 m at lc/16
  const double expected[] = {0.00093318961901180217, -0.00047879379637177379, -0.00088692655374313903};
  const double xs[] = {0.0, 3.3, 9.99};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(road.height(xs[i]), expected[i], 1e-12) << xs[i];
}

TEST(RandomRoad, SampleStdEqualsStdDevByConstruction) {
  // lc = 1, spacing 1/16 and x_max = 2000 are exact binary numbers, so the grid points covering
  // [0, x_max] are exactly j / 16, j = 0 .. 32000.
  RandomRoadSpec spec = gaussian_spec(1.0, 2000.0, 3);
  spec.std_dev = 2.5e-3;
  spec.lead_in = 0.0;  // the window is applied after the scaling; see the LeadIn test
  const RandomRoad road(spec);
  ASSERT_EQ(road.spacing(), 1.0 / 16.0);
  const auto r = grid_heights(road, 32001);
  const double m = mean_of(r);
  double sum_sq = 0.0;
  for (double v : r) sum_sq += (v - m) * (v - m);
  const double std = std::sqrt(sum_sq / static_cast<double>(r.size()));
  // Only summation rounding separates the two: ~1e-16 * sqrt(n) relative.
  std::printf("  sample std / std_dev - 1 = %.3g\n", std / spec.std_dev - 1.0);
  EXPECT_NEAR(std / spec.std_dev, 1.0, 1e-12);
}

TEST(RandomRoad, GaussianAutocorrelationAndZeroMean) {
  // T = 20000 correlation lengths sampled at lc/16 = 320001 points.
  const double lc = 0.5;
  const double length = 20000.0 * lc;
  const double t_over_lc = length / lc;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    RandomRoadSpec spec = gaussian_spec(lc, length, seed);
    spec.lead_in = 0.0;
    const RandomRoad road(spec);
    const auto r = grid_heights(road, 320001);

    // Sampling error of the normalised autocorrelation rho(xi) over a record of length T
    // (Bartlett's formula, continuous form) for rho(s) = exp(-(s/lc)^2):
    //   var = (lc/T) sqrt(pi/2) [1 + 3 exp(-2 q^2) - 4 exp(-1.5 q^2)],   q = xi/lc,
    // giving standard deviations 0.0021, 0.0057, 0.0079 at q = 0.5, 1, 2. The tolerance is five
    // of them (a false failure has probability < 1e-6 per lag). The tolerance of 0.05 suggested
    // for 2000 lc would have been only 1.5 to 8 sigma there, hence the longer record. Bias from
    // the discrete, periodic synthesis (wrap margin 5 lc: e^-25) and from removing the sample
    // mean (~lc/T = 5e-5) is far below this.
    for (double q : {0.5, 1.0, 2.0}) {
      const auto lag = static_cast<std::size_t>(std::lround(q * lc / road.spacing()));
      const double rho = autocorrelation(r, lag);
      const double expected = std::exp(-q * q);
      const double var = std::sqrt(std::numbers::pi / 2.0) / t_over_lc *
                         (1.0 + 3.0 * std::exp(-2.0 * q * q) - 4.0 * std::exp(-1.5 * q * q));
      const double tolerance = 5.0 * std::sqrt(var);
      std::printf("  seed %llu, lag %.1f lc: rho = %.5f, expected %.5f, error %+.5f (tolerance %.4f)\n",
                  static_cast<unsigned long long>(seed), q, rho, expected, rho - expected, tolerance);
      EXPECT_NEAR(rho, expected, tolerance) << "seed " << seed << ", lag " << q << " lc";
    }

    // The mean over T has variance sigma^2 (1/T) integral rho = sigma^2 sqrt(pi) lc / T,
    // i.e. a standard deviation of 0.0094 sigma here; five of them.
    const double mean_sd = spec.std_dev * std::sqrt(std::sqrt(std::numbers::pi) / t_over_lc);
    const double m = mean_of(r);
    std::printf("  seed %llu: mean = %+.4f sigma (tolerance %.4f sigma)\n",
                static_cast<unsigned long long>(seed), m / spec.std_dev, 5.0 * mean_sd / spec.std_dev);
    EXPECT_NEAR(m, 0.0, 5.0 * mean_sd) << "seed " << seed;
  }
}

TEST(RandomRoad, BandLimitedSpectrumStaysInBandAndIsFlat) {
  // Band 2 .. 20 cycles/m (wavelengths 0.5 .. 0.05 m) over 2000 m sampled every 2^-9 m.
  RandomRoadSpec spec;
  spec.std_dev = 1e-3;
  spec.spectrum = RandomRoadSpec::Spectrum::band;
  spec.min_wavelength = 0.05;
  spec.max_wavelength = 0.5;
  spec.sample_spacing = 1.0 / 512.0;
  spec.lead_in = 0.0;  // the lead-in window would itself spread the spectrum
  spec.x_max = 2000.0;
  spec.seed = 11;
  const RandomRoad road(spec);
  const std::size_t n = 1024000;  // 2000 m / 2^-9
  const auto r = grid_heights(road, n);

  // Our own periodogram: Hann window (sidelobes fall as the 6th power of the distance in
  // bins), real-to-complex FFT.
  double* in = fftw_alloc_real(n);
  fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(static_cast<int>(n), in, out, FFTW_ESTIMATE);
  for (std::size_t j = 0; j < n; ++j) {
    const double s = std::sin(std::numbers::pi * static_cast<double>(j) / static_cast<double>(n));
    in[j] = s * s * r[j];
  }
  fftw_execute(plan);
  const double resolution = 1.0 / (static_cast<double>(n) * road.spacing());  // cycles/m
  // Out of band: below 0.95 * 2 or above 1.05 * 20 cycles/m. With the resolution of 1/2000
  // cycles/m the 5 % margins are >= 200 bins, where Hann leakage from the band is ~(1/200)^6
  // ~ 1e-14 of the in-band power per bin; the synthesis itself puts exactly nothing there,
  // so what remains is rounding (~1e-17 observed). 1e-10 leaves room for both.
  double inside = 0.0, outside = 0.0;
  double third[3] = {0.0, 0.0, 0.0};
  std::size_t third_bins[3] = {0, 0, 0};
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double p = out[k][0] * out[k][0] + out[k][1] * out[k][1];
    const double f = static_cast<double>(k) * resolution;
    if (f < 0.95 * 2.0 || f > 1.05 * 20.0) {
      outside += p;
    } else {
      inside += p;
    }
    // Flatness: mean periodogram over the three thirds of the band, kept clear of the edges.
    if (f > 2.1 && f < 19.9) {
      const auto t = static_cast<std::size_t>(std::min(2.0, (f - 2.1) / ((19.9 - 2.1) / 3.0)));
      third[t] += p;
      ++third_bins[t];
    }
  }
  fftw_destroy_plan(plan);
  fftw_free(out);
  fftw_free(in);

  const double fraction = outside / (inside + outside);
  std::printf("  energy fraction outside the band: %.3g\n", fraction);
  EXPECT_LT(fraction, 1e-10);

  // Each third spans 5.9 cycles/m, ~11900 bins; a Hann periodogram bin has a relative standard
  // deviation of 1, neighbours correlated over ~2 bins, so the mean of a third is known to
  // ~sqrt(2/11900) = 1.3 %. The tolerance 0.1 is ~8 of those, and a spectrum tilted by a
  // factor of 1/n or n across the band would miss it by far.
  const double all = (third[0] + third[1] + third[2]) /
                     static_cast<double>(third_bins[0] + third_bins[1] + third_bins[2]);
  for (int t = 0; t < 3; ++t) {
    const double ratio = third[t] / static_cast<double>(third_bins[t]) / all;
    std::printf("  band third %d: mean power / band mean = %.4f\n", t, ratio);
    EXPECT_NEAR(ratio, 1.0, 0.1) << "third " << t;
  }
}

TEST(RandomRoad, LeadInStartsAtZeroWithoutJump) {
  RandomRoadSpec spec = gaussian_spec(0.25, 50.0, 5);  // default lead-in 2 lc = 0.5 m
  const RandomRoad road(spec);
  EXPECT_EQ(road.lead_in(), 0.5);
  spec.lead_in = 0.0;
  const RandomRoad bare(spec);

  EXPECT_EQ(road.height(0.0), 0.0);
  EXPECT_EQ(road.height(-1e-9), 0.0);
  // Continuity at 0: between the first two grid points the road is linear from r(0) = 0, so
  // |r(eps)| <= (eps / spacing) * w(spacing) * max|r_bare|, with max|r_bare| < 6 sigma.
  const double w1 = std::pow(std::sin(std::numbers::pi * road.spacing() / (2.0 * road.lead_in())), 2);
  EXPECT_LT(std::abs(road.height(1e-9)), 1e-9 / road.spacing() * w1 * 6.0 * spec.std_dev);
  // The window w(x) = sin^2(pi x / (2 lead_in)), written here independently of the
  // implementation's 0.5 (1 - cos(pi x / lead_in)), times the stationary road.
  const std::size_t count = static_cast<std::size_t>(std::ceil(50.0 / road.spacing()));
  for (std::size_t j = 0; j <= count; ++j) {
    const double x = road.spacing() * static_cast<double>(j);
    if (x >= road.lead_in()) {
      ASSERT_EQ(road.height(x), bare.height(x)) << "x = " << x;
    } else {
      const double s = std::sin(std::numbers::pi * x / (2.0 * road.lead_in()));
      ASSERT_NEAR(road.height(x), s * s * bare.height(x), 1e-15 * spec.std_dev) << "x = " << x;
    }
  }
  // Near the start the road is small: |r| <= w(x) * max|r_bare| with w(0.01 m) = 1e-3.
  for (double x = 0.0; x <= 0.01; x += 1e-4) EXPECT_LT(std::abs(road.height(x)), 1e-3 * 6.0 * spec.std_dev);
}

TEST(RandomRoad, LinearBetweenGridPointsAndRangeChecked) {
  const RandomRoad road(gaussian_spec(0.2, 3.0, 9));
  EXPECT_GE(road.end(), 3.0);
  const double h = road.spacing();
  for (int j = 0; j < 100; ++j) {
    const double x0 = h * j + 1.0;
    // Rounding of x (x0 is not on the grid exactly) and of the weights: ~1e-15 relative.
    EXPECT_NEAR(road.height(x0 + 0.25 * h), 0.75 * road.height(x0) + 0.25 * road.height(x0 + h), 1e-12 * 1e-3);
  }
  EXPECT_NO_THROW((void)road.height(3.0));
  EXPECT_NO_THROW((void)road.height(road.end()));
  EXPECT_THROW((void)road.height(road.end() + h), std::logic_error);
  EXPECT_THROW((void)road.height(std::nan("")), std::logic_error);
  EXPECT_EQ(road.height(-5.0), 0.0);
}

TEST(RandomRoad, InvalidParametersNameTheKey) {
  auto key_of = [](const RandomRoadSpec& spec) {
    try {
      RandomRoad road(spec);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("(no error)");
  };
  RandomRoadSpec spec = gaussian_spec(1.0, 1e9, 1);  // 1.6e10 samples at lc/16
  EXPECT_EQ(key_of(spec), "sample_spacing");
  spec = gaussian_spec(1.0, 10.0, 1);
  spec.sample_spacing = 0.6;  // coarser than lc/2
  EXPECT_EQ(key_of(spec), "sample_spacing");
  spec = gaussian_spec(1.0, 10.0, 1);
  spec.std_dev = 0.0;
  EXPECT_EQ(key_of(spec), "std_dev");
  spec = gaussian_spec(1.0, 10.0, 1);
  spec.lead_in = -1.0;
  EXPECT_EQ(key_of(spec), "lead_in");
  spec.spectrum = RandomRoadSpec::Spectrum::band;
  spec.lead_in.reset();
  spec.min_wavelength = 0.5;
  spec.max_wavelength = 0.5;
  EXPECT_EQ(key_of(spec), "min_wavelength");
}

}  // namespace
}  // namespace rollnoise
