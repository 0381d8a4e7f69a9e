// make_rolling_aggregate_surface: the aggregate road of a long run, generated in tiles as the
// tyre reaches them (issue 13: memory flat with run length). Checked against the single map
// make_aggregate_surface makes (the reference): identical up to `length`, joined without a seam,
// the same statistics in every tile, and the same heights whatever order the tiles are visited in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "road/aggregate_road.hpp"
#include "road/sampled_road.hpp"

namespace rollnoise {
namespace {

// A small dense asphalt: 11 mm stones on 0.4 m tiles, 0.1 m wide.
AggregateRoadSpec dense_asphalt(double x_max) {
  AggregateRoadSpec spec;
  spec.max_chip_size = 0.011;
  spec.min_chip_size = 0.0028;
  spec.grading_exponent = 0.45;
  spec.shape_factor = 0.6;
  spec.coverage = 0.95;
  spec.binder_level = 0.7;
  spec.seed = 7;
  spec.length = 0.4;
  spec.width = 0.1;
  spec.half_width = 0.04;
  spec.x_max = x_max;
  return spec;
}

TEST(TiledAggregateSurface, UpToItsLengthTheRoadIsTheSingleMapSampleForSample) {
  const auto single = make_aggregate_surface(dense_asphalt(0.4));
  const auto rolling = make_rolling_aggregate_surface(dense_asphalt(0.3));
  const auto tiled = make_rolling_aggregate_surface(dense_asphalt(2.0));
  const double h = single->spacing();
  for (std::size_t i = 0; i < single->x_count(); ++i)
    for (double y : {-0.04, -0.013, 0.0, 0.021, 0.04}) {
      const double x = h * static_cast<double>(i);
      ASSERT_EQ(rolling->height(x, y), single->height(x, y)) << x << ' ' << y;
      ASSERT_EQ(tiled->height(x, y), single->height(x, y)) << x << ' ' << y;
    }
}

// Over x in [x0, x1) and |y| ≤ 0.04 m, on the samples' grid: the mean and RMS of the heights, and
// the share of the samples where no stone rises above the binder (those at the lowest height).
struct Statistics {
  double mean = 0.0, rms = 0.0, bare = 0.0;
};

Statistics statistics(const RoadSurface& road, double x0, double x1, double h) {
  std::vector<double> z;
  for (double y = -0.04; y <= 0.04; y += h)
    for (double x = x0; x < x1; x += h) z.push_back(road.height(x, y));
  Statistics s;
  const double lowest = *std::min_element(z.begin(), z.end());
  for (double v : z) {
    s.mean += v;
    s.rms += v * v;
    s.bare += v == lowest ? 1.0 : 0.0;
  }
  const auto n = static_cast<double>(z.size());
  s.mean /= n;
  s.rms = std::sqrt(s.rms / n - s.mean * s.mean);
  s.bare /= n;
  return s;
}

TEST(TiledAggregateSurface, TilesJoinWithoutASeamAndAreTheSameRandomSurface) {
  const auto tiled = make_rolling_aggregate_surface(dense_asphalt(4.0));
  const auto single = make_aggregate_surface(dense_asphalt(0.4));
  const double h = single->spacing(), length = h * static_cast<double>(single->x_count() - 1);
  // At a tile boundary the two tiles agree: the first tile's last line is the next one's first.
  for (double y : {-0.04, 0.0, 0.033}) EXPECT_EQ(tiled->height(length, y), single->height(length, y)) << y;
  // Across a boundary the road is as continuous as within a tile: the largest step between
  // neighbouring samples there is no larger than the largest within a tile's interior.
  double step_inside = 0.0, step_across = 0.0;
  for (double y = -0.04; y <= 0.04; y += h) {
    for (double x = 0.1; x < 0.3; x += h) step_inside = std::max(step_inside, std::abs(tiled->height(x + h, y) - tiled->height(x, y)));
    for (int k = 1; k <= 4; ++k) {
      const double edge = length * k;
      for (double x = edge - 3 * h; x < edge + 3 * h; x += h)
        step_across = std::max(step_across, std::abs(tiled->height(x + h, y) - tiled->height(x, y)));
    }
  }
  EXPECT_LE(step_across, step_inside);
  // Each later tile is the same random surface as a first tile. The reference: the first tiles
  // of 20 other seeds, whose RMS ranged over 335–384 µm (mean 363) and bare share over a few per
  // cent. A tile's RMS within 15 % of their mean (the tiles' own scatter, 327–414 µm over nine
  // tiles, is of that order), its bare share within a factor 1.5 of theirs (twice the stones
  // would cut it about 20-fold, half of them raise it 4-fold), and its mean height within a
  // quarter of an RMS of the first tile's (all tiles share the first tile's datum).
  double rms = 0.0, bare = 0.0;
  const int seeds = 20;
  for (int seed = 0; seed < seeds; ++seed) {
    AggregateRoadSpec other = dense_asphalt(0.4);
    other.seed = static_cast<std::uint64_t>(100 + seed);
    const Statistics s = statistics(*make_aggregate_surface(other), 0.05, length, h);  // past the lead-in
    rms += s.rms / seeds;
    bare += s.bare / seeds;
  }
  ASSERT_GT(bare, 0.005);
  const Statistics first = statistics(*tiled, 0.05, length, h);
  for (int k = 1; k < 10; ++k) {
    const Statistics tile = statistics(*tiled, length * k, length * (k + 1), h);
    EXPECT_NEAR(tile.rms, rms, 0.15 * rms) << "tile " << k;
    EXPECT_GT(tile.bare, bare / 1.5) << "tile " << k;
    EXPECT_LT(tile.bare, bare * 1.5) << "tile " << k;
    EXPECT_NEAR(tile.mean, first.mean, 0.25 * rms) << "tile " << k;
  }
}

TEST(TiledAggregateSurface, HeightsDoNotDependOnTheOrderTheTilesAreVisited) {
  const auto forward = make_rolling_aggregate_surface(dense_asphalt(2.0));
  const auto jumping = make_rolling_aggregate_surface(dense_asphalt(2.0));
  std::vector<double> xs;
  for (double x = 0.0; x < 2.0; x += 0.0137) xs.push_back(x);
  std::vector<double> ahead;
  for (double x : xs) ahead.push_back(forward->height(x, 0.012));
  // Backwards: every tile is dropped and made again at least once.
  for (std::size_t i = xs.size(); i-- > 0;) ASSERT_EQ(jumping->height(xs[i], 0.012), ahead[i]) << xs[i];
  for (std::size_t i = 0; i < xs.size(); i += 7) ASSERT_EQ(jumping->height(xs[i], 0.012), ahead[i]) << xs[i];
}

// Tiles after the first hold only the strip the tyre reads (|y| ≤ half_width and a column
// beyond): there they equal, bit for bit, the tiles of a tyre as wide as the surface (which hold
// every column), and a point beyond the strip is an error rather than a height never raised.
TEST(TiledAggregateSurface, LaterTilesHoldTheStripUnderTheTyreWithTheFullWidthHeights) {
  const auto narrow = make_rolling_aggregate_surface(dense_asphalt(2.0));
  AggregateRoadSpec wide_spec = dense_asphalt(2.0);
  wide_spec.half_width = wide_spec.width / 2.0;
  const auto wide = make_rolling_aggregate_surface(wide_spec);
  for (double x = 0.0; x < 2.0; x += 0.0071)
    for (double y : {-0.04, -0.0391, -0.02, 0.0, 0.0173, 0.0399, 0.04})
      ASSERT_EQ(narrow->height(x, y), wide->height(x, y)) << x << ' ' << y;
  EXPECT_THROW(narrow->height(1.0, 0.049), std::logic_error);
  EXPECT_NO_THROW(wide->height(1.0, 0.049));
  EXPECT_NO_THROW(narrow->height(0.2, 0.049)) << "the first tile holds the whole width";
}

// The rolled mix (AC 11): its mastic surface is averaged across tile boundaries over a square of
// the largest stone, so tiles need their neighbours' stones. Visited in any order, and held as a
// strip or the whole width, the heights are the same bits; across a boundary the road is as
// continuous as within a tile.
AggregateRoadSpec rolled_asphalt(double x_max, double half_width) {
  AggregateRoadSpec spec;
  spec.texture = AggregateRoadSpec::Texture::rolled;
  spec.sieves = {0.000063, 0.00025, 0.0005, 0.001, 0.002, 0.004, 0.0056, 0.008, 0.0112, 0.016};
  spec.passing = {7.0, 15.0, 21.0, 28.0, 37.0, 51.0, 60.0, 76.0, 95.0, 100.0};
  spec.binder_content = 5.5;
  spec.air_voids = 4.0;
  spec.sample_spacing = 0.0005;
  spec.seed = 3;
  spec.length = 0.3;
  spec.width = 0.06;
  spec.half_width = half_width;
  spec.x_max = x_max;
  return spec;
}

TEST(TiledAggregateSurface, RolledMixTilesAreTheSameInAnyOrderAndJoinWithoutASeam) {
  const auto forward = make_rolling_aggregate_surface(rolled_asphalt(0.9, 0.015));
  const auto jumping = make_rolling_aggregate_surface(rolled_asphalt(0.9, 0.015));
  const auto wide = make_rolling_aggregate_surface(rolled_asphalt(0.9, 0.03));
  std::vector<double> xs;
  for (double x = 0.0; x < 0.9; x += 0.0031) xs.push_back(x);
  std::vector<double> ahead;
  for (double x : xs) ahead.push_back(forward->height(x, 0.012));
  for (std::size_t i = xs.size(); i-- > 0;) ASSERT_EQ(jumping->height(xs[i], 0.012), ahead[i]) << xs[i];
  for (std::size_t i = 0; i < xs.size(); ++i) ASSERT_EQ(wide->height(xs[i], 0.012), ahead[i]) << xs[i];
  const double h = 0.0005, length = 0.3;
  double step_inside = 0.0, step_across = 0.0;
  for (double y = -0.015; y <= 0.015; y += h) {
    for (double x = 0.05; x < 0.25; x += h) step_inside = std::max(step_inside, std::abs(forward->height(x + h, y) - forward->height(x, y)));
    for (int k = 1; k <= 2; ++k)
      for (double x = length * k - 3 * h; x < length * k + 3 * h; x += h)
        step_across = std::max(step_across, std::abs(forward->height(x + h, y) - forward->height(x, y)));
  }
  EXPECT_LE(step_across, step_inside);
}

}  // namespace
}  // namespace rollnoise
