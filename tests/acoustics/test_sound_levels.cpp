// Levels of known signals: the 94 dB calibration tone in its band, pink noise's equal band
// levels, Leq and LAeq, and LAFmax of tone bursts against the exponential rise.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include <fftw3.h>

#include "acoustics/frequency_weighting.hpp"
#include "acoustics/sound_levels.hpp"
#include "core/cancellation.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"

namespace rollnoise {
namespace {

constexpr double fs = 48000.0;
const double level_of_1pa_rms = 20.0 * std::log10(1.0 / 20e-6);  // 93.9794 dB

// a·√2·sin(2π f t): RMS a, from t = 0, n samples.
std::vector<double> tone(double rms, double f, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = rms * std::sqrt(2.0) * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / fs);
  return x;
}

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

// Pink noise of period n samples: seeded Gaussian white noise, transformed, each bin's magnitude
// set exactly to 1/√f_k (phase kept; DC and Nyquist zero), transformed back, scaled to RMS 1 Pa.
// Its power spectrum is then exactly 1/f on the bins f_k = k fs/n: the band levels carry no
// statistical scatter, only what the filters and the finite bin spacing give. (With random
// amplitudes, i.e. plain filtered noise, a band of width B averaged over T has a level scatter
// of 4.34/√(BT) dB: 0.5 dB across 28 bands at 3 standard deviations would need BT ≈ 700 in the
// 20 Hz band (B = 4.6 Hz), 150 s of signal.)
std::vector<double> periodic_pink_noise(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::unique_ptr<double[], FftwFree> time(fftw_alloc_real(n));
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  for (std::size_t i = 0; i < n; i += 2) {
    const double u1 = (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    time[i] = r * std::cos(2.0 * std::numbers::pi * u2);
    if (i + 1 < n) time[i + 1] = r * std::sin(2.0 * std::numbers::pi * u2);
  }
  FftwPlan([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(n), time.get(), spectrum.get(), FFTW_ESTIMATE); })
      .execute();
  spectrum[0][0] = spectrum[0][1] = 0.0;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    const double magnitude = std::hypot(spectrum[k][0], spectrum[k][1]);
    const double target = (k == n / 2) ? 0.0 : 1.0 / std::sqrt(static_cast<double>(k));
    const double scale = magnitude > 0.0 ? target / magnitude : 0.0;
    spectrum[k][0] *= scale;
    spectrum[k][1] *= scale;
  }
  FftwPlan([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum.get(), time.get(), FFTW_ESTIMATE); })
      .execute();
  std::vector<double> x(time.get(), time.get() + n);
  const double rms = std::sqrt(mean_square(x));
  for (double& v : x) v /= rms;
  return x;
}

std::size_t index_of(const BandSpectrum& s, const std::string& label) {
  return static_cast<std::size_t>(std::find(s.labels.begin(), s.labels.end(), label) - s.labels.begin());
}

TEST(SoundLevels, OnePascalRmsSineIs94dBInIts1kHzBand) {
  const std::vector<double> x = tone(1.0, 1000.0, 48000);  // 1 s
  BandSpectrumOptions options;
  options.settle_time = 0.1;
  const BandSpectrum s = band_spectrum(x, fs, options);
  const std::size_t k = index_of(s, "1000");
  ASSERT_LT(k, s.labels.size());
  std::printf("[measured] 1 Pa RMS, 1 kHz: L(1 kHz band) = %.4f dB; 630 / 800 / 1250 / 1600 Hz bands: %.2f / %.2f / "
              "%.2f / %.2f dB\n",
              s.lp_db[k], s.lp_db[k - 2], s.lp_db[k - 1], s.lp_db[k + 1], s.lp_db[k + 2]);
  EXPECT_NEAR(s.lp_db[k], 94.0, 0.05);
  EXPECT_NEAR(s.lpa_db[k], s.lp_db[k], 1e-9);  // A(1 kHz) = 0
  // Two bands away the order-3 (6th-order band-pass) filters give the Butterworth 37.0 dB
  // (test_fractional_octave_bands.cpp); with order 4 it is more than 40 dB.
  EXPECT_NEAR(s.lp_db[k] - s.lp_db[k - 2], 37.0, 0.1);
  EXPECT_NEAR(s.lp_db[k] - s.lp_db[k + 2], 37.0, 0.1);
  options.filter_order = 4;
  const BandSpectrum s4 = band_spectrum(x, fs, options);
  std::printf("[measured] order 4: L(1 kHz band) = %.4f dB; 630 / 1600 Hz bands %.2f / %.2f dB down\n", s4.lp_db[k],
              s4.lp_db[k] - s4.lp_db[k - 2], s4.lp_db[k] - s4.lp_db[k + 2]);
  EXPECT_NEAR(s4.lp_db[k], 94.0, 0.05);
  EXPECT_GT(s4.lp_db[k] - s4.lp_db[k - 2], 40.0);
  EXPECT_GT(s4.lp_db[k] - s4.lp_db[k + 2], 40.0);
  // The whole-signal levels.
  EXPECT_NEAR(leq_db(x), level_of_1pa_rms, 1e-9);
  EXPECT_NEAR(laeq_db(x, fs), level_of_1pa_rms, 0.01);
}

