// Spatial averages of the plate's mobility (greens/plate_mobility_average.hpp), used by the
// energy budget's velocity estimate: the closed form by modal orthogonality against a direct
// average of |KroppPlate::mobility|² over a grid, and the near-field average over the whole
// circumference against the closed form.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "greens/passenger_plate.hpp"
#include "greens/plate_mobility_average.hpp"

namespace rollnoise {
namespace {

constexpr double kPi = std::numbers::pi;

PlateParameters small_tyre() { return test::passenger_plate(24, 5); }

// The mobility is a trigonometric polynomial of order M in x and a sine series of order N in y:
// the midpoint rule with more than 2M points around and 2N + 1 across averages |Y|² exactly.
double grid_average(const KroppPlate& plate, double y0, double omega, double half_length, int nx, int ny) {
  const double b = plate.parameters().width;
  double sum = 0.0;
  for (int i = 0; i < nx; ++i) {
    const double x = -half_length + (i + 0.5) * 2.0 * half_length / nx;
    for (int j = 0; j < ny; ++j) sum += std::norm(plate.mobility(x, (j + 0.5) * b / ny, y0, omega));
  }
  return sum / (nx * ny);
}

TEST(PlateMobilityAverage, BeltMeanByOrthogonalityEqualsTheGridAverage) {
  const KroppPlate plate(small_tyre());
  const double L = plate.circumference();
  for (double f : {90.0, 400.0, 1500.0}) {
    for (double y0 : {0.09, 0.05}) {
      const double omega = 2 * kPi * f;
      const double closed = belt_mean_square_mobility(plate, y0, omega);
      const double grid = grid_average(plate, y0, omega, 0.5 * L, 64, 16);
      EXPECT_NEAR(closed, grid, 1e-10 * grid) << f << " Hz, y0 = " << y0;
      EXPECT_NEAR(near_mean_square_mobility(plate, y0, omega, 0.5 * L, L / 64), closed, 1e-10 * closed);
    }
  }
}

TEST(PlateMobilityAverage, NearMeanEqualsTheGridAverageOverTheStretch) {
  const KroppPlate plate(small_tyre());
  const double omega = 2 * kPi * 700.0, d = 0.3;
  // Both integrate x by the midpoint rule on the same points; y exactly.
  const double near = near_mean_square_mobility(plate, 0.09, omega, d, 0.6 / 120);
  const double grid = grid_average(plate, 0.09, omega, d, 120, 16);
  EXPECT_NEAR(near, grid, 1e-10 * grid);
  // Near the drive point the belt moves more than on average.
  EXPECT_GT(near, belt_mean_square_mobility(plate, 0.09, omega));
}

// The energy budget makes the table of cosines once and evaluates many frequencies with it:
// each must equal a fresh evaluation, bit for bit, in any order.
TEST(PlateMobilityAverage, NearMeanReusedOverFrequenciesEqualsFreshEvaluations) {
  const KroppPlate plate(small_tyre());
  const NearMeanSquareMobility near(plate, 0.07, 0.3);
  for (double f : {700.0, 90.0, 2500.0, 700.0}) {
    const double omega = 2 * kPi * f;
    EXPECT_EQ(near(omega), near_mean_square_mobility(plate, 0.07, omega, 0.3)) << f << " Hz";
  }
  EXPECT_NE(near(2 * kPi * 700.0), near(2 * kPi * 90.0));
}

// The patch receptance against the mean of the point-to-point receptance over pairs of points
// of the patch (midpoint rule, 80 × 10 points). The rule's error on a mode is about (k h)²/24:
// around, k_24·h = 0.19 → 1.5e-3; across, k_5·h_y = 1.22 → 6 % on the highest lateral mode's
// share, which is a small part of the sum. Measured 0.4–0.7 %; required 1 %.
TEST(PlateMobilityAverage, PatchReceptanceIsTheMeanOverThePatch) {
  const KroppPlate plate(small_tyre());
  const double l = 0.12, w = 0.14, b = plate.parameters().width;
  const int nx = 80, ny = 10;
  for (double f : {0.0, 300.0, 1000.0}) {
    const double omega = 2 * kPi * f;
    std::complex<double> mean = 0.0;
    for (int i = 0; i < nx; ++i)
      for (int i0 = 0; i0 < nx; ++i0)
        for (int j = 0; j < ny; ++j)
          for (int j0 = 0; j0 < ny; ++j0)
            mean += plate.receptance((i - i0) * l / nx, 0.5 * (b - w) + (j + 0.5) * w / ny,
                                     0.5 * (b - w) + (j0 + 0.5) * w / ny, omega);
    mean /= static_cast<double>(nx * nx * ny * ny);
    const std::complex<double> closed = patch_receptance(plate, l, w, omega);
    EXPECT_LT(std::abs(closed - mean), 1e-2 * std::abs(mean)) << f << " Hz";
    std::printf("patch receptance at %g Hz: closed %.6e, pair mean %.6e, relative difference %.1e\n", f,
                std::abs(closed), std::abs(mean), std::abs(closed - mean) / std::abs(mean));
  }
}

}  // namespace
}  // namespace rollnoise
