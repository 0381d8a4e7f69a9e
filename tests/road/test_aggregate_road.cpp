// The aggregate road (type = "aggregate", aggregate_road.hpp): the chip-seal calibration against
// the two measured CAPTIF texture profiles (MPD per ISO 13473-1, third-octave texture levels per
// ISO 13473-4), positive and negative texture, the 2-D map and its lines, determinism, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "road/laser_profile.hpp"
#include "road/mean_profile_depth.hpp"
#include "road/sampled_road.hpp"
#include "road_generator_helpers.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;
using test::BandAverage;

const SampledProfile& as_line(const RoadProfile& p) { return dynamic_cast<const SampledProfile&>(p); }
const SampledSurface& as_map(const RoadSurface& s) { return dynamic_cast<const SampledSurface&>(s); }

// The measured profiles: the shared data set, else the copy in the repository.
fs::path captif_dir() {
  for (const fs::path& dir : {fs::path(ROLLNOISE_SOURCE_DIR) / ".." / "shared" / "data" / "texture" / "captif",
                              fs::path(ROLLNOISE_SOURCE_DIR) / "data" / "surfaces" / "captif"}) {
    if (fs::exists(dir / "20211011_aylesbury_dec_station_0.dat")) return dir;
  }
  return {};
}

// The calibration (docs/road_aggregate_model.md): a grade 3/4 chip, max_chip_size 13.2 mm; every
// other key at its default (min_chip_size 3.3 mm, grading_exponent 0.5, shape_factor 0.7,
// elongation 1, coverage 0.85, binder_level 0.1, texture "positive").
const std::string chip_seal = "type = \"aggregate\"\nmax_chip_size = 0.0132\n";

TEST(AggregateRoad, ChipSealCalibrationReproducesTheCaptifProfiles) {
  const fs::path dir = captif_dir();
  if (dir.empty()) GTEST_SKIP() << "no CAPTIF profiles (../shared/data/texture/captif or data/surfaces/captif)";
  std::vector<MeasuredProfile> measured;
  for (const char* name : {"20211011_aylesbury_dec_station_0.dat", "20211011_aylesbury_dec_station_1.dat"}) {
    measured.push_back(read_laser_profile(dir / name));
  }

  BandAverage model;
  double mpd = 0.0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto road = test::profile_from(chip_seal + "sample_spacing = 0.00025\nlength = 20.0\nlead_in = 0.0\nseed = " +
                                         std::to_string(seed));
    const SampledProfile& p = as_line(*road);
    model.add(p.samples(), p.spacing());
    mpd += mean_profile_depth(p.samples(), p.spacing()).mpd_m / seeds;
  }

  for (const MeasuredProfile& m : measured) {
    const double measured_mpd = mean_profile_depth(m.z_m, m.spacing_m).mpd_m;
    std::printf("  %s: MPD measured %.3f mm, model (mean of 8 seeds) %.3f mm, %+.1f %%\n",
                fs::path(m.source).filename().c_str(), measured_mpd * 1e3, mpd * 1e3, 100.0 * (mpd / measured_mpd - 1.0));
    EXPECT_NEAR(mpd / measured_mpd, 1.0, 0.15) << m.source;
    double worst = 0.0;
    for (const TextureBand& b : texture_spectrum(m.z_m, m.spacing_m)) {
      if (b.nominal_wavelength_m < 3.9e-3 || b.nominal_wavelength_m > 64e-3) continue;
      ASSERT_TRUE(model.has(b.nominal_wavelength_m));
      const double error = model.level(b.nominal_wavelength_m) - b.level_db;
      std::printf("    %6.2f mm  measured %5.1f dB  model %5.1f dB  error %+5.2f dB\n", b.nominal_wavelength_m * 1e3,
                  b.level_db, model.level(b.nominal_wavelength_m), error);
      EXPECT_LE(std::abs(error), 3.0) << m.source << ", band " << b.nominal_wavelength_m;
      worst = std::max(worst, std::abs(error));
    }
    std::printf("    max |error| 4-63 mm: %.2f dB\n", worst);
  }
}

TEST(AggregateRoad, PositiveAndNegativeTextureAreSkewedAsNamed) {
  // The same stones: chips standing up from the binder (positive), or cut flat at a common top
  // plane with voids below (negative).
  const std::string stones = "type = \"aggregate\"\nmax_chip_size = 0.0132\nbinder_level = 0.3\n";
  for (int seed = 1; seed <= 3; ++seed) {
    const auto positive = test::profile_from(stones + "length = 10.0\nseed = " + std::to_string(seed));
    const auto negative = test::profile_from(stones + "length = 10.0\ntexture = \"negative\"\nseed = " + std::to_string(seed));
    const double s_pos = test::skewness(as_line(*positive).samples());
    const double s_neg = test::skewness(as_line(*negative).samples());
    std::printf("  seed %d: skewness positive %+.2f, negative %+.2f\n", seed, s_pos, s_neg);
    EXPECT_GT(s_pos, 0.3);
    EXPECT_LT(s_neg, -0.3);
  }
  // The calibrated chip seal itself (binder_level 0.1) is still positively skewed.
  const auto calibrated = test::profile_from(chip_seal + "length = 10.0\n");
  EXPECT_GT(test::skewness(as_line(*calibrated).samples()), 0.0);
  // And the maps.
  const auto map_pos = test::surface_from(stones + "length = 0.5\nwidth = 0.2\n");
  const auto map_neg = test::surface_from(stones + "length = 0.5\nwidth = 0.2\ntexture = \"negative\"\n");
  const SampledSurface& p = as_map(*map_pos);
  const SampledSurface& n = as_map(*map_neg);
  std::vector<double> all_p;
  std::vector<double> all_n;
  const auto first = static_cast<std::size_t>(std::ceil(4.0 * 0.0132 / p.spacing()));  // beyond the lead-in
  for (std::size_t i = first; i < p.x_count(); ++i) {
    const std::vector<double> rp = p.row(i);
    const std::vector<double> rn = n.row(i);
    all_p.insert(all_p.end(), rp.begin(), rp.end());
    all_n.insert(all_n.end(), rn.begin(), rn.end());
  }
  EXPECT_GT(test::skewness(all_p), 0.3);
  EXPECT_LT(test::skewness(all_n), -0.3);
}