TEST(SoundLevels, OnePascalRmsSineIs94dBInIts1kHzBandByWelch) {
  const std::vector<double> x = tone(1.0, 1000.0, 48000 * 4);
  BandSpectrumOptions options;
  options.method = BandSpectrumOptions::Method::welch;
  options.f_low = 100.0;  // resolution a tenth of the 100 Hz band: 4096-sample segments
  const BandSpectrum s = band_spectrum(x, fs, options);
  const std::size_t k = index_of(s, "1000");
  std::printf("[measured] Welch path, 1 Pa RMS at 1 kHz: L(1 kHz band) = %.4f dB; 800 Hz band %.1f dB\n", s.lp_db[k],
              s.lp_db[k - 1]);
  EXPECT_NEAR(s.lp_db[k], 94.0, 0.05);
  EXPECT_LT(s.lp_db[k - 2], s.lp_db[k] - 60.0);  // brick-wall bands: only window leakage
}

// Pink noise: equal third-octave band levels, 20 Hz to 10 kHz. Two periods of the periodic
// signal, the first left out as settling time: the average then covers exactly one period in
// the filters' steady state, and every band's power is Σ_k |H(f_k)|²/f_k, bins 0.1 Hz apart
// (≥ 46 bins in the 20 Hz band: the sum is the integral ∫|H|² d(ln f) to far better than 0.01 dB).
TEST(SoundLevels, PinkNoiseGivesEqualThirdOctaveBandLevels) {
  const std::size_t period = 480000;  // 10 s
  std::vector<double> x = periodic_pink_noise(period, 7);
  x.insert(x.end(), x.begin(), x.end());
  BandSpectrumOptions options;
  options.settle_time = 10.0;
  const BandSpectrum s = band_spectrum(x, fs, options);
  ASSERT_EQ(s.lp_db.size(), 28u);
  const auto [lo, hi] = std::minmax_element(s.lp_db.begin(), s.lp_db.end());
  double mean = 0.0;
  for (double l : s.lp_db) mean += l;
  mean /= static_cast<double>(s.lp_db.size());
  // The ideal band: bin k holds c/k of the mean square 1 Pa², c = 1/H (H = Σ 1/k over the
  // bins 1 .. n/2 − 1), so a third octave holds c·ln(10^0.1); the Butterworth order-3 band's
  // effective width exceeds the ideal one by π/(3 sin(π/6))/2 = 4.7 % (+0.20 dB).
  double harmonic = 0.0;
  for (std::size_t k = 1; k < period / 2; ++k) harmonic += 1.0 / static_cast<double>(k);
  const double ideal = 10.0 * std::log10(std::log(std::pow(10.0, 0.1)) / harmonic / (20e-6 * 20e-6));
  std::printf("[measured] pink noise, third octaves 20 Hz-10 kHz: spread (max - min) %.4f dB (lowest %s Hz, highest %s Hz); "
              "mean %.3f dB, ideal band %.3f dB\n",
              *hi - *lo, s.labels[static_cast<std::size_t>(lo - s.lp_db.begin())].c_str(),
              s.labels[static_cast<std::size_t>(hi - s.lp_db.begin())].c_str(), mean, ideal);
  EXPECT_LE(*hi - *lo, 0.5);
  EXPECT_NEAR(mean - ideal, 10.0 * std::log10(std::numbers::pi / 3.0), 0.05);
  // The A-weighted band levels are the band levels plus A(f_m).
  for (std::size_t i = 0; i < s.lp_db.size(); ++i) {
    EXPECT_NEAR(s.lpa_db[i], s.lp_db[i] + weighting_db(FrequencyWeighting::A, s.exact_hz[i]), 1e-12);
  }

  // The Welch path on the same signal (2^17-sample segments, 0.37 Hz).
  options.method = BandSpectrumOptions::Method::welch;
  const BandSpectrum w = band_spectrum(x, fs, options);
  const auto [wlo, whi] = std::minmax_element(w.lp_db.begin(), w.lp_db.end());
  std::printf("[measured] pink noise by Welch: spread %.4f dB (lowest %s, highest %s)\n", *whi - *wlo,
              w.labels[static_cast<std::size_t>(wlo - w.lp_db.begin())].c_str(),
              w.labels[static_cast<std::size_t>(whi - w.lp_db.begin())].c_str());
  EXPECT_LE(*whi - *wlo, 0.5);
}

