// The grid and time step that carry a band (rolling_settings.hpp): checked against the band
// edges of IEC 61260-1 and against the defining inequality 0.99·v·N/(2·L) ≥ f_2.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact/rolling_settings.hpp"
#include "core/fftw_plan.hpp"

namespace rollnoise {
namespace {

constexpr double kCircumference = 2.0 * std::numbers::pi * 0.316;  // the 205/55 R16

TEST(FftwFastLength, SizesOfFftwsCodeletsAndNoOthers) {
  // 2^a·3^b·5^c·7^d·11^e·13^f, e + f ≤ 1 (FFTW's manual), checked against trial division.
  const auto by_trial = [](long n) {
    int elevens_and_thirteens = 0;
    for (const long p : {2L, 3L, 5L, 7L, 11L, 13L}) {
      while (n % p == 0) {
        n /= p;
        if (p >= 11) ++elevens_and_thirteens;
      }
    }
    return n == 1 && elevens_and_thirteens <= 1;
  };
  for (long n = 1; n <= 5000; ++n) EXPECT_EQ(fftw_fast_length(n), by_trial(n)) << n;
  EXPECT_EQ(next_fftw_fast_length(1016, true), 1024);
  EXPECT_EQ(next_fftw_fast_length(1626, true), 1638);
  EXPECT_EQ(next_fftw_fast_length(127, false), 128);
  EXPECT_EQ(next_fftw_fast_length(143, false), 144);  // 11·13 has both
  EXPECT_EQ(next_fftw_fast_length(1024, true), 1024);
  EXPECT_THROW(next_fftw_fast_length(0, true), std::invalid_argument);
}

TEST(RollingSettings, BandTopEdgeIsTheThirdOctaveUpperEdge) {
  // IEC 61260-1 base 10: f_m = 1000·10^(x/10), f_2 = f_m·10^(1/20). The 5 kHz band is x = 7.
  EXPECT_NEAR(band_top_edge(5000.0), 5623.413, 1e-3);
  EXPECT_NEAR(band_top_edge(1000.0), 1122.018, 1e-3);
  // A nominal centre is taken to its exact band: 3150 is 10^(1/2)·1000 = 3162.3.
  EXPECT_NEAR(band_top_edge(3150.0), 3548.134, 1e-3);
}

TEST(RollingSettings, GridForTheBandIsTheLeastEvenCountThatCarriesIt) {
  const double f2 = band_top_edge(5000.0);
  for (const double speed : {8.3333, 13.889, 22.222, 36.111}) {
    const int n = circumferential_points_for_band(5000.0, kCircumference, speed);
    EXPECT_EQ(n % 2, 0) << speed;
    const auto carried = [&](int cells) { return 0.99 * speed * cells / (2.0 * kCircumference); };
    EXPECT_GE(carried(n), f2) << speed;
    // The least such count, unless rounded up to a fast transform length: then no fast length
    // lies between the least count and n.
    int least = n;
    while (carried(least - 2) >= f2) least -= 2;
    EXPECT_TRUE(fftw_fast_length(n)) << speed;
    for (int m = least; m < n; m += 2) EXPECT_FALSE(fftw_fast_length(m)) << speed << " " << m;
    // One step per cell then suffices.
    EXPECT_EQ(substeps_for_band(5000.0, kCircumference / n, speed), 1) << speed;
  }
  // The counts docs/physics/contact.md and the cases quote (30, 50, 80, 130 km/h): the least even counts are
  // 2708, 1626, 1016 and 626, rounded up to 2730 = 2·3·5·7·13, 1638 = 2·3²·7·13, 1024 = 2¹⁰ and
  // 630 = 2·3²·5·7.
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 8.3333), 2730);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 13.889), 1638);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 22.222), 1024);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 36.111), 630);
  EXPECT_THROW(circumferential_points_for_band(0.0, kCircumference, 22.222), std::invalid_argument);
}

TEST(RollingSettings, SubStepsOnACoarserGridCarryTheSameBand) {
  // 512 cells at 30 km/h: p = 6 (Nyquist 6.45 kHz), the least p with 0.99·p·v/(2·dx) ≥ f_2.
  const double dx = kCircumference / 512.0;
  const int p = substeps_for_band(5000.0, dx, 8.3333);
  EXPECT_EQ(p, 6);
  EXPECT_GE(0.99 * p * 8.3333 / (2.0 * dx), band_top_edge(5000.0));
  EXPECT_LT(0.99 * (p - 1) * 8.3333 / (2.0 * dx), band_top_edge(5000.0));
  EXPECT_EQ(substeps_for_band(0.0, dx, 8.3333), 1);
}

}  // namespace
}  // namespace rollnoise
