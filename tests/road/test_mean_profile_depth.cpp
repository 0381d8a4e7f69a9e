// mean_profile_depth (ISO 13473-1:2019) on profiles whose MPD follows from the definition.
//
// The standard's low pass (mean_profile_depth.hpp) is a 2nd-order Butterworth made digital by the
// pre-warped bilinear transform and run forward and backward; on a sampled sinusoid of
// wavelength λ at spacing Δ it acts, away from the ends, as the exact gain
//   G(λ, Δ) = 1 / (1 + (tan(πΔ/λ) / tan(πΔ/λc))^4),  λc = 2.4 mm,
// without shifting its phase. The tests below predict the MPD from that and the definition
// (peak of each 50 mm half, minus the mean level, after slope suppression).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <algorithm>
#include <vector>

#include "core/error.hpp"
#include "road/mean_profile_depth.hpp"

namespace rollnoise {
namespace {

constexpr double pi = std::numbers::pi;

double lowpass_gain(double wavelength, double spacing) {
  const double r = std::tan(pi * spacing / wavelength) / std::tan(pi * spacing / mpd_lowpass_cutoff_m);
  return 1.0 / (1.0 + std::pow(r, 4));
}

// A cos(2π(x - 50 mm)/λ) with sample i standing for [iΔ, (i+1)Δ), at its centre x = (i + ½)Δ.
// For λ dividing 100 mm, each segment is then symmetric about its centre (x = 50 mm + k·100 mm),
// so the slope suppression's least-squares line is exactly flat and the mean level 0: a
// sinusoid at any other phase would leave a line of up to 3λ/(πL)·A = 0.48 A at the ends of
// a segment L = 100 mm long (λ = 50 mm), and the MSD would no longer be its amplitude.
std::vector<double> centred_cosine(double amplitude, double wavelength, double spacing, std::size_t n) {
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (static_cast<double>(i) + 0.5) * spacing;
    z[i] = amplitude * std::cos(2.0 * pi * (x - 0.05) / wavelength);
  }
  return z;
}

// The standard's steps 3–6 written out for a profile already filtered: 100 mm segments of
// `per_segment` samples, least-squares line removed, peak of each half, minus the mean level.
double mpd_of_filtered(const std::vector<double>& g, std::size_t per_segment) {
  const std::size_t segments = g.size() / per_segment;
  double sum = 0.0;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t m = per_segment;
    double st = 0, sz = 0, stt = 0, stz = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const double t = static_cast<double>(i);
      const double v = g[s * m + i];
      st += t; sz += v; stt += t * t; stz += t * v;
    }
    const double md = static_cast<double>(m);
    const double slope = (md * stz - st * sz) / (md * stt - st * st);
    const double offset = (sz - slope * st) / md;
    double peak1 = -1e300, peak2 = -1e300, mean = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      const double r = g[s * m + i] - offset - slope * static_cast<double>(i);
      mean += r / md;
      if (i < m / 2) peak1 = std::max(peak1, r);
      else peak2 = std::max(peak2, r);
    }
    sum += 0.5 * (peak1 + peak2) - mean;
  }
  return sum / static_cast<double>(segments);
}

TEST(MeanProfileDepth, SineIsExactToTheDefinition) {
  // A sin(2πx/λ) at x = iΔ, i = 0 … n with n a whole number of segments: both ends are zero
  // crossings, which the filter's odd reflection continues exactly, so the filtered profile is
  // A·G·sin(2πx/λ) everywhere. The MPD must be the definition applied to that (with the extra
  // last sample left out as the rest beyond the last whole segment).
  for (const auto& [spacing, wavelength] : {std::pair{0.5e-3, 25e-3}, {0.5e-3, 10e-3}, {1e-3, 12.5e-3}, {1e-3, 50e-3}}) {
    const double amplitude = 1.3e-3;
    const auto per_segment = static_cast<std::size_t>(std::llround(mpd_segment_length_m / spacing));
    const std::size_t n = 4 * per_segment;
    std::vector<double> z(n + 1), filtered(n);
    const double gain = lowpass_gain(wavelength, spacing);
    for (std::size_t i = 0; i <= n; ++i) {
      z[i] = amplitude * std::sin(2 * pi * static_cast<double>(i) * spacing / wavelength);
      if (i < n) filtered[i] = gain * z[i];
    }
    const MpdResult r = mean_profile_depth(z, spacing);
    EXPECT_EQ(r.segments, 4u);
    // Left: rounding (~1e-16 relative, a few hundred operations) and the filter's start-up
    // transient, decayed to < 1e-10 of its size over the 64 samples of padding.
    EXPECT_NEAR(r.mpd_m, mpd_of_filtered(filtered, per_segment), 1e-9 * amplitude)
        << spacing << " " << wavelength;
  }
}

