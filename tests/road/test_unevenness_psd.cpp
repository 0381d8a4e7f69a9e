// ISO 8608: the class table, and the class and G_d(n0) of profiles synthesised with a known
// G_d(n0) and waviness w = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include <fftw3.h>

#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/unevenness_psd.hpp"

namespace rollnoise {
namespace {

TEST(UnevennessPsd, ClassTableOfTheStandard) {
  const double expected[] = {16e-6, 64e-6, 256e-6, 1024e-6, 4096e-6, 16384e-6, 65536e-6, 262144e-6};
  for (char c = 'A'; c <= 'H'; ++c) {
    EXPECT_DOUBLE_EQ(iso8608_class_gd_n0(c), expected[c - 'A']) << c;
    // The limits are a factor 2 either side of the geometric mean.
    EXPECT_EQ(iso8608_class_of(expected[c - 'A']), std::string(1, c));
    EXPECT_EQ(iso8608_class_of(1.999 * expected[c - 'A']), std::string(1, c));
    if (c > 'A') {
      EXPECT_EQ(iso8608_class_of(0.5 * expected[c - 'A']), std::string(1, c));
      EXPECT_EQ(iso8608_class_of(0.499 * expected[c - 'A']), std::string(1, static_cast<char>(c - 1)));
    }
  }
  EXPECT_EQ(iso8608_class_of(1e-9), "A");
  EXPECT_EQ(iso8608_class_of(1.0), "H");
  EXPECT_THROW(iso8608_class_gd_n0('I'), InputError);
  EXPECT_THROW(iso8608_class_gd_n0('a'), InputError);
  EXPECT_THROW(iso8608_class_of(0.0), InputError);
  EXPECT_THROW(iso8608_class_of(std::numeric_limits<double>::quiet_NaN()), InputError);
}

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

// A profile of n points at spacing dx with one-sided PSD G_d(n) = gd_n0 (n/0.1)^-2 for
// n >= 0.005 cycles/m (0 below: a road has no infinitely long waves): every DFT line k has the
// amplitude sqrt(2 G_d(n_k) Δn), Δn = 1/(n dx), and a random phase.
std::vector<double> synthesise(double gd_n0, std::size_t n, double dx, std::uint64_t seed) {
  std::unique_ptr<fftw_complex[], FftwFree> spectrum(fftw_alloc_complex(n / 2 + 1));
  std::unique_ptr<double[], FftwFree> z(fftw_alloc_real(n));
  const FftwPlan plan([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum.get(), z.get(), FFTW_ESTIMATE); });
  std::mt19937_64 rng(seed);
  const double dn = 1.0 / (static_cast<double>(n) * dx);
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double f = static_cast<double>(k) * dn;
    double amplitude = 0.0;
    if (f >= 0.005 && 2 * k < n) amplitude = std::sqrt(2.0 * gd_n0 * std::pow(f / 0.1, -2.0) * dn);
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    // z_i = Σ_k a_k cos(2π k i / n + φ_k) = Re Σ_k a_k e^{iφ_k} e^{2πi k i/n}: the c2r transform
    // of X_k = a_k e^{iφ_k} / 2 (it adds the conjugate half).
    spectrum[k][0] = 0.5 * amplitude * std::cos(phase);
    spectrum[k][1] = 0.5 * amplitude * std::sin(phase);
  }
  plan.execute();
  return {z.get(), z.get() + n};
}

TEST(UnevennessPsd, SynthesisedProfilesGiveTheirClassAndGdN0) {
  // 2^16 points at 5 cm: 3.3 km, Welch segments of 2^14 points (819 m, 7 of them).
  // Scatter of the fitted G_d(n0): a third-octave band of m bins, averaged over K ≈ 7
  // half-overlapping segments (≈ 5 independent ones), scatters by about 1/sqrt(5 m); the fit is
  // the mean of B = 24 bands, the lowest holding 1 to 2 bins: relative standard deviation
  // sqrt(Σ 1/(5 m_b)) / B ≈ 0.025. Tolerance 10 % (4 standard deviations), checked on each
  // class with its own seed; the class, a factor 2 from its limits, must be exact.
  const std::size_t n = 1 << 16;
  const double dx = 0.05;
  for (char c = 'A'; c <= 'H'; ++c) {
    const double gd_n0 = iso8608_class_gd_n0(c);
    const auto z = synthesise(gd_n0, n, dx, 77 + static_cast<std::uint64_t>(c));
    const UnevennessPsd psd = unevenness_psd(z, dx);
    EXPECT_EQ(psd.iso8608_class, std::string(1, c));
    EXPECT_NEAR(psd.gd_n0 / gd_n0, 1.0, 0.10) << c;
    EXPECT_EQ(psd.waviness, 2.0);
    ASSERT_EQ(psd.n.size(), psd.gd.size());
    ASSERT_EQ(psd.n.size(), (std::size_t{1} << 14) / 2);
    EXPECT_DOUBLE_EQ(psd.n.front(), 1.0 / ((1 << 14) * dx));
  }
}

TEST(UnevennessPsd, BetweenClassesTheNearestLimitDecides) {
  // 1.6 · gm(C) (below C's upper limit 2 · gm) is C; 2.6 · gm(C) = 0.65 · gm(D) is D.
  const std::size_t n = 1 << 16;
  const double dx = 0.05;
  EXPECT_EQ(unevenness_psd(synthesise(1.6 * 256e-6, n, dx, 5), dx).iso8608_class, "C");
  EXPECT_EQ(unevenness_psd(synthesise(2.6 * 256e-6, n, dx, 6), dx).iso8608_class, "D");
}

TEST(UnevennessPsd, BadInputIsAnInputError) {
  auto key_of = [](std::vector<double> z, double spacing) -> std::string {
    try {
      unevenness_psd(z, spacing);
    } catch (const InputError& e) {
      return e.key();
    }
    return "no error";
  };
  EXPECT_EQ(key_of(std::vector<double>(1000, 0.0), -1.0), "spacing");
  EXPECT_EQ(key_of(std::vector<double>(1000, 0.0), std::numeric_limits<double>::quiet_NaN()), "spacing");
  // 2 m of texture at 1 mm: no spatial frequency of 0.011 … 2.83 cycles/m below a quarter of
  // the sampling rate is resolved with bins k >= 3 of a 512-point segment (k/0.512 m >= 5.9).
  EXPECT_EQ(key_of(std::vector<double>(2000, 0.0), 1e-3), "profile");
  std::vector<double> with_nan(1000, 0.0);
  with_nan[9] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(key_of(with_nan, 0.1), "profile");
  EXPECT_EQ(key_of({1.0, 2.0}, 0.1), "profile");
}

}  // namespace
}  // namespace rollnoise
