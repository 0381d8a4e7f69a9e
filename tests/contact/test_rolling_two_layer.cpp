// The two-layer tyre through the common rolling path (issue 11): its modes tabulated and fitted
// with poles (greens/fitted_modal_tyre.hpp), its tread's local compliance from its own modes plus
// the static residual of those beyond the table (greens/static_residual.hpp), no separate tread.
//   - The fitted modes against the tyre's own receptance between cells (two_layer_tyre.cpp, which
//     sums the exact layer solutions itself): the scaling, lateral shapes and cell factors.
//   - Smooth road: the steady state holds (the whole-G0 P-matrix step keeps it to round-off).
//   - Rough road: F ≥ 0, no penetration and complementarity at every step; the modal engine
//     equals the direct one (the closed-form sheared kernel of the same poles).
//   - The fit's error in a run: the production fit (relative RMS 3e-3 to 20 kHz) against a
//     reference fitted over ten times tighter to 100 kHz (about 100 poles a mode).
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "contact/rolling_tyre.hpp"
#include "greens/fitted_modal_tyre.hpp"
#include "greens/static_residual.hpp"
#include "greens/two_layer_tyre.hpp"
#include "greens/two_layer_test_support.hpp"
#include "rolling_test_roads.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

// The passenger file's values with few modes.
TwoLayerParameters small_two_layer() { return test::tyre_like_two_layer(24, 5); }

TyreGrid small_grid() {
  TyreGrid g;
  g.radius = 0.316;
  g.width = 0.18;
  g.circumferential = 64;
  g.lateral = 4;
  g.tread_width = 0.14;
  g.window = 12;
  return g;
}

struct FittedTwoLayer {
  TwoLayerTyre layers;
  FittedModalTyre modes;
  explicit FittedTwoLayer(const TwoLayerParameters& p, const Eigen::VectorXd& frequencies = tyre_mode_fit_frequencies(),
                          const VectorFittingOptions& options = tyre_mode_fit_options())
      : layers(p),
        modes(tabulate_two_layer(layers, frequencies, p.circumferential_modes), "two_layer", true, options) {}
  Eigen::MatrixXd residual(const TyreGrid& grid) const {
    KeptModes kept{layers.circumference(), layers.width(), LateralShape::sine, 1, layers.parameters().lateral_modes,
                   layers.parameters().circumferential_modes};
    std::vector<double> y;
    for (int j = 0; j < grid.lateral; ++j) y.push_back(grid.y(j));
    return static_residual_compliance(
        kept, [&](double kx, double ky) { return layers.wavenumber_compliance(kx, ky, 0.0)(2, 2).real(); },
        grid.window, grid.dx(), y, grid.dy());
  }
};

const FittedTwoLayer& tyre() {
  static const FittedTwoLayer fitted(small_two_layer());
  return fitted;
}

TEST(RollingTwoLayer, FittedModesGiveTheTyresReceptanceBetweenCells) {
  const FittedTwoLayer& t = tyre();
  EXPECT_EQ(t.modes.fit_report().unconverged, 0u);
  const TyreGrid grid = small_grid();
  const double dx = grid.dx(), dy = grid.dy();
  for (const double f : {0.0, 90.0, 700.0, 3000.0}) {
    const double omega = 2 * pi * f;
    const auto exact = t.layers.response(omega);
    for (const int di : {0, 1, 3}) {
      const SurfaceLocation r{di * dx, grid.y(1), dx, dy}, s{0.0, grid.y(2), dx, dy};
      const std::complex<double> reference = exact.receptance(r, s);
      std::complex<double> sum = 0.0;
      double magnitudes = 0.0;  // Σ|term|: the scale each mode's own fit error acts on
      for (int l = 0; l < t.modes.lateral_modes(); ++l)
        for (int m = 0; m <= t.modes.orders(); ++m) {
          const std::complex<double> term = (m == 0 ? 1.0 : 2.0) *
                                            std::cos(2 * pi * m * di * dx / grid.circumference()) *
                                            t.modes.mode_response(m, l, dx, dy).receptance(omega) *
                                            t.modes.lateral_shape(l, r.y) * t.modes.lateral_shape(l, s.y);
          sum += term;
          magnitudes += std::abs(term);
        }
      // Each mode's fit is within 3e-3 RMS (3e-2 at worst) of its table: the sum within 1e-2 of
      // the terms' magnitudes (where terms cancel, as between cells at 3 kHz, relative to the sum
      // itself it can be a few per cent).
      EXPECT_LT(std::abs(sum - reference), 1e-2 * magnitudes) << f << " Hz, " << di << " cells: " << sum << " vs "
                                                              << reference;
      if (di == 0) {
        EXPECT_LT(std::abs(sum - reference), 1e-2 * std::abs(reference)) << f << " Hz, the cell itself";
      }
    }
  }
}