TEST(MeanProfileDepth, CosineCentredOnEachSegmentGivesItsAmplitude) {
  // Δ = 1 mm, λ = 12.5 mm (8 per segment): the crests at 12.5, 37.5, 62.5, 87.5 mm are the
  // centres of samples 12, 37, 62, 87 and each segment is symmetric about its centre: the
  // slope suppression removes nothing, the mean level is 0, each half's peak is +A·G, so
  // MSD = A·G, and MPD too.
  //
  // Tolerance: the profile ends on a crest, where the filter's odd reflection turns the
  // curvature over; the transient of that step (~2 % of A, decaying by 0.69 per sample) shifts
  // the mean level and the slope of the first and last segments slightly: 1e-4·A bounds it
  // (measured: 2e-6 here, 3e-5 below), below the filter's effect 1 - G = 2.2e-5 ... 6.5e-5
  // only by a small factor, but far below the sampled-crest factor cos(πΔ/λ) = 1 - 2e-3 below.
  {
    const double amplitude = 1.5e-3;
    const double spacing = 1e-3;
    const double wavelength = 12.5e-3;
    const auto z = centred_cosine(amplitude, wavelength, spacing, 500);  // 5 segments
    const MpdResult r = mean_profile_depth(z, spacing);
    EXPECT_EQ(r.segments, 5u);
    EXPECT_DOUBLE_EQ(r.spacing_m, spacing);
    EXPECT_NEAR(r.mpd_m, amplitude * lowpass_gain(wavelength, spacing), 1e-4 * amplitude);
    EXPECT_NEAR(r.etd_m, 0.2e-3 + 0.8 * r.mpd_m, 1e-18);
  }
  {
    // Δ = 0.5 mm (the standard's recommended interval), λ = 25 mm: the crests at 25 and 75 mm
    // sit halfway between two sample centres (24.75, 25.25 mm), which see A·G·cos(πΔ/λ).
    const double amplitude = 0.8e-3;
    const double spacing = 0.5e-3;
    const double wavelength = 25e-3;
    const auto z = centred_cosine(amplitude, wavelength, spacing, 800);  // 4 segments
    const MpdResult r = mean_profile_depth(z, spacing);
    EXPECT_EQ(r.segments, 4u);
    const double expected = amplitude * lowpass_gain(wavelength, spacing) * std::cos(pi * spacing / wavelength);
    EXPECT_NEAR(r.mpd_m, expected, 1e-4 * amplitude);
  }
}

