// clean_profile: dropouts and spikes of a measured profile (ISO 13473-1:2019 §7.3, §7.5): the
// spike criterion judged at the 0.5 mm scale of the evaluated profile (profile_cleaning.hpp).
// Every threshold is written in terms of α (spike_slope_threshold) and the 0.5 mm scale, so the
// tests check the rule whatever α is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/profile_cleaning.hpp"

namespace rollnoise {
namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double alpha = spike_slope_threshold;
// The smallest height step that is a spike at the 0.5 mm scale: α · 0.5 mm.
const double step_limit = spike_slope_threshold * mpd_resample_spacing_m;

TEST(ProfileCleaning, DropoutsAreInterpolatedLinearlyAndEndsTakeTheNearestValue) {
  // Spacing 1 m: the steps below (at most 0.5 m per metre) are far from the spike slope α.
  static_assert(spike_slope_threshold > 1.0);
  std::vector<double> z = {nan, nan, 1.0, nan, nan, 2.5, 2.0, nan, std::numeric_limits<double>::infinity(), nan};
  const CleaningReport report = clean_profile(z, 1.0);
  EXPECT_EQ(report.dropouts, 7u);
  EXPECT_EQ(report.spikes, 0u);
  const std::vector<double> expected = {1.0, 1.0, 1.0, 1.5, 2.0, 2.5, 2.0, 2.0, 2.0, 2.0};
  ASSERT_EQ(z.size(), expected.size());
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_DOUBLE_EQ(z[i], expected[i]) << i;
}

TEST(ProfileCleaning, ASpikeIsRemovedAndItsNeighboursAreKept) {
  // Spacing 0.5 mm (the evaluated profile's own: judged sample by sample): the spike threshold
  // is |Δz| >= α · 0.5 mm between neighbours.
  const double dx = 0.5e-3;
  std::vector<double> z = {0.0, 0.1e-3, 0.2e-3, 0.3e-3 + 2 * step_limit, 0.4e-3, 0.5e-3, 0.6e-3};
  const CleaningReport report = clean_profile(z, dx);
  // The raised value makes steps of about twice the threshold to both neighbours. The rule
  // marks both ends of each step: samples 2, 3 and 4, and refills them from samples 1 and 5.
  EXPECT_EQ(report.spikes, 3u);
  EXPECT_EQ(report.dropouts, 0u);
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_NEAR(z[i], 0.1e-3 * static_cast<double>(i), 1e-15) << i;
}

TEST(ProfileCleaning, AStepJustBelowTheThresholdIsTexture) {
  // Spacing 1 mm (coarser than 0.5 mm: judged sample by sample, |Δz| >= α · Δx).
  const double dx = 1e-3;
  const double below = 0.97 * alpha * dx, above = 1.03 * alpha * dx;  // slopes 0.97 α and 1.03 α
  std::vector<double> z = {0.0, 0.0, below, below};
  EXPECT_EQ(clean_profile(z, dx).spikes, 0u);
  std::vector<double> steeper = {0.0, 0.0, above, above};
  EXPECT_EQ(clean_profile(steeper, dx).spikes, 2u);
}

TEST(ProfileCleaning, SpikesAcrossADropoutUseTheDistanceBetweenValidSamples) {
  // A step of 1.5 α · 0.5 mm: a spike between neighbours 0.5 mm apart (slope 1.5 α), not across
  // a dropout, 1 mm between the valid samples (slope 0.75 α).
  const double step = 1.5 * step_limit;
  std::vector<double> z = {0.0, nan, step};
  const CleaningReport report = clean_profile(z, 0.5e-3);
  EXPECT_EQ(report.spikes, 0u);
  EXPECT_EQ(report.dropouts, 1u);
  EXPECT_DOUBLE_EQ(z[1], step / 2);
  std::vector<double> adjacent = {0.0, step, step};
  EXPECT_EQ(clean_profile(adjacent, 0.5e-3).spikes, 2u);
}

// --- Profiles finer than 0.5 mm: the criterion at the 0.5 mm scale -------------------------
const double laser_dx = 0.0375e-3;  // the CAPTIF laser's step

// A stone-edge sawtooth of height 0.8 α · 0.5 mm (1.2 mm for α = 3, 2.4 mm for α = 6): rises
// over 4 samples (0.15 mm: slope 8/3 α, steeper than α at the laser's spacing), falls back over
// 36 samples (slope 0.3 α); period 40 samples (1.5 mm).
const double tooth = 0.8 * step_limit;
std::vector<double> sawtooth(std::size_t n) {
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = i % 40;
    z[i] = k < 4 ? tooth * static_cast<double>(k) / 4.0 : tooth * (1.0 - static_cast<double>(k - 4) / 36.0);
  }
  return z;
}

