// The ISO 8608 road (type = "iso8608", iso8608_road.hpp) against the class it is made from: the
// displacement PSD by unevenness_psd (Welch), per octave band of the standard's range and as a
// fitted G_d(n0) and slope; determinism; the same profile on every line of a 2-D road; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "road/iso8608_road.hpp"
#include "road/sampled_road.hpp"
#include "road/unevenness_psd.hpp"
#include "road_generator_helpers.hpp"

namespace rollnoise {
namespace {

const SampledProfile& as_line(const RoadProfile& p) { return dynamic_cast<const SampledProfile&>(p); }

// Mean over 8 seeds of the Welch PSD of 2 km of class `cls`: per octave band of n (centres
// 0.0156 .. 2 cycles/m, edges a factor sqrt 2 either side, within 0.011 .. 2.83), the band mean
// of the estimate against the band mean of the target at the same frequencies; then a
// least-squares line through the band means in log-log gives G_d(n0) and w.
void check_class(const std::string& road_keys, double gd_n0, double w, const char* what) {
  std::vector<double> n;
  std::vector<double> mean_gd;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto road = test::profile_from(road_keys + "\nlength = 2000.0\nlead_in = 0.0\nseed = " + std::to_string(seed));
    const SampledProfile& p = as_line(*road);
    const UnevennessPsd psd = unevenness_psd(p.samples(), p.spacing());
    if (n.empty()) {
      n = psd.n;
      mean_gd.assign(n.size(), 0.0);
    }
    for (std::size_t k = 0; k < n.size(); ++k) mean_gd[k] += psd.gd[k] / seeds;
  }
  double worst = 0.0;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int bands = 0;
  for (double centre = 1.0 / 64.0; centre < 2.1; centre *= 2.0) {
    const double lo = std::max(centre / std::sqrt(2.0), Iso8608RoadSpec::n_low);
    const double hi = std::min(centre * std::sqrt(2.0), Iso8608RoadSpec::n_high);
    double estimate = 0.0, target = 0.0;
    int bins = 0;
    for (std::size_t k = 0; k < n.size(); ++k) {
      // Bins 1 and 2 of a Welch segment lie in the window's main lobe around the removed trend.
      if (n[k] < lo || n[k] >= hi || n[k] < 3.0 * n[0]) continue;
      estimate += mean_gd[k];
      target += gd_n0 * std::pow(n[k] / 0.1, -w);
      ++bins;
    }
    if (bins == 0) continue;
    const double error = 10.0 * std::log10(estimate / target);
    std::printf("  %s  octave %.4f cycles/m (%d bins)  error %+5.2f dB\n", what, centre, bins, error);
    worst = std::max(worst, std::abs(error));
    const double x = std::log10(centre / 0.1);
    const double y = std::log10(estimate / bins);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++bands;
  }
  const double slope = (bands * sxy - sx * sy) / (bands * sxx - sx * sx);
  const double fitted_gd_n0 = std::pow(10.0, (sy - slope * sx) / bands);
  std::printf("  %s  max |band error| %.2f dB; fit: G_d(n0) = %.4g m^3 (class %.4g, %+.2f dB), w = %.3f\n", what,
              worst, fitted_gd_n0, gd_n0, 10.0 * std::log10(fitted_gd_n0 / gd_n0), -slope);
  EXPECT_GE(bands, 7);
  EXPECT_LE(worst, 1.0) << what;
  EXPECT_NEAR(10.0 * std::log10(fitted_gd_n0 / gd_n0), 0.0, 1.0) << what;
  EXPECT_NEAR(-slope, w, 0.1) << what;
}

TEST(Iso8608Road, ClassCHasItsSpectrum) { check_class("type = \"iso8608\"\nclass = \"C\"", 256e-6, 2.0, "class C"); }

TEST(Iso8608Road, ClassAHasItsSpectrum) { check_class("type = \"iso8608\"\nclass = \"A\"", 16e-6, 2.0, "class A"); }

TEST(Iso8608Road, ExplicitGdAndWaviness) {
  check_class("type = \"iso8608\"\ngd_n0 = 1e-4\nwaviness = 2.5", 1e-4, 2.5, "gd_n0 1e-4, w 2.5");
}

TEST(Iso8608Road, AnalysisClassifiesTheGeneratedRoad) {
  for (const char* cls : {"A", "D", "H"}) {
    const auto road = test::profile_from(std::string("type = \"iso8608\"\nclass = \"") + cls + "\"\nlength = 2000.0\n");
    const SampledProfile& p = as_line(*road);
    EXPECT_EQ(unevenness_psd(p.samples(), p.spacing()).iso8608_class, cls);
  }
}

TEST(Iso8608Road, SameSeedIdenticalOtherSeedDiffersFlatLeadIn) {
  const auto a = test::profile_from("type = \"iso8608\"\nclass = \"B\"\nseed = 3");
  const auto b = test::profile_from("type = \"iso8608\"\nclass = \"B\"\nseed = 3");
  const auto c = test::profile_from("type = \"iso8608\"\nclass = \"B\"\nseed = 4");
  EXPECT_EQ(as_line(*a).samples(), as_line(*b).samples());
  EXPECT_NE(as_line(*a).samples(), as_line(*c).samples());
  EXPECT_EQ(a->type(), "iso8608");
  EXPECT_EQ(a->height(-3.0), 0.0);
  EXPECT_EQ(a->height(0.0), 0.0);
  EXPECT_GE(as_line(*a).end(), 100.0);  // the default length
  // A run shorter than `length` sees the same road.
  const auto shorter = test::profile_from("type = \"iso8608\"\nclass = \"B\"\nseed = 3", 30.0);
  for (double x : {0.5, 11.0, 29.9}) EXPECT_EQ(shorter->height(x), a->height(x));
}

TEST(Iso8608Road, SameProfileOnEveryLineOfASurface) {
  const auto surface = test::surface_from("type = \"iso8608\"\nclass = \"D\"\nseed = 9", 50.0, 0.15);
  const auto profile = test::profile_from("type = \"iso8608\"\nclass = \"D\"\nseed = 9", 50.0);
  for (double x : {-1.0, 0.0, 3.3, 20.0, 49.0}) {
    for (double y : {-0.15, 0.0, 0.1}) EXPECT_EQ(surface->height(x, y), profile->height(x));
  }
}

TEST(Iso8608Road, BadInputNamesTheKey) {
  std::string m = test::profile_error("type = \"iso8608\"\nclass = \"Z\"");
  EXPECT_MENTIONS(m, "[road] class");
  m = test::profile_error("type = \"iso8608\"");
  EXPECT_MENTIONS(m, "[road] class");
  m = test::profile_error("type = \"iso8608\"\nclass = \"A\"\ngd_n0 = 1e-5");
  EXPECT_MENTIONS(m, "[road] gd_n0");
  m = test::profile_error("type = \"iso8608\"\nclass = \"A\"\nwaviness = 2.5");
  EXPECT_MENTIONS(m, "[road] waviness");
  m = test::profile_error("type = \"iso8608\"\ngd_n0 = -1e-5");
  EXPECT_MENTIONS(m, "[road] gd_n0");
  m = test::profile_error("type = \"iso8608\"\ngd_n0 = 1e-5\nwaviness = 0.0");
  EXPECT_MENTIONS(m, "[road] waviness");
  m = test::profile_error("type = \"iso8608\"\nclass = \"A\"\nsample_spacing = 0.2");
  EXPECT_MENTIONS(m, "[road] sample_spacing");
  EXPECT_MENTIONS(m, "2.83");
  m = test::profile_error("type = \"iso8608\"\nclass = \"A\"\nwidth = 0.2");
  EXPECT_MENTIONS(m, "width");  // unknown for this type
}

}  // namespace
}  // namespace rollnoise
