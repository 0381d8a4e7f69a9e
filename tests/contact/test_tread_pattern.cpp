// The tread pattern (contact/tread_pattern.hpp): its geometry, and the rolling tyre on a flat
// road with it, against references computed here: the pattern's tones at N·v/(2πR) and its
// harmonics, a pitch sequence's spectrum as the Fourier transform of its impulse train, and a
// slick's run unchanged.
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "contact/rolling_tyre.hpp"
#include "contact/tread_pattern.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/tread_compliance.hpp"
#include "rolling_test_roads.hpp"
#include "rolling_test_tyre.hpp"

namespace rollnoise {
namespace {

using test::Flat;
using test::small_grid;
using test::small_plate;

TreadPatternGeometry lateral_grooves(std::vector<double> lengths, double width, double depth) {
  TreadPatternGeometry g;
  g.pitch_lengths = std::move(lengths);
  g.groove_width = width;
  g.groove_depth = depth;
  return g;
}

TEST(TreadPattern, EqualPitchesStartEvenlyAndTheirGroovesAreCentredThere) {
  const TreadPattern p(lateral_grooves(std::vector<double>(8, 1.0), 0.01, 0.008), 1.6);
  ASSERT_EQ(p.pitch_starts().size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) EXPECT_NEAR(p.pitch_starts()[k], 0.2 * static_cast<double>(k), 1e-15);
  EXPECT_EQ(p.height(0.2 + 0.0049, 0.03), -0.008);
  EXPECT_EQ(p.height(0.2 - 0.0049, -0.03), -0.008);
  EXPECT_EQ(p.height(0.2 + 0.0051, 0.0), 0.0);
  EXPECT_EQ(p.height(1.6 - 0.004, 0.0), -0.008);  // the groove at s = 0, from the end of the turn
  EXPECT_EQ(p.height(-0.004 + 3 * 1.6, 0.0), -0.008);  // periodic
  EXPECT_EQ(p.tone_order(), 8);
}

TEST(TreadPattern, PitchSequenceIsScaledToTheCircumference) {
  const TreadPattern p(lateral_grooves({1.0, 1.5, 0.5, 1.0}, 0.01, 0.008), 2.0);
  const double expected[] = {0.0, 0.5, 1.25, 1.5};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(p.pitch_starts()[k], expected[k], 1e-15);
}

TEST(TreadPattern, AnInclinedGrooveMovesAlongTheCircumferenceAcrossTheWidth) {
  TreadPatternGeometry g = lateral_grooves({1.0, 1.0}, 0.01, 0.005);
  g.groove_angle = std::numbers::pi / 4.0;  // 45°: s moves by y
  const TreadPattern p(g, 1.0);
  EXPECT_EQ(p.height(0.05, 0.05), -0.005);
  EXPECT_EQ(p.height(0.05, 0.0), 0.0);
  // 0.01 m normal to the groove is 0.01·√2 along the circumference.
  EXPECT_EQ(p.height(0.05 + 0.0069, 0.05), -0.005);
  EXPECT_EQ(p.height(0.05 + 0.0072, 0.05), 0.0);
}

TEST(TreadPattern, RibsAndTheirShareOfACell) {
  TreadPatternGeometry g;
  g.ribs = {{0.02, 0.01, 0.008}, {-0.03, 0.004, 0.006}};
  const TreadPattern p(g, 2.0);
  EXPECT_EQ(p.height(0.3, 0.024), -0.008);
  EXPECT_EQ(p.height(0.3, 0.026), 0.0);
  EXPECT_EQ(p.height(0.7, -0.031), -0.006);
  EXPECT_EQ(p.tone_order(), 0);
  // A groove half as wide as the cell, centred in it: half its depth (16 midpoints, 8 inside).
  EXPECT_DOUBLE_EQ(p.lateral_mean(1.1, -0.03, 0.008), -0.003);
  EXPECT_DOUBLE_EQ(p.lateral_mean(1.1, 0.02, 0.004), -0.008);  // a cell inside the groove
}

TEST(TreadPattern, MapIsInterpolatedPeriodicallyAround) {
  TreadPatternGeometry g;
  TreadHeightMap m;
  m.lines_around = 4;  // s = 0, 0.25, 0.5, 0.75 of L = 1
  m.y = {-0.1, 0.1};
  m.z = {0.0, 0.0, -0.004, -0.004, 0.0, 0.0, -0.002, -0.002};
  g.map = m;
  const TreadPattern p(g, 1.0);
  EXPECT_DOUBLE_EQ(p.height(0.125, 0.0), -0.002);
  EXPECT_DOUBLE_EQ(p.height(0.875, 0.05), -0.001);  // between s = 0.75 and s = 1 ≡ 0
  EXPECT_DOUBLE_EQ(p.height(-0.25, 0.0), -0.002);
  EXPECT_EQ(p.tone_order(), 2);  // the heights repeat twice a turn (the larger of orders 1 and 2)
}

// The rolling plate of the other tests, slick or patterned, on a flat road for `turns` turns of
// the 64-cell belt (one step per cell).
struct PatternRun {
  KroppPlate plate{small_plate(0.3)};
  TyreGrid grid = small_grid();
  double speed = 20.0;
  RollingModes modes{plate, grid, grid.dx() / speed};
  Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 4e8);

