// The texture line of the energy budget (contact/texture_under_contact.hpp and
// acoustics/band_power.hpp): a sine texture of known amplitude and wavelength, sampled as the
// rolling tyre samples it, lands in the band f = v/λ at its level; the patch mean follows the
// discrete average over the patch's columns. And the single-point force estimate's limits.
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "acoustics/band_power.hpp"
#include "contact/contact_force_estimate.hpp"
#include "contact/texture_under_contact.hpp"
#include "greens/passenger_plate.hpp"

namespace rollnoise {
namespace {

constexpr double kPi = std::numbers::pi;

TyreGrid demo_grid() {
  TyreGrid grid;
  grid.radius = 0.316;
  grid.width = 0.18;
  grid.tread_width = 0.14;
  grid.circumferential = 512;
  grid.lateral = 20;
  grid.window = 52;
  return grid;
}

// The road r(x) = A·cos(2πx/λ + φ) under every window point, as simulate_rolling_tyre samples
// it: point (i, j) at step n over x_i + v·nΔt, Δt = dx/v.
TyreContactTrace sine_trace(const TyreGrid& grid, double amplitude, double wavelength, std::size_t steps) {
  TyreContactTrace t;
  t.road.resize(static_cast<Eigen::Index>(steps), grid.points());
  for (std::size_t n = 0; n < steps; ++n)
    for (int j = 0; j < grid.lateral; ++j)
      for (int i = 0; i < grid.window; ++i)
        t.road(static_cast<Eigen::Index>(n), i + static_cast<Eigen::Index>(grid.window) * j) =
            amplitude * std::cos(2 * kPi * (grid.x(i) + static_cast<double>(n) * grid.dx()) / wavelength + 0.3);
  return t;
}

TEST(TextureUnderContact, SineTextureLandsInBandVOverLambdaAtItsLevel) {
  const TyreGrid grid = demo_grid();
  const double v = 22.222, fs = v / grid.dx();   // 5730 Hz
  const double amplitude = 0.1e-3, f = 1000.0;  // 0.1 mm at λ = v/f = 22.2 mm
  const std::size_t steps = 1146;                // 0.2 s, the demo run
  const TyreContactTrace t = sine_trace(grid, amplitude, v / f, steps);
  const std::vector<std::vector<double>> lines = centre_line_road(t, grid);
  ASSERT_EQ(lines.size(), 2u);  // Ny = 20: rows 9 and 10
  const std::vector<FractionalOctaveBand> bands = fractional_octave_bands(3, 100.0, 2500.0);
  const std::vector<double> ms = fluctuation_band_mean_squares(lines[0], fs, bands, welch_segment_for(steps));
  const double expected_db = level_db(0.5 * amplitude * amplitude, 1e-6);  // 36.99 dB re 1 µm
  std::size_t at = 0;
  for (std::size_t b = 0; b < bands.size(); ++b)
    if (bands[b].nominal == 1000.0) at = b;
  const double got_db = level_db(ms[at], 1e-6);
  // One Hann segment of 1024 samples holds 179 cycles: the Welch mean square of a sine is
  // A²/2 up to the window's ripple at 2f (relative ~1e-4) and the main lobe (±2 bins = ±11 Hz)
  // lies well inside the band (891–1122 Hz). Required 0.1 dB.
  EXPECT_NEAR(got_db, expected_db, 0.1);
  std::printf("sine 0.1 mm at 22.2 mm, 80 km/h: 1 kHz band %.4f dB, expected %.4f dB (error %.2e dB)\n", got_db,
              expected_db, got_db - expected_db);
  // The neighbours hold only the window's side lobes.
  EXPECT_LT(level_db(ms[at - 1], 1e-6), expected_db - 30.0);
  EXPECT_LT(level_db(ms[at + 1], 1e-6), expected_db - 30.0);
}

TEST(TextureUnderContact, PatchMeanIsTheAverageOverThePatchColumns) {
  const TyreGrid grid = demo_grid();
  const double amplitude = 1e-3, wavelength = 0.05;
  const TyreContactTrace t = sine_trace(grid, amplitude, wavelength, 300);
  const double length = 0.1;
  const std::vector<double> mean = patch_mean_road(t, grid, length);
  // The columns with |x_i| ≤ l/2 are x_i = (i − Nw/2)·dx for i − Nw/2 = −K … K: the mean of
  // cos(k(x_i + s) + φ) over them is cos(ks + φ)·D, D = sin((2K+1)k dx/2)/((2K+1) sin(k dx/2)).
  const int K = static_cast<int>(std::floor(0.5 * length / grid.dx()));
  const double k = 2 * kPi / wavelength, h = grid.dx();
  const double d = std::sin((2 * K + 1) * k * h / 2) / ((2 * K + 1) * std::sin(k * h / 2));
  for (std::size_t n = 0; n < mean.size(); n += 37) {
    const double expected = amplitude * d * std::cos(k * static_cast<double>(n) * h + 0.3);
    EXPECT_NEAR(mean[n], expected, 1e-12) << n;
  }
}

TEST(ContactForceEstimate, SoftTreadPassesItsOwnStiffnessAndStiffTreadTheBelts) {
  const PlateParameters p = test::passenger_plate(64, 9);
  const KroppPlate plate(p);
  const double omega = 2 * kPi * 500.0, y0 = 0.09;
  // A tread far softer than the belt: |F/r|² → k_c².
  EXPECT_NEAR(single_point_force_transfer(plate, 1.0, y0, omega), 1.0, 1e-4);
  // A rigid tread: 1/|α|².
  const double alpha2 = std::norm(plate.receptance(0.0, y0, y0, omega));
  EXPECT_NEAR(single_point_force_transfer(plate, std::numeric_limits<double>::infinity(), y0, omega), 1.0 / alpha2,
              1e-12 / alpha2);
}

}  // namespace
}  // namespace rollnoise
