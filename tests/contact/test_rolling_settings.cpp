// The grid and time step that carry a band (rolling_settings.hpp): checked against the band
// edges of IEC 61260-1 and against the defining inequality 0.99·v·N/(2·L) ≥ f_2.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact/rolling_settings.hpp"

namespace rollnoise {
namespace {

constexpr double kCircumference = 2.0 * std::numbers::pi * 0.316;  // the 205/55 R16

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
    EXPECT_LT(carried(n - 2), f2) << speed;
    // One step per cell then suffices.
    EXPECT_EQ(substeps_for_band(5000.0, kCircumference / n, speed), 1) << speed;
  }
  // The counts the README and the cases quote (30, 50, 80, 130 km/h).
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 8.3333), 2708);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 13.889), 1626);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 22.222), 1016);
  EXPECT_EQ(circumferential_points_for_band(5000.0, kCircumference, 36.111), 626);
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