  TyreContactTrace roll(std::shared_ptr<const TreadPattern> pattern, int turns) const {
    TyreRunSettings settings{speed, turns * grid.circumferential * grid.dx() / speed, 1500.0, HistoryKind::modal};
    settings.pattern = std::move(pattern);
    const Flat road;
    return simulate_rolling_tyre(modes, local, road, settings);
  }
};

// The DFT of the total force over the last turn (its last Nθ samples): orders 0 … Nθ − 1.
std::vector<std::complex<double>> last_turn_spectrum(const TyreContactTrace& trace, int cells) {
  const Eigen::Index start = trace.total_force.size() - cells;
  std::vector<std::complex<double>> out(static_cast<std::size_t>(cells));
  for (int k = 0; k < cells; ++k)
    for (int n = 0; n < cells; ++n)
      out[static_cast<std::size_t>(k)] +=
          trace.total_force(start + n) * std::polar(1.0, -2.0 * std::numbers::pi * k * n / cells);
  return out;
}

TEST(RollingTreadPattern, NoPatternAndAPatternOfNoDepthGiveTheSlicksRunBitForBit) {
  const PatternRun run;
  const TyreContactTrace slick = run.roll(nullptr, 1);
  TreadPatternGeometry g = lateral_grooves(std::vector<double>(8, 1.0), 2.0 * run.grid.dx(), 0.0);
  g.ribs = {{0.0, 0.02, 0.0}};
  const TyreContactTrace flat = run.roll(std::make_shared<const TreadPattern>(g, run.grid.circumference()), 1);
  ASSERT_EQ(slick.force.rows(), flat.force.rows());
  EXPECT_TRUE(slick.force == flat.force);
  EXPECT_TRUE(slick.displacement == flat.displacement);
  EXPECT_TRUE(slick.total_force == flat.total_force);
  // On a flat road the slick stays in its steady state.
  EXPECT_NEAR(slick.total_force.maxCoeff() - slick.total_force.minCoeff(), 0.0, 1e-9 * 1500.0);
}

TEST(RollingTreadPattern, EqualPitchesGiveTheirToneAtNvOver2piRAndItsHarmonics) {
  const PatternRun run;
  constexpr int pitches = 8;
  // Grooves 2 mm deep, deeper than the tread's local indentation: forces vanish in them.
  const auto pattern = std::make_shared<const TreadPattern>(
      lateral_grooves(std::vector<double>(pitches, 1.0), 1.3 * run.grid.dx(), 2e-3), run.grid.circumference());
  const TyreContactTrace trace = run.roll(pattern, 3);
  EXPECT_LT(trace.total_force.minCoeff(), 0.99 * trace.total_force.maxCoeff());
  const int cells = run.grid.circumferential;
  const std::vector<std::complex<double>> f = last_turn_spectrum(trace, cells);
  // Over one turn (T = 2πR/v) order k is the frequency k·v/(2πR): the largest line is order N,
  // f_1 = N·v/(2πR), and the force lives on its harmonics.
  std::size_t largest = 1;
  double on = 0.0, off = 0.0;
  for (std::size_t k = 1; k <= static_cast<std::size_t>(cells / 2); ++k) {
    if (std::abs(f[k]) > std::abs(f[largest])) largest = k;
    (k % pitches == 0 ? on : off) += std::norm(f[k]);
  }
  EXPECT_EQ(largest, static_cast<std::size_t>(pitches));
  EXPECT_NEAR(static_cast<double>(largest) * run.speed / run.grid.circumference(),
              pitches * run.speed / (2.0 * std::numbers::pi * run.grid.radius), 1e-9);
  EXPECT_GT(std::abs(f[2 * pitches]), 1e-3 * std::abs(f[pitches]));  // the harmonics are there
  EXPECT_LT(off, 1e-12 * on);  // and nothing between them
}

// N pitches that do not divide the Nθ cells: the contact's nonlinearity makes harmonics above the
// grid's Nyquist order Nθ/2, which the steps fold back to Nθ − k·N, between the pattern's own
// harmonics (docs/physics/tyre-models.md, "The cell-passing artefact"). They stay small.
TEST(RollingTreadPattern, PitchesThatDoNotDivideTheCellsFoldLittleBetweenTheirHarmonics) {
  const PatternRun run;
  constexpr int pitches = 6;
  const auto pattern = std::make_shared<const TreadPattern>(
      lateral_grooves(std::vector<double>(pitches, 1.0), 1.3 * run.grid.dx(), 2e-3), run.grid.circumference());
  const int cells = run.grid.circumferential;
  const std::vector<std::complex<double>> f = last_turn_spectrum(run.roll(pattern, 3), cells);
  double on = 0.0, off = 0.0;
  for (std::size_t k = 1; k <= static_cast<std::size_t>(cells / 2); ++k) (k % pitches == 0 ? on : off) += std::norm(f[k]);
  EXPECT_GT(off, 1e-12 * on);
  EXPECT_LT(off, 0.05 * on) << "off/on = " << off / on;  // 0.036 (-14 dB), 2026-11-27
}

// A pitch sequence spreads the tone over the orders m as |S(m)|, S(m) = Σ_k e^{−2πi·m·s_k/L}, the
// Fourier transform of its impulse train at the pitch starts s_k: two sequences with the same
// groove, in the contact's linear range (grooves far shallower than the indentation), give total
// forces F_A(m)/F_B(m) = S_A(m)/S_B(m), whatever the tyre's response and the groove's shape.
TEST(RollingTreadPattern, PitchSequenceSpreadsTheToneAsItsImpulseTrainsTransform) {
  const PatternRun run;
  const int cells = run.grid.circumferential;
  // Pitch lengths in cells (each sums to the 64 cells of a turn), so that each groove meets the
  // cells' samples alike.
  const std::vector<double> a = {6, 10, 8, 6, 10, 8, 8, 8}, b = {8, 8, 6, 10, 8, 9, 7, 8};
  const auto roll = [&](const std::vector<double>& lengths) {
    return run.roll(std::make_shared<const TreadPattern>(lateral_grooves(lengths, 1.3 * run.grid.dx(), 1e-5),
                                                         run.grid.circumference()),
                    3);
  };
  const auto train = [&](const std::vector<double>& lengths, int m) {
    std::complex<double> s = 0.0;
    double start = 0.0;
    for (double l : lengths) {
      s += std::polar(1.0, -2.0 * std::numbers::pi * m * start / cells);
      start += l;
    }
    return s;
  };
  const std::vector<std::complex<double>> fa = last_turn_spectrum(roll(a), cells), fb = last_turn_spectrum(roll(b), cells);
  double error = 0.0, scale = 0.0;
  for (int m = 1; m < cells / 2; ++m) {
    const std::complex<double> left = fa[static_cast<std::size_t>(m)] * train(b, m);
    const std::complex<double> right = fb[static_cast<std::size_t>(m)] * train(a, m);
    error += std::norm(left - right);
    scale += std::norm(left);
  }
  EXPECT_LT(std::sqrt(error / scale), 1e-8);
  // And the sequence does spread: order 8 of the sequence carries less than N = 8 equal pitches'.
  EXPECT_LT(std::abs(train(a, 8)), 8.0 * 0.9);
}

}  // namespace
}  // namespace rollnoise
