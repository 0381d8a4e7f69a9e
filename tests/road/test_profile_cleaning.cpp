// clean_profile: dropouts and spikes of a measured profile (ISO 13473-1:2019 §7.3, §7.5).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "road/profile_cleaning.hpp"

namespace rollnoise {
namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

TEST(ProfileCleaning, DropoutsAreInterpolatedLinearlyAndEndsTakeTheNearestValue) {
  // Spacing 1 m: steps of 1 m between the values below are far from the spike slope (3).
  std::vector<double> z = {nan, nan, 1.0, nan, nan, 2.5, 2.0, nan, std::numeric_limits<double>::infinity(), nan};
  const CleaningReport report = clean_profile(z, 1.0);
  EXPECT_EQ(report.dropouts, 7u);
  EXPECT_EQ(report.spikes, 0u);
  const std::vector<double> expected = {1.0, 1.0, 1.0, 1.5, 2.0, 2.5, 2.0, 2.0, 2.0, 2.0};
  ASSERT_EQ(z.size(), expected.size());
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_DOUBLE_EQ(z[i], expected[i]) << i;
}

TEST(ProfileCleaning, ASpikeIsRemovedAndItsNeighboursAreKept) {
  // Spacing 0.5 mm: the spike threshold is |Δz| >= 3 · 0.5 mm = 1.5 mm between neighbours.
  const double dx = 0.5e-3;
  std::vector<double> z = {0.0, 0.1e-3, 0.2e-3, 5.0e-3, 0.4e-3, 0.5e-3, 0.6e-3};
  const CleaningReport report = clean_profile(z, dx);
  // The 5 mm value makes steps of 4.8 and 4.6 mm to both neighbours. The rule marks both ends
  // of each step: samples 2, 3 and 4, and refills them from samples 1 and 5.
  EXPECT_EQ(report.spikes, 3u);
  EXPECT_EQ(report.dropouts, 0u);
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_NEAR(z[i], 0.1e-3 * static_cast<double>(i), 1e-15) << i;
}

TEST(ProfileCleaning, AStepJustBelowTheThresholdIsTexture) {
  const double dx = 1e-3;
  std::vector<double> z = {0.0, 0.0, 2.99e-3, 2.99e-3};  // slope 2.99 < 3
  EXPECT_EQ(clean_profile(z, dx).spikes, 0u);
  std::vector<double> steeper = {0.0, 0.0, 3.01e-3, 3.01e-3};
  EXPECT_EQ(clean_profile(steeper, dx).spikes, 2u);
}

TEST(ProfileCleaning, SpikesAcrossADropoutUseTheDistanceBetweenValidSamples) {
  // 2 mm over a gap of 2 samples (1 mm at 0.5 mm): slope 2, not a spike.
  std::vector<double> z = {0.0, nan, 2e-3};
  const CleaningReport report = clean_profile(z, 0.5e-3);
  EXPECT_EQ(report.spikes, 0u);
  EXPECT_EQ(report.dropouts, 1u);
  EXPECT_DOUBLE_EQ(z[1], 1e-3);
}

TEST(ProfileCleaning, AllDropoutsIsAnInputError) {
  std::vector<double> z(100, nan);
  try {
    clean_profile(z, 1e-3);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "profile");
  }
  std::vector<double> empty;
  EXPECT_THROW(clean_profile(empty, 1e-3), InputError);
}

TEST(ProfileCleaning, BadSpacingIsAnInputError) {
  for (double spacing : {0.0, -1e-3, nan, std::numeric_limits<double>::infinity()}) {
    std::vector<double> z = {0.0, 1.0};
    try {
      clean_profile(z, spacing);
      FAIL() << spacing;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "spacing");
    }
  }
}

}  // namespace
}  // namespace rollnoise
