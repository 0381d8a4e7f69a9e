// SineRoad against its defining formula, evaluated here independently.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "road/sine_road.hpp"

namespace rollnoise {
namespace {

TEST(SineRoad, MatchesFormulaAtManyPoints) {
  const double amplitude = 2.5e-3;
  const double wavelength = 0.37;
  const SineRoad road(amplitude, wavelength);
  EXPECT_EQ(road.type(), "sine");
  // Independent evaluation in long double; the two differ by the rounding of sin's argument in
  // double: a few ulp of the phase, which reaches 2 pi * 37 / 0.37 = 628 rad here, i.e. up to
  // ~4e-13 rad. 1e-12 * amplitude bounds that and would catch any wrong factor.
  for (int i = 0; i <= 10000; ++i) {
    const double x = 0.0037 * i;
    const long double phase = 2.0L * 3.14159265358979323846264338327950288L * static_cast<long double>(x) /
                              static_cast<long double>(wavelength);
    const double expected = static_cast<double>(static_cast<long double>(amplitude) * std::sin(phase));
    ASSERT_NEAR(road.height(x), expected, 1e-12 * amplitude) << "x = " << x;
  }
}

TEST(SineRoad, KnownValues) {
  const SineRoad road(1e-3, 0.2);
  EXPECT_EQ(road.height(0.0), 0.0);
  EXPECT_NEAR(road.height(0.05), 1e-3, 1e-18);    // quarter wavelength: crest
  EXPECT_NEAR(road.height(0.15), -1e-3, 1e-18);   // three quarters: trough
  EXPECT_NEAR(road.height(0.1), 0.0, 1e-18);      // half wavelength: zero crossing
}

TEST(SineRoad, ZeroBeforeStart) {
  const SineRoad road(1e-3, 0.2);
  for (double x : {-1e-12, -0.05, -0.15, -1.0, -1e6}) EXPECT_EQ(road.height(x), 0.0) << x;
  EXPECT_EQ(road.height(-std::numeric_limits<double>::infinity()), 0.0);
}

TEST(SineRoad, RejectsNonPositiveParameters) {
  EXPECT_THROW(SineRoad(0.0, 1.0), InputError);
  EXPECT_THROW(SineRoad(-1.0, 1.0), InputError);
  EXPECT_THROW(SineRoad(1.0, 0.0), InputError);
  EXPECT_THROW(SineRoad(1.0, std::nan("")), InputError);
}

}  // namespace
}  // namespace rollnoise