TEST(MeanProfileDepth, UnchangedByAnOffsetAndALinearTrend) {
  // A profile with texture at many wavelengths; then + 7 mm offset + a slope of 2 %.
  const double spacing = 0.5e-3;
  std::vector<double> z(1000);  // 5 segments
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double x = static_cast<double>(i) * spacing;
    z[i] = 1e-3 * std::sin(2 * pi * x / 13e-3) + 0.4e-3 * std::sin(2 * pi * x / 4.1e-3 + 1) +
           0.7e-3 * std::cos(2 * pi * x / 37e-3);
  }
  std::vector<double> tilted = z;
  for (std::size_t i = 0; i < z.size(); ++i) tilted[i] += 7e-3 + 0.02 * static_cast<double>(i) * spacing;
  const double mpd = mean_profile_depth(z, spacing).mpd_m;
  EXPECT_GT(mpd, 0.5e-3);
  // The filter passes a line unchanged (DC gain 1, zero phase, line-preserving reflection at
  // the ends) and the slope suppression removes it: only rounding of heights of ~10 mm is left.
  EXPECT_NEAR(mean_profile_depth(tilted, spacing).mpd_m, mpd, 1e-12);
  // The same at a spacing that is resampled (0.1 mm -> 0.5 mm bins: averages of a line are a line).
  std::vector<double> fine(5000), fine_tilted(5000);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const double x = static_cast<double>(i) * 0.1e-3;
    fine[i] = 1e-3 * std::sin(2 * pi * x / 13e-3);
    fine_tilted[i] = fine[i] - 3e-3 - 0.05 * x;
  }
  EXPECT_NEAR(mean_profile_depth(fine_tilted, 0.1e-3).mpd_m, mean_profile_depth(fine, 0.1e-3).mpd_m, 1e-12);
}

TEST(MeanProfileDepth, IndependentOfTheSpacingWithinTheStandardsRange) {
  // A centred 50 mm cosine (one peak per half) of amplitude A over 1 m, at spacings from the laser's
  // 0.0375 mm (resampled to 0.5 mm bins) to the coarsest allowed, 1 mm. Every result is A up to
  //  - the sampled peak: at worst half a sample off the crest, cos(π · 1 mm / 50 mm) = 1 - 2.0e-3;
  //  - the bin average: 1 - (π · 0.5/50)²/6 = 1 - 1.6e-4;
  //  - the filter: 1 - G(50 mm, Δ) < 5e-6.
  // So all agree with A within 2.5e-3 relative.
  const double amplitude = 2e-3;
  for (double spacing : {0.0375e-3, 0.1e-3, 0.25e-3, 0.5e-3, 0.8e-3, 1e-3}) {
    const auto n = static_cast<std::size_t>(std::llround(1.0 / spacing));
    const auto z = centred_cosine(amplitude, 50e-3, spacing, n);
    const MpdResult r = mean_profile_depth(z, spacing);
    EXPECT_EQ(r.segments, 10u) << spacing;
    EXPECT_NEAR(r.mpd_m, amplitude, 2.5e-3 * amplitude) << spacing;
    EXPECT_DOUBLE_EQ(r.spacing_m, std::max(spacing, mpd_resample_spacing_m)) << spacing;
  }
}

TEST(MeanProfileDepth, TheRestBeyondTheLastWholeSegmentIsLeftOut) {
  const double spacing = 0.5e-3;
  EXPECT_EQ(mean_profile_depth(std::vector<double>(200, 0.0), spacing).segments, 1u);  // exactly 100 mm
  EXPECT_EQ(mean_profile_depth(std::vector<double>(399, 0.0), spacing).segments, 1u);
  EXPECT_EQ(mean_profile_depth(std::vector<double>(400, 0.0), spacing).segments, 2u);
  EXPECT_DOUBLE_EQ(mean_profile_depth(std::vector<double>(400, 1.0), spacing).mpd_m, 0.0);
}

TEST(MeanProfileDepth, BadInputIsAnInputError) {
  auto key_of = [](std::vector<double> z, double spacing) -> std::string {
    try {
      mean_profile_depth(z, spacing);
    } catch (const InputError& e) {
      return e.key();
    }
    return "no error";
  };
  EXPECT_EQ(key_of(std::vector<double>(199, 0.0), 0.5e-3), "profile");  // 99.5 mm: shorter than a segment
  EXPECT_EQ(key_of({}, 0.5e-3), "profile");
  EXPECT_EQ(key_of(std::vector<double>(2666, 0.0), 0.0375e-3), "profile");  // 99.98 mm
  std::vector<double> with_nan(400, 0.0);
  with_nan[17] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(key_of(with_nan, 0.5e-3), "profile");
  for (double spacing : {0.0, -0.5e-3, 1.01e-3, std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(key_of(std::vector<double>(400, 0.0), spacing), "spacing") << spacing;
  }
}

}  // namespace
}  // namespace rollnoise