TEST(ProfileCleaning, SteepTextureAtTheLaserSpacingLosesNoPoint) {
  // Every rising step is 0.2 α · 0.5 mm between neighbours 0.0375 mm apart (slope 8/3 α: a spike
  // to a criterion applied at the data's spacing, α x 0.0375 mm). At the 0.5 mm scale the steps
  // between bin means are at most the tooth's height, 0.8 α · 0.5 mm, below α · 0.5 mm.
  const std::vector<double> original = sawtooth(4000);  // 150 mm
  std::vector<double> z = original;
  const CleaningReport report = clean_profile(z, laser_dx);
  EXPECT_EQ(report.spikes, 0u);
  EXPECT_EQ(report.dropouts, 0u);
  EXPECT_EQ(z, original);
  // The criterion at the data's spacing (α x 0.0375 mm) would have taken every stone edge.
  std::size_t steep = 0;
  for (std::size_t i = 1; i < original.size(); ++i) steep += std::abs(original[i] - original[i - 1]) >= alpha * laser_dx;
  EXPECT_EQ(steep, 4000u / 40 * 4);  // the 4 rising steps of every tooth
}

TEST(ProfileCleaning, ASingleReadingJumpingSeveralMillimetresIsStillASpike) {
  // The sawtooth with one reading 2.5 α · 0.5 mm too high: it steps by more than α · 0.5 mm
  // from both neighbours, so it and its two neighbours (both ends of each step) are replaced;
  // averaged into its 0.5 mm bin (13 readings) it would only be a bump of 0.19 α · 0.5 mm,
  // which captif-slp would keep.
  const std::vector<double> original = sawtooth(4000);
  std::vector<double> z = original;
  const std::size_t at = 2010;  // in a falling flank
  z[at] += 2.5 * step_limit;
  const CleaningReport report = clean_profile(z, laser_dx);
  EXPECT_EQ(report.spikes, 3u);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (i + 1 < at || i > at + 1) {
      ASSERT_EQ(z[i], original[i]) << i;  // the stone edges all stay
    }
  }
  // Refilled on the line between at - 2 and at + 2, which is the flank itself.
  for (std::size_t i = at - 1; i <= at + 1; ++i) EXPECT_NEAR(z[i], original[i], 1e-15) << i;
  // A reading stepping by just under α · 0.5 mm from both neighbours is texture; by just over,
  // a spike (raised by 0.97 and 1.03 times α · 0.5 mm: the flank falls 0.022 α · 0.5 mm per
  // sample, so the steps are 0.95 to 0.99 and 1.01 to 1.05 times the threshold).
  std::vector<double> below = sawtooth(4000), above = sawtooth(4000);
  below[at] += 0.97 * step_limit;
  above[at] += 1.03 * step_limit;
  EXPECT_EQ(clean_profile(below, laser_dx).spikes, 0u);
  EXPECT_EQ(clean_profile(above, laser_dx).spikes, 3u);
}

// A face on a flat profile sampled at 0.05 mm, where the 0.5 mm bins hold 10 samples each
// (bin k: samples 10k .. 10k + 9): rising by `rise` per sample over samples 100..119, flat at
// 20 · rise from there. It fills bins 10 and 11, whose means (5.5 and 15.5 · rise) step by
// 10 · rise; their neighbours step by 5.5 and 4.5 · rise.
const double face_dx = 0.05e-3;
std::vector<double> face(double rise) {
  std::vector<double> z(300, 0.0);
  for (std::size_t i = 100; i < z.size(); ++i) z[i] = std::min(rise * static_cast<double>(i - 99), 20 * rise);
  return z;
}

TEST(ProfileCleaning, AFaceSteepAtTheHalfMillimetreScaleIsASpikeThoughNoSingleReadingIs) {
  // rise = 2/15 α · 0.5 mm (0.2 mm for α = 3, 0.4 mm for α = 6): the means of bins 10 and 11
  // step by 1.33 α · 0.5 mm: both bins are spikes, as in captif-slp's test on the resampled
  // profile (their neighbours step by 0.73 and 0.6 α · 0.5 mm: kept). No single reading steps by
  // α · 0.5 mm.
  const double rise = 2.0 / 15.0 * step_limit;
  std::vector<double> z = face(rise);
  const std::vector<double> original = z;
  const CleaningReport report = clean_profile(z, face_dx);
  EXPECT_EQ(report.spikes, 20u);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (i < 100 || i >= 120) {
      EXPECT_EQ(z[i], original[i]) << i;
    } else {
      EXPECT_NEAR(z[i], 20 * rise * static_cast<double>(i - 99) / 21.0, 1e-15) << i;  // sample 99 to 120
    }
  }
  // Bin means stepping by just under α · 0.5 mm are texture; by just over, spikes.
  std::vector<double> below = face(0.097 * step_limit), above = face(0.103 * step_limit);
  EXPECT_EQ(clean_profile(below, face_dx).spikes, 0u);
  EXPECT_EQ(clean_profile(above, face_dx).spikes, 20u);
}

TEST(ProfileCleaning, DropoutsInAMarkedBinStayDropouts) {
  // The face above with two readings missing in it: they are filled and counted as dropouts,
  // the other 18 samples of the two bins as spikes.
  std::vector<double> z = face(2.0 / 15.0 * step_limit);
  const double dx = face_dx;
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