TEST(AggregateRoad, LinesOfTheMapAreLikeTheProfile) {
  // The profile is a line of a map (only the stones that reach it are placed): the lines of a
  // map have the same MPD and texture levels to within their scatter.
  const auto map = test::surface_from(chip_seal + "sample_spacing = 0.0005\nlength = 3.0\nwidth = 0.3\nlead_in = 0.0\n");
  const SampledSurface& s = as_map(*map);
  double map_mpd = 0.0;
  int lines = 0;
  BandAverage map_bands;
  for (std::size_t j = 0; j < s.y_count(); j += 30) {
    const std::vector<double> line = s.column(j);
    map_mpd += mean_profile_depth(line, s.spacing()).mpd_m;
    map_bands.add(line, s.spacing());
    ++lines;
  }
  map_mpd /= lines;
  double profile_mpd = 0.0;
  BandAverage profile_bands;
  for (int seed = 1; seed <= 4; ++seed) {
    const auto road = test::profile_from(chip_seal + "sample_spacing = 0.0005\nlength = 10.0\nlead_in = 0.0\nseed = " +
                                         std::to_string(seed));
    profile_mpd += mean_profile_depth(as_line(*road).samples(), 0.0005).mpd_m / 4.0;
    profile_bands.add(as_line(*road).samples(), 0.0005);
  }
  EXPECT_NEAR(map_mpd / profile_mpd, 1.0, 0.1);
  for (double w : {4e-3, 8e-3, 16e-3, 31.5e-3}) {
    EXPECT_NEAR(map_bands.level(w), profile_bands.level(w), 1.5) << "band " << w;
  }
}

TEST(AggregateRoad, SameSeedIdenticalOtherSeedDiffersFlatLeadIn) {
  const auto a = test::profile_from(chip_seal + "length = 2.0\nseed = 11");
  const auto b = test::profile_from(chip_seal + "length = 2.0\nseed = 11");
  const auto c = test::profile_from(chip_seal + "length = 2.0\nseed = 12");
  EXPECT_EQ(a->type(), "aggregate");
  EXPECT_EQ(as_line(*a).samples(), as_line(*b).samples());
  EXPECT_NE(as_line(*a).samples(), as_line(*c).samples());
  EXPECT_EQ(a->height(-0.01), 0.0);
  EXPECT_EQ(a->height(0.0), 0.0);
  const auto sa = test::surface_from(chip_seal + "length = 0.3\nwidth = 0.1\nseed = 11", 0.2, 0.05);
  const auto sb = test::surface_from(chip_seal + "length = 0.3\nwidth = 0.1\nseed = 11", 0.25, 0.04);
  const auto sc = test::surface_from(chip_seal + "length = 0.3\nwidth = 0.1\nseed = 12", 0.2, 0.05);
  bool differs = false;
  for (std::size_t i = 0; i < as_map(*sa).x_count(); ++i) {
    EXPECT_EQ(as_map(*sa).row(i), as_map(*sb).row(i));
    differs = differs || as_map(*sa).row(i) != as_map(*sc).row(i);
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(sa->height(-0.5, 0.02), 0.0);
}

TEST(AggregateRoad, BadInputNamesTheKey) {
  const std::string base = "type = \"aggregate\"\nmax_chip_size = 0.0132\nlength = 0.5\n";
  EXPECT_MENTIONS(test::profile_error("type = \"aggregate\"\n"), "[road] max_chip_size");
  EXPECT_MENTIONS(test::profile_error(base + "min_chip_size = 0.02\n"), "[road] min_chip_size");
  EXPECT_MENTIONS(test::profile_error(base + "coverage = 1.0\n"), "[road] coverage");
  EXPECT_MENTIONS(test::profile_error(base + "binder_level = 1.0\n"), "[road] binder_level");
  EXPECT_MENTIONS(test::profile_error(base + "shape_factor = 1.5\n"), "[road] shape_factor");
  EXPECT_MENTIONS(test::profile_error(base + "elongation = 0.5\n"), "[road] elongation");
  EXPECT_MENTIONS(test::profile_error(base + "grading_exponent = 3.0\n"), "[road] grading_exponent");
  EXPECT_MENTIONS(test::profile_error(base + "texture = \"bumpy\"\n"), "[road] texture");
  const std::string coarse = test::profile_error(base + "sample_spacing = 0.001\n");
  EXPECT_MENTIONS(coarse, "[road] sample_spacing");
  EXPECT_MENTIONS(coarse, "min_chip_size / 4");
  EXPECT_MENTIONS(test::profile_error(base + "width = 0.2\n"), "width");  // a profile has none
  EXPECT_MENTIONS(test::surface_error(base + "width = 0.0\n"), "[road] width");
  try {
    test::surface_from(base + "width = 0.1\n", 0.2, 0.1);
    ADD_FAILURE() << "a tyre wider than the map must be rejected";
  } catch (const InputError& e) {
    EXPECT_MENTIONS(e.what(), "[road] width");
  }
}

}  // namespace
}  // namespace rollnoise
