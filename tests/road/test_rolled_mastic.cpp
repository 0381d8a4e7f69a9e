// The rolled mix's mastic surface, column by column (road/rolled_mastic.hpp), against direct
// computations written out here level by level and sample by sample.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "road/rolled_mastic.hpp"

namespace rollnoise {
namespace {

constexpr double thickness = 0.0112;
constexpr double dz = thickness / mastic_levels;

bool bit(std::uint64_t word, int level) { return ((word >> level) & 1u) != 0; }

TEST(RolledMastic, AStoneOccupiesTheLevelsWhoseCentresItHolds) {
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> height(-1.2 * thickness, 0.1 * thickness);
  for (int trial = 0; trial < 2000; ++trial) {
    double lo = height(engine), hi = height(engine);
    if (lo > hi) std::swap(lo, hi);
    const std::uint64_t word = occupied_levels(lo, hi, thickness);
    for (int level = 0; level < mastic_levels; ++level) {
      const double centre = -thickness + (level + 0.5) * dz;
      ASSERT_EQ(bit(word, level), centre >= lo && centre <= hi) << lo << ' ' << hi << ' ' << level;
    }
  }
  EXPECT_EQ(occupied_levels(-2.0 * thickness, 0.0, thickness), ~std::uint64_t{0});
  EXPECT_EQ(occupied_levels(0.001, 0.002, thickness), 0u);
}

// The mastic's surface by filling the column level by level from the bottom.
double filled_level_by_level(std::uint64_t occupied, double share) {
  double left = share;
  for (int level = 0; level < mastic_levels; ++level) {
    if (bit(occupied, level)) continue;
    if (left <= 1.0) return level + left;
    left -= 1.0;
  }
  return mastic_levels;
}

TEST(RolledMastic, TheMasticFillsTheFreeLevelsFromTheBottomUp) {
  // An empty column: the share itself; a stone across the bottom half lifts it by 32 levels.
  EXPECT_DOUBLE_EQ(mastic_top(0, 20.25), 20.25);
  EXPECT_DOUBLE_EQ(mastic_top(occupied_levels(-thickness, -thickness / 2.0, thickness), 20.25), 52.25);
  // A column fuller than the share allows: to the plane.
  EXPECT_DOUBLE_EQ(mastic_top(occupied_levels(-thickness, -thickness / 4.0, thickness), 20.25), 64.0);
  std::mt19937_64 engine(5);
  std::uniform_real_distribution<double> share(0.1, 40.0);
  for (int trial = 0; trial < 5000; ++trial) {
    const std::uint64_t word = engine() & engine();  // about a quarter of the levels occupied
    const double s = share(engine);
    ASSERT_NEAR(mastic_top(word, s), filled_level_by_level(word, s), 1e-12) << word << ' ' << s;
  }
}

TEST(RolledMastic, TheOffsetKeepsTheMasticsTotal) {
  std::mt19937_64 engine(7);
  std::vector<std::uint64_t> columns(3000);
  for (std::uint64_t& c : columns) c = engine() | engine();  // about three quarters occupied
  const double share = 12.0;
  const double offset = mastic_offset(columns, share);
  EXPECT_GT(offset, 0.0);  // some columns hold fewer than 12 free levels
  double placed = 0.0, wanted = 0.0;
  for (std::uint64_t c : columns) {
    // Placed in a column: the levels up to its mastic surface that are free.
    const double top = mastic_top(c, share + offset);
    double free_below = 0.0;
    for (int level = 0; level < mastic_levels; ++level)
      if (!bit(c, level)) free_below += std::clamp(top - level, 0.0, 1.0);
    placed += free_below;
    wanted += share;
  }
  EXPECT_NEAR(placed, wanted, 1e-6 * wanted);
  // No column too full: no offset. Too little room in all: refused.
  EXPECT_EQ(mastic_offset(std::vector<std::uint64_t>(10, 0), share), 0.0);
  EXPECT_THROW(mastic_offset(std::vector<std::uint64_t>(10, ~std::uint64_t{0} >> 10), share), std::invalid_argument);
}

TEST(RolledMastic, TheSurfaceIsAveragedOverTheClippedSquare) {
  const std::size_t nx = 23, ny = 17, radius = 4;
  std::mt19937_64 engine(11);
  std::uniform_real_distribution<double> value(0.0, 64.0);
  std::vector<double> field(nx * ny);
  for (double& v : field) v = value(engine);
  std::vector<double> smoothed = field;
  smooth_mastic_surface(smoothed, nx, ny, radius);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) {
      double sum = 0.0;
      int count = 0;
      for (std::size_t p = 0; p < nx; ++p)
        for (std::size_t q = 0; q < ny; ++q)
          if (std::abs(static_cast<double>(p) - static_cast<double>(i)) <= radius &&
              std::abs(static_cast<double>(q) - static_cast<double>(j)) <= radius) {
            sum += field[p * ny + q];
            ++count;
          }
      ASSERT_NEAR(smoothed[i * ny + j], sum / count, 1e-9) << i << ' ' << j;
    }
}

}  // namespace
}  // namespace rollnoise
