// clean_profile: dropouts and spikes of a measured profile (ISO 13473-1:2019 §7.3, §7.5): the
// spike criterion judged at the 0.5 mm scale of the evaluated profile (profile_cleaning.hpp).
#include <gtest/gtest.h>

#include <algorithm>
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
  // Spacing 0.5 mm (the evaluated profile's own: judged sample by sample): the spike threshold is |Δz| >= 3 · 0.5 mm = 1.5 mm between neighbours.
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

// --- Profiles finer than 0.5 mm: the criterion at the 0.5 mm scale -------------------------
const double laser_dx = 0.0375e-3;  // the CAPTIF laser's step

// A stone-edge sawtooth: rises 1.2 mm over 4 samples (0.15 mm: slope 8, steeper than 3 at the
// laser's spacing), falls back over 36 samples (slope 0.9); period 40 samples (1.5 mm).
std::vector<double> sawtooth(std::size_t n) {
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = i % 40;
    z[i] = k < 4 ? 1.2e-3 * static_cast<double>(k) / 4.0 : 1.2e-3 * (1.0 - static_cast<double>(k - 4) / 36.0);
  }
  return z;
}

TEST(ProfileCleaning, SteepTextureAtTheLaserSpacingLosesNoPoint) {
  // Every rising step is 0.3 mm between neighbours 0.0375 mm apart (slope 8: a spike to a
  // criterion applied at the data's spacing, 3 x 0.0375 mm = 0.11 mm). At the 0.5 mm scale the
  // steps between bin means are at most the 1.2 mm height, below 3 x 0.5 mm = 1.5 mm.
  const std::vector<double> original = sawtooth(4000);  // 150 mm
  std::vector<double> z = original;
  const CleaningReport report = clean_profile(z, laser_dx);
  EXPECT_EQ(report.spikes, 0u);
  EXPECT_EQ(report.dropouts, 0u);
  EXPECT_EQ(z, original);
  // The criterion as it was (3 x the data's spacing) would have taken every stone edge.
  std::size_t steep = 0;
  for (std::size_t i = 1; i < original.size(); ++i) steep += std::abs(original[i] - original[i - 1]) >= 3 * laser_dx;
  EXPECT_EQ(steep, 4000u / 40 * 4);  // the 4 rising steps of every tooth
}

TEST(ProfileCleaning, ASingleReadingJumpingSeveralMillimetresIsStillASpike) {
  // The sawtooth with one reading 4 mm too high: it steps by more than 3 x 0.5 mm from both
  // neighbours, so it and its two neighbours (both ends of each step) are replaced; averaged
  // into its 0.5 mm bin it would only be a 0.3 mm bump, which captif-slp would keep.
  const std::vector<double> original = sawtooth(4000);
  std::vector<double> z = original;
  const std::size_t at = 2010;  // in a falling flank
  z[at] += 4e-3;
  const CleaningReport report = clean_profile(z, laser_dx);
  EXPECT_EQ(report.spikes, 3u);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (i + 1 < at || i > at + 1) {
      ASSERT_EQ(z[i], original[i]) << i;  // the stone edges all stay
    }
  }
  // Refilled on the line between at - 2 and at + 2, which is the flank itself.
  for (std::size_t i = at - 1; i <= at + 1; ++i) EXPECT_NEAR(z[i], original[i], 1e-15) << i;
  // A reading stepping by just under 1.5 mm from both neighbours is texture; by just over, a
  // spike (raised by 1.45 and 1.55 mm: the flank falls 0.033 mm per sample).
  std::vector<double> below = sawtooth(4000), above = sawtooth(4000);
  below[at] += 1.45e-3;
  above[at] += 1.55e-3;
  EXPECT_EQ(clean_profile(below, laser_dx).spikes, 0u);
  EXPECT_EQ(clean_profile(above, laser_dx).spikes, 3u);
}

TEST(ProfileCleaning, AFaceSteeperThanThreeOverAMillimetreIsASpikeAtTheHalfMillimetreScale) {
  // At 0.05 mm the 0.5 mm bins hold 10 samples each (bin k: samples 10k .. 10k + 9). A face
  // rising 4 mm over samples 100..119 (0.2 mm per sample, slope 4) fills bins 10 and 11, whose
  // means (1.1 and 3.1 mm) step by 2 mm >= 1.5 mm: both bins are spikes, as in captif-slp's test
  // on the resampled profile (its neighbours step by 1.1 and 0.9 mm: kept). No single reading
  // steps by 1.5 mm.
  const double dx = 0.05e-3;
  std::vector<double> z(300, 0.0);
  for (std::size_t i = 100; i < z.size(); ++i) z[i] = std::min(0.2e-3 * static_cast<double>(i - 99), 4e-3);
  const std::vector<double> original = z;
  const CleaningReport report = clean_profile(z, dx);
  EXPECT_EQ(report.spikes, 20u);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (i < 100 || i >= 120) {
      EXPECT_EQ(z[i], original[i]) << i;
    } else {
      EXPECT_NEAR(z[i], 4e-3 * static_cast<double>(i - 99) / 21.0, 1e-15) << i;  // sample 99 to 120
    }
  }
}

TEST(ProfileCleaning, DropoutsInAMarkedBinStayDropouts) {
  // The face above with two readings missing in it: they are filled and counted as dropouts,
  // the other 18 samples of the two bins as spikes.
  const double dx = 0.05e-3;
  std::vector<double> z(300, 0.0);
  for (std::size_t i = 100; i < z.size(); ++i) z[i] = std::min(0.2e-3 * static_cast<double>(i - 99), 4e-3);
  z[105] = nan;
  z[112] = nan;
  const CleaningReport report = clean_profile(z, dx);
  EXPECT_EQ(report.dropouts, 2u);
  EXPECT_EQ(report.spikes, 18u);
  for (double v : z) EXPECT_TRUE(std::isfinite(v));
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