using test::Bumps;
using test::Flat;

TEST(RollingTwoLayer, SmoothRoadKeepsTheSteadyStateUnderTheLoad) {
  const TyreGrid grid = small_grid();
  const double speed = 22.2, load = 3200.0;
  const RollingModes rolling(tyre().modes, grid, grid.dx() / speed);
  const TyreContactTrace t = simulate_rolling_tyre(rolling, tyre().residual(grid), Flat(),
                                                   {speed, 60 * grid.dx() / speed, load, HistoryKind::modal});
  EXPECT_GT(t.contact_matrix_skewness, 1e-2);
  // The case the whole-G0 step is for: lagging G0's skew part would amplify perturbations.
  EXPECT_FALSE(t.skew_part_lagged) << "growth per step " << t.lagged_skew_growth;
  EXPECT_NEAR(t.total_force.mean(), load, 5e-3 * load);
  EXPECT_LE((t.total_force.array() - load).abs().maxCoeff(), 1e-9 * load);
  EXPECT_GT(t.steady_rolling_resistance, 0.0);  // the layers' loss makes the pressure lean
}

TEST(RollingTwoLayer, RoughRoadContactConditionsAndEnginesAgree) {
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const RollingModes rolling(tyre().modes, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = tyre().residual(grid);
  TyreRunSettings settings{speed, 80 * grid.dx() / speed, 3200.0, HistoryKind::modal};
  const TyreContactTrace modal = simulate_rolling_tyre(rolling, local, Bumps(), settings);
  const Eigen::MatrixXd gap = modal.displacement - modal.road;
  EXPECT_GE(modal.force.minCoeff(), 0.0);
  EXPECT_GE(gap.minCoeff(), -1e-12);  // m: no penetration
  EXPECT_LE((modal.force.array() * gap.array()).abs().maxCoeff(), 1e-10 * modal.force.maxCoeff() * gap.maxCoeff());
  EXPECT_LT(modal.contact_area.minCoeff(), modal.contact_area.maxCoeff());
  settings.history = HistoryKind::direct;
  const TyreContactTrace direct = simulate_rolling_tyre(rolling, local, Bumps(), settings);
  EXPECT_LE((modal.force - direct.force).cwiseAbs().maxCoeff(), 1e-9 * direct.force.cwiseAbs().maxCoeff());
  EXPECT_LE((modal.displacement - direct.displacement).cwiseAbs().maxCoeff(),
            1e-9 * direct.displacement.cwiseAbs().maxCoeff());
}

TEST(RollingTwoLayer, TheFitsErrorInARunStaysWithinItsTolerance) {
  // Same tyre, same rough road, two fits: the production one and a reference with a target 30
  // times tighter, sampled to 100 kHz (the tread's thickness resonances resolved).
  VectorFittingOptions tight = tyre_mode_fit_options();
  tight.target_rms_error = 1e-4;
  tight.target_max_error = 2e-3;
  tight.maximum_pole_pairs = 60;
  const FittedTwoLayer reference(small_two_layer(), default_fit_frequencies(300, 1.0, 1.0e5), tight);
  const ModalFitReport& fit = reference.modes.fit_report();
  ASSERT_LE(fit.worst_rms_error, 2e-4);  // over 10 times the production fit's accuracy
  std::printf("reference fit: %zu modes, %zu poles, %zu unconverged, worst relative RMS %.1e, max %.1e\n", fit.modes, fit.poles, fit.unconverged, fit.worst_rms_error, fit.worst_max_error);
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const Eigen::MatrixXd local = tyre().residual(grid);  // the static residual does not depend on the fit
  TyreRunSettings settings{speed, 80 * grid.dx() / speed, 3200.0, HistoryKind::modal};
  const TyreContactTrace production = simulate_rolling_tyre(RollingModes(tyre().modes, grid, grid.dx() / speed), local, Bumps(), settings);
  const TyreContactTrace exact = simulate_rolling_tyre(RollingModes(reference.modes, grid, grid.dx() / speed), local, Bumps(), settings);
  // Total force and the cell forces, relative to their largest values: within the fit's
  // tolerance in the time domain (step means within 4.4e-3 of the peak, docs/greens/rolling_fit.md).
  const double total = (production.total_force - exact.total_force).cwiseAbs().maxCoeff() / exact.total_force.maxCoeff();
  const double cells = (production.force - exact.force).cwiseAbs().maxCoeff() / exact.force.maxCoeff();
  EXPECT_LE(total, 5e-3);
  EXPECT_LE(cells, 2e-2);
  EXPECT_GT(total, 0.0);  // two different fits: the check compares something
  std::printf("fit error in the run: total force %.2e, cell forces %.2e (of their largest values)\n", total, cells);
}

}  // namespace
}  // namespace rollnoise