TEST(SoundLevels, LeqOfKnownSignals) {
  // A sine of RMS a: 10 lg(a²/p0²).
  EXPECT_NEAR(leq_db(tone(0.2, 250.0, 48000)), 20.0 * std::log10(0.2 / 20e-6), 1e-9);
  // On for half the time: 3.01 dB less.
  std::vector<double> half = tone(1.0, 1000.0, 48000);
  half.resize(96000, 0.0);
  EXPECT_NEAR(leq_db(half), level_of_1pa_rms - 10.0 * std::log10(2.0), 1e-9);
  // Any signal: 10 lg(mean square / p0²).
  const std::vector<double> steps = {0.1, -0.3, 0.2, 0.0};
  EXPECT_NEAR(leq_db(steps), 10.0 * std::log10((0.01 + 0.09 + 0.04) / 4.0 / 4e-10), 1e-9);
  EXPECT_EQ(leq_db(std::vector<double>(10, 0.0)), -INFINITY);
  EXPECT_THROW(mean_square(std::vector<double>{}), std::invalid_argument);
}

// LAeq and LCeq of tones: the level plus the weighting at the tone's frequency, to the digital
// filter's accuracy (< 0.08 dB, test_frequency_weighting.cpp) and exactly (0.01 dB) the
// filter's own response; 10 s, so that the filter's start-up transient is < 0.01 dB of the average.
TEST(SoundLevels, WeightedLeqOfTonesAddsTheWeighting) {
  for (double f : {100.0, 1000.0, 4000.0, 12000.0}) {
    const std::vector<double> x = tone(1.0, f, 480000);
    for (FrequencyWeighting w : {FrequencyWeighting::A, FrequencyWeighting::C}) {
      const double measured = weighted_leq_db(x, fs, w);
      EXPECT_NEAR(measured, level_of_1pa_rms + WeightingFilter(w, fs).response_db(f), 0.01) << f;
      EXPECT_NEAR(measured, level_of_1pa_rms + weighting_db(w, f), 0.08) << f;
      std::printf("[measured] L%seq of a 1 Pa RMS %5.0f Hz tone: %.3f dB (closed form %.3f)\n", to_string(w).c_str(), f,
                  measured, level_of_1pa_rms + weighting_db(w, f));
    }
    EXPECT_EQ(laeq_db(x, fs), weighted_leq_db(x, fs, FrequencyWeighting::A));
    EXPECT_NEAR(weighted_leq_db(x, fs, FrequencyWeighting::Z), level_of_1pa_rms, 1e-9) << f;
  }
}

// A tone burst of `duration` s at `f` Hz and 1 Pa RMS after 0.1 s of silence, then 0.5 s of silence.
std::vector<double> burst(double f, double duration) {
  std::vector<double> x(4800, 0.0);
  const std::vector<double> on = tone(1.0, f, static_cast<std::size_t>(std::lround(duration * fs)));
  x.insert(x.end(), on.begin(), on.end());
  x.resize(x.size() + 24000, 0.0);
  return x;
}

// The fraction of a burst's energy the A weighting passes, relative to A at the tone's
// frequency, from the burst's spectrum and the closed-form weighting: Σ|X_k|² 10^(A(f_k)/10) /
// (Σ|X_k|² 10^(A(f)/10)). 1 for a long burst; for a short one the spectrum spreads over the
// weighting's slope (a 2 ms burst at 1 kHz: main lobe 500-1500 Hz, where A runs from −3.2 to +0.9 dB).
double weighted_energy_fraction(std::span<const double> x, double f) {
  const std::size_t n = std::size_t{1} << 17;
  std::unique_ptr<double[], FftwFree> time(fftw_alloc_real(n));
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  for (std::size_t i = 0; i < n; ++i) time[i] = i < x.size() ? x[i] : 0.0;
  FftwPlan([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(n), time.get(), spectrum.get(), FFTW_ESTIMATE); })
      .execute();
  double plain = 0.0;
  double weighted = 0.0;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    const double power = spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1];
    plain += power;
    weighted += power * std::pow(10.0, weighting_db(FrequencyWeighting::A, static_cast<double>(k) * fs / static_cast<double>(n)) / 10.0);
  }
  return weighted / plain / std::pow(10.0, weighting_db(FrequencyWeighting::A, f) / 10.0);
}

// Tone bursts from silence (starting and stopping at zero crossings): the F-time-weighted level
// rises as 10 lg(1 − e^{−T/τ}) below the steady level, and the maximum is reached at the burst's
// end. Without frequency weighting that holds to 0.003 dB for every duration. With the A
// weighting a short burst also loses what its spread spectrum loses on the weighting's slope
// (1 kHz, 2 ms: 0.37 dB): the expected LAFmax is the steady level + 10 lg(1 − e^{−T/τ}) + that
// spectral fraction. That is met to 0.03 dB: the rest (≤ 0.02 dB, the same with the digital
// filter's response in place of the closed form) is the weighting filter's spreading of the
// burst's energy in time — what arrives late finds the detector already decaying. (IEC 61672-1
// checks tonebursts at 4 kHz, where A is flat enough that a 2 ms burst loses 0.04 dB.)
TEST(SoundLevels, LafmaxOfToneBurstsFollowsTheExponentialRise) {
  for (double f : {1000.0, 4000.0}) {
    const double steady_z = max_time_weighted_level_db(tone(1.0, f, 96000), fs, FrequencyWeighting::Z, fast_time_constant);
    const double steady_a = lafmax_db(tone(1.0, f, 96000), fs);
    EXPECT_NEAR(steady_z, level_of_1pa_rms, 0.01) << f;
    EXPECT_NEAR(steady_a, level_of_1pa_rms + WeightingFilter(FrequencyWeighting::A, fs).response_db(f), 0.01) << f;
    for (double duration : {0.5, 0.2, 0.05, 0.01, 0.002, 0.00025}) {
      if (std::abs(duration * f - std::round(duration * f)) > 1e-9) continue;  // whole periods only
      const std::vector<double> x = burst(f, duration);
      const double rise = 10.0 * std::log10(1.0 - std::exp(-duration / fast_time_constant));
      const double z = max_time_weighted_level_db(x, fs, FrequencyWeighting::Z, fast_time_constant) - steady_z;
      const double spectral = 10.0 * std::log10(weighted_energy_fraction(x, f));
      const double a = lafmax_db(x, fs) - steady_a;
      std::printf("[measured] %4.0f Hz burst of %7.5f s: rise %+8.4f dB; Z: %+8.4f; A: %+8.4f (with the burst's "
                  "spectral A loss %+.4f: %+8.4f)\n",
                  f, duration, rise, z, a, spectral, rise + spectral);
      EXPECT_NEAR(z, rise, 0.003) << f << " Hz, " << duration << " s";
      EXPECT_NEAR(a, rise + spectral, 0.03) << f << " Hz, " << duration << " s";
      if (duration >= 0.2) {
        EXPECT_NEAR(a, rise, 0.005) << f << " Hz, " << duration << " s";
      }
    }
  }
  // S time weighting: a 1 s burst reaches 10 lg(1 − e^{−1}) = −2.0 dB.
  std::vector<double> x = tone(1.0, 1000.0, 48000);
  x.resize(96000, 0.0);
  EXPECT_NEAR(max_time_weighted_level_db(x, fs, FrequencyWeighting::A, slow_time_constant),
              level_of_1pa_rms + 10.0 * std::log10(1.0 - std::exp(-1.0)), 0.01);
  EXPECT_THROW(time_weighted_levels_db(x, fs, FrequencyWeighting::A, 0.0), InputError);
}

TEST(SoundLevels, BandSpectrumRejectsBadOptions) {
  const std::vector<double> x = tone(1.0, 1000.0, 4800);
  BandSpectrumOptions options;
  options.settle_time = 0.1;
  try {
    band_spectrum(x, fs, options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "settle_time");
  }
  options.settle_time = 0.0;
  options.method = BandSpectrumOptions::Method::welch;
  try {
    band_spectrum(x, fs, options);  // the 20 Hz band needs 2^17-sample segments
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "welch_segment_length");
  }
  options.method = BandSpectrumOptions::Method::filter_bank;
  options.f_high = 20000.0;
  EXPECT_THROW(band_spectrum(x, 32000.0, options), InputError);
  EXPECT_THROW(band_spectrum(std::vector<double>{}, fs, BandSpectrumOptions{}), InputError);
}

// The band filters and the weighting filter poll a CancellationToken as they go (long sound
// output under Ctrl-C): a cancelled token (the test's own flag, set before the call: no timing)
// throws Interrupted; one that is not cancelled gives the levels of the default token.
TEST(SoundLevels, BandAndWeightingFiltersStopWhenCancelled) {
  const std::vector<double> x = tone(1.0, 1000.0, 3 * 48000);
  std::atomic<int> flag{0};
  BandSpectrumOptions options;
  options.settle_time = 0.5;
  const BandSpectrum expected = band_spectrum(x, fs, options);
  options.cancel = CancellationToken(flag);
  EXPECT_EQ(band_spectrum(x, fs, options).lp_db, expected.lp_db);
  const WeightingFilter a(FrequencyWeighting::A, fs);
  EXPECT_EQ(a.apply(x, CancellationToken(flag)), a.apply(x));
  flag = SIGTERM;
  EXPECT_THROW(band_spectrum(x, fs, options), Interrupted);
  EXPECT_THROW(a.apply(x, CancellationToken(flag)), Interrupted);
}

}  // namespace
}  // namespace rollnoise
