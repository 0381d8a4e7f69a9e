// The rolling plate: the modal engine against the direct one (the exact sheared kernel from
// the modes' analytic step integrals), and the steady rolling state it starts from.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact/rolling_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/tread_compliance.hpp"
#include "rolling_test_roads.hpp"
#include "rolling_test_tyre.hpp"

namespace rollnoise {
namespace {

using test::small_grid;
using test::small_plate;
using test::Bumps;
using test::Flat;

Eigen::MatrixXd tread(const TyreGrid& g) { return winkler_compliance(g.points(), g.dx(), g.dy(), 4e8); }

// The plate through the common rolling path (its modes as poles) against the plate's own modal
// form, written out here: G[k](p, q) = Σ_mn w_m Re(e^{ik_m Δx}·∫ e^{iω_m τ} h_mn)·sin sin / M with
// h_mn the oscillator's closed form (sdof_oscillator.cpp), as the plate's own rolling code computed it before
// the models shared one path.
TEST(RollingTyre, PlateModesEqualThePlatesOwnModalSum) {
  const KroppPlate plate(small_plate(0.15));
  const TyreGrid grid = small_grid();
  const double speed = 20.0, dt = grid.dx() / (2 * speed);
  const RollingModes rolling(plate, grid, dt, 2);
  for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{7}}) {
    const Eigen::MatrixXd lag = rolling.sheared_lag(k);
    double worst = 0.0;
    for (int jp = 0; jp < grid.lateral; ++jp)
      for (int ip = 0; ip < grid.window; ++ip)
        for (int jq = 0; jq < grid.lateral; ++jq)
          for (int iq = 0; iq < grid.window; ++iq) {
            double sum = 0.0;
            for (int n = 1; n <= plate.parameters().lateral_modes; ++n)
              for (int m = 0; m <= plate.parameters().circumferential_modes; ++m) {
                const double omega = plate.wavenumber_x(m) * speed;
                const auto h = plate.mode_oscillator(m, n).phase_integral(omega, static_cast<double>(k) * dt, static_cast<double>(k + 1) * dt);
                const auto phase = std::polar(1.0, plate.wavenumber_x(m) * (ip - iq) * grid.dx());
                sum += (m == 0 ? 1.0 : 2.0) * (phase * h).real() * std::sin(plate.wavenumber_y(n) * grid.y(jp)) *
                       std::sin(plate.wavenumber_y(n) * grid.y(jq)) / plate.modal_mass();
              }
            worst = std::max(worst, std::abs(sum - lag(ip + grid.window * jp, iq + grid.window * jq)));
          }
    EXPECT_LT(worst, 1e-11 * lag.cwiseAbs().maxCoeff()) << "lag " << k;
  }
}

TEST(RollingTyre, ModalEngineEqualsDirect) {
  const KroppPlate plate(small_plate(0.15));
  const TyreGrid grid = small_grid();
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  TyreRunSettings settings{speed, 60 * grid.dx() / speed, 1500.0, HistoryKind::direct};
  const Bumps road;
  const TyreContactTrace direct = simulate_rolling_tyre(rolling, tread(grid), road, settings);
  settings.history = HistoryKind::modal;
  const TyreContactTrace modal = simulate_rolling_tyre(rolling, tread(grid), road, settings);
  ASSERT_EQ(direct.force.rows(), 61);
  EXPECT_EQ(modal.engine, "modal");
  EXPECT_EQ(direct.engine, "direct");
  // The case loses and regains contact: the active set changes.
  EXPECT_LT(direct.contact_area.minCoeff(), direct.contact_area.maxCoeff());
  const double force_scale = direct.force.cwiseAbs().maxCoeff();
  const double displacement_scale = direct.displacement.cwiseAbs().maxCoeff();
  EXPECT_LE((modal.force - direct.force).cwiseAbs().maxCoeff(), 1e-9 * force_scale);
  EXPECT_LE((modal.displacement - direct.displacement).cwiseAbs().maxCoeff(), 1e-9 * displacement_scale);
}

TEST(RollingTyre, RoughRoadKeepsTheContactConditionsAtEveryStep) {
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  for (const Eigen::MatrixXd& local :
       {tread(grid), halfspace_compliance(grid.positions(), grid.dx(), grid.dy(), 4e6, 0.48)}) {
    const TyreContactTrace t =
        simulate_rolling_tyre(rolling, local, Bumps(), {speed, 200 * grid.dx() / speed, 3200.0, HistoryKind::modal});
    const Eigen::MatrixXd gap = t.displacement - t.road;
    const double max_force = t.force.maxCoeff();
    const double max_gap = gap.maxCoeff();
    EXPECT_GE(t.force.minCoeff(), 0.0);
    EXPECT_GE(gap.minCoeff(), -1e-12);  // m: no penetration
    EXPECT_LE((t.force.array() * gap.array()).abs().maxCoeff(), 1e-12 * max_force * max_gap);
    // The bumps make contact come and go.
    EXPECT_LT(t.contact_area.minCoeff(), 0.9 * t.contact_area.maxCoeff());
  }
}

TEST(RollingTyre, HalfspaceTreadModalEqualsDirect) {
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 15.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = halfspace_compliance(grid.positions(), grid.dx(), grid.dy(), 4e6, 0.48);
  TyreRunSettings settings{speed, 40 * grid.dx() / speed, 2500.0, HistoryKind::direct};
  const TyreContactTrace direct = simulate_rolling_tyre(rolling, local, Bumps(), settings);
  settings.history = HistoryKind::modal;
  const TyreContactTrace modal = simulate_rolling_tyre(rolling, local, Bumps(), settings);
  EXPECT_LE((modal.force - direct.force).cwiseAbs().maxCoeff(), 1e-9 * direct.force.cwiseAbs().maxCoeff());
}

TEST(RollingTyre, NonlinearTreadWithExponentOneIsTheWinklerTread) {
  // KINSOL on F = k·δⁿ with n = 1 against the exact LCP with Winkler springs of the same
  // stiffness (k_p = k_w·dx·dy), from the steady state on through a rough road.
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const double k_w = 4e8;
  const TyreRunSettings settings{speed, 80 * grid.dx() / speed, 3200.0, HistoryKind::modal};
  const TyreContactTrace linear = simulate_rolling_tyre(rolling, tread(grid), Bumps(), settings);
  NonlinearTread springs{Eigen::VectorXd::Constant(grid.points(), k_w * grid.dx() * grid.dy()), 1.0};
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(grid.points(), grid.points());
  const TyreContactTrace nonlinear = simulate_rolling_tyre(rolling, none, Bumps(), settings, nullptr, &springs);
  EXPECT_NEAR(nonlinear.indentation, linear.indentation, 1e-10 * linear.indentation);
  EXPECT_LE((nonlinear.force - linear.force).cwiseAbs().maxCoeff(), 1e-8 * linear.force.maxCoeff());
  EXPECT_LE((nonlinear.displacement - linear.displacement).cwiseAbs().maxCoeff(),
            1e-8 * linear.displacement.cwiseAbs().maxCoeff());

  // A stiffening tread (n = 1.5) still meets the contact conditions and carries the load.
  springs.exponent = 1.5;
  springs.stiffness *= 1e4;  // N/m^1.5: comparable deflections at these loads
  const TyreContactTrace hertzian = simulate_rolling_tyre(rolling, none, Bumps(), settings, nullptr, &springs);
  const Eigen::MatrixXd gap = hertzian.displacement - hertzian.road;
  EXPECT_GE(hertzian.force.minCoeff(), 0.0);
  EXPECT_GE(gap.minCoeff(), -1e-12);
  EXPECT_NEAR(hertzian.steady_force.sum(), 3200.0, 1e-9 * 3200.0);
}

TEST(RollingTyre, NonlinearTreadNewtonEqualsKinsol) {
  // The same run with the steady state and each step solved by Newton over contact sets with FFT
  // products (the default) and by the KINSOL reference: both solve each problem to round-off, so
  // the runs agree to the conditioning of the steps (forces within 1e-8).
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const TyreRunSettings settings{speed, 80 * grid.dx() / speed, 3200.0, HistoryKind::modal};
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(grid.points(), grid.points());
  for (const double exponent : {1.5, 2.0}) {
    NonlinearTread springs{Eigen::VectorXd::Constant(grid.points(), 4e8 * grid.dx() * grid.dy() / std::pow(1e-3, exponent - 1.0)),
                           exponent, NonlinearTreadSolver::kinsol};
    const TyreContactTrace reference = simulate_rolling_tyre(rolling, none, Bumps(), settings, nullptr, &springs);
    springs.solver = NonlinearTreadSolver::newton;
    const TyreContactTrace newton = simulate_rolling_tyre(rolling, none, Bumps(), settings, nullptr, &springs);
    EXPECT_LT(reference.contact_area.minCoeff(), 0.9 * reference.contact_area.maxCoeff());  // contact comes and goes
    // The steady state (T not symmetric: BiCGSTAB against KINSOL) and each step.
    EXPECT_NEAR(newton.indentation, reference.indentation, 1e-10 * reference.indentation) << "n = " << exponent;
    EXPECT_LE((newton.steady_force - reference.steady_force).cwiseAbs().maxCoeff(), 1e-8 * reference.steady_force.maxCoeff());
    EXPECT_LE((newton.force - reference.force).cwiseAbs().maxCoeff(), 1e-8 * reference.force.maxCoeff()) << "n = " << exponent;
    EXPECT_LE((newton.displacement - reference.displacement).cwiseAbs().maxCoeff(),
              1e-8 * reference.displacement.cwiseAbs().maxCoeff())
        << "n = " << exponent;
    EXPECT_GT(newton.lcp_cg_iterations, 0);
  }
}

TEST(RollingTyre, SmoothRoadKeepsTheSteadyState) {
  const KroppPlate plate(small_plate(0.15));
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const double load = 3200.0;
  const TyreContactTrace t =
      simulate_rolling_tyre(rolling, tread(grid), Flat(), {speed, 100 * grid.dx() / speed, load, HistoryKind::modal});
  EXPECT_LE((t.total_force.array() - load).abs().maxCoeff(), 1e-9 * load);
  for (Eigen::Index n = 0; n < t.force.rows(); ++n) {
    EXPECT_LE((t.force.row(n).transpose() - t.steady_force).cwiseAbs().maxCoeff(), 1e-9 * load) << "step " << n;
  }
  EXPECT_TRUE(t.warnings.empty());
}

// Sub-steps (issue 10 §3): Δt = dx/(p·v), the tyre advancing a fraction of a cell per step. The
// modal engine (recursion with the phase e^{iω_m Δt}) against the direct one (the closed-form
// sheared step integrals), on a road that makes contact come and go, for p = 3.
TEST(RollingTyre, SubStepsModalEngineEqualsDirect) {
  const KroppPlate plate(small_plate(0.15));
  const TyreGrid grid = small_grid();
  const double speed = 20.0;
  const int p = 3;
  const RollingModes rolling(plate, grid, grid.dx() / (p * speed), p);
  EXPECT_NEAR(rolling.speed(), speed, 1e-12 * speed);
  EXPECT_NEAR(rolling.passing_rate(5), 2 * M_PI * 5 / grid.circumference() * speed, 1e-9);
  TyreRunSettings settings{speed, 60 * grid.dx() / speed, 1500.0, HistoryKind::direct};
  const Bumps road;
  const TyreContactTrace direct = simulate_rolling_tyre(rolling, tread(grid), road, settings);
  settings.history = HistoryKind::modal;
  const TyreContactTrace modal = simulate_rolling_tyre(rolling, tread(grid), road, settings);
  ASSERT_EQ(direct.force.rows(), 181);
  EXPECT_LT(direct.contact_area.minCoeff(), direct.contact_area.maxCoeff());
  EXPECT_LE((modal.force - direct.force).cwiseAbs().maxCoeff(), 1e-9 * direct.force.cwiseAbs().maxCoeff());
  EXPECT_LE((modal.displacement - direct.displacement).cwiseAbs().maxCoeff(),
            1e-9 * direct.displacement.cwiseAbs().maxCoeff());
  // The wrong time step for the plate's sub-steps is refused.
  EXPECT_THROW(simulate_rolling_tyre(RollingModes(plate, grid, grid.dx() / (2 * speed)), tread(grid), road, settings),
               std::invalid_argument);
}

// With sub-steps a smooth road still keeps the steady state at every step, and the rolling
// resistance (the work of the forces over each cell of travel) is the steady one.
TEST(RollingTyre, SubStepsKeepTheSteadyStateOnASmoothRoad) {
  const KroppPlate plate(small_plate(0.15));
  const TyreGrid grid = small_grid();
  const double speed = 22.2, load = 3200.0;
  for (int p : {2, 5}) {
    const RollingModes rolling(plate, grid, grid.dx() / (p * speed), p);
    const TyreContactTrace t = simulate_rolling_tyre(rolling, tread(grid), Flat(),
                                                     {speed, 50 * grid.dx() / speed, load, HistoryKind::modal});
    EXPECT_LE((t.total_force.array() - load).abs().maxCoeff(), 1e-9 * load) << "p = " << p;
    const double resistance = t.input_power.mean() / speed;
    EXPECT_NEAR(resistance, t.steady_rolling_resistance, 1e-6 * t.steady_rolling_resistance) << "p = " << p;
    EXPECT_GT(resistance, 0.0);
  }
}

// Sub-steps converge: on a road wave (4 cells long) that starts under the window at t = 0, the
// total force with p = 1 … 8 against p = 64 at the instants they share, once the start (the
// wave appearing under half the window at once, whose first response depends on Δt) has passed.
// This small belt's highest modes turn by ωΔt ≈ 17 in one cell's transit: the step
// discretisation is far from its asymptotic first order at p = 1, and sub-steps close the gap.
TEST(RollingTyre, SubStepsConverge) {
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 22.2, load = 1500.0;
  class Wave : public RoadSurface {
   public:
    std::string type() const override { return "wave"; }
    double height(double x, double) const override { return x < 0.0 ? 0.0 : 4e-4 * std::sin(2 * M_PI * x / 0.12); }
  };
  const int reference = 64;
  std::vector<Eigen::VectorXd> totals;
  for (int p : {1, 2, 4, 8, reference}) {
    const RollingModes rolling(plate, grid, grid.dx() / (p * speed), p);
    totals.push_back(simulate_rolling_tyre(rolling, tread(grid), Wave(), {speed, 40 * grid.dx() / speed, load,
                                                                          HistoryKind::modal}).total_force);
  }
  std::vector<double> error(4, 0.0);
  double swing = 0.0;
  for (Eigen::Index n = 10; n <= 40; ++n) {
    for (int a = 0; a < 4; ++a) error[a] = std::max(error[a], std::abs(totals[a]((1 << a) * n) - totals[4](reference * n)));
    swing = std::max(swing, std::abs(totals[4](reference * n) - load));
  }
  for (int a = 0; a < 4; ++a) RecordProperty("difference_p" + std::to_string(1 << a) + "_N", std::to_string(error[a]));
  RecordProperty("force_swing_N", std::to_string(swing));
  EXPECT_GT(swing, 30.0);
  EXPECT_LT(error[2], error[1]);
  EXPECT_LT(error[3], error[2]);
  EXPECT_LT(error[3], 0.5 * error[0]);
  std::printf("max difference from p = 64 over n = 10…40: p=1 %.1f, p=2 %.1f, p=4 %.1f, p=8 %.1f N (swing %.1f N)\n",
              error[0], error[1], error[2], error[3], swing);
}

// What the window's points read of a road finer than the cells (RoadSampling). A texture wave
// one cell long (the cell-passing wavenumber 2π/dx, which with sub-steps would modulate the
// contact at v/dx) is removed by the cell mean exactly and by the low-pass to −57 dB; a wave ten
// cells long passes (cell mean sinc(π/10): −0.14 dB; low-pass within 0.01 dB); the point value
// reads both as they are (with p = 2 it meets the cell wave at two phases, 0.3 and π + 0.3).
TEST(RollingTyre, RoadSamplingRemovesWhatTheCellsCannotResolve) {
  const KroppPlate plate(small_plate(0.1));
  const TyreGrid grid = small_grid();
  const double speed = 22.2, amplitude = 1e-5;
  const int p = 2;
  const RollingModes rolling(plate, grid, grid.dx() / (p * speed), p);
  class Wave : public RoadSurface {
   public:
    Wave(double wavelength, double amplitude) : wavelength_(wavelength), amplitude_(amplitude) {}
    std::string type() const override { return "wave"; }
    double height(double x, double) const override { return amplitude_ * std::sin(2 * M_PI * x / wavelength_ + 0.3); }

   private:
    double wavelength_, amplitude_;
  };
  struct Expectation {
    RoadSampling sampling;
    double cell_wave_gain;  // largest |r| / amplitude for λ = dx
    double long_wave_gain;  // for λ = 10 dx
    double tolerance;
  };
  for (const Expectation& e : {Expectation{RoadSampling::point, std::sin(0.3), 1.0, 0.01},
                               Expectation{RoadSampling::cell_mean, 0.0, std::sin(M_PI / 10) / (M_PI / 10), 0.01},
                               Expectation{RoadSampling::lowpass, 0.0, 1.0, 0.01}}) {
    TyreRunSettings settings{speed, 40 * grid.dx() / speed, 1500.0, HistoryKind::modal, e.sampling};
    const TyreContactTrace cell = simulate_rolling_tyre(rolling, tread(grid), Wave(grid.dx(), amplitude), settings);
    const TyreContactTrace long_wave = simulate_rolling_tyre(rolling, tread(grid), Wave(10 * grid.dx(), amplitude), settings);
    const double cell_gain = cell.road.cwiseAbs().maxCoeff() / amplitude;
    const double long_gain = long_wave.road.cwiseAbs().maxCoeff() / amplitude;
    if (e.cell_wave_gain == 0.0) {
      EXPECT_LE(cell_gain, e.sampling == RoadSampling::cell_mean ? 1e-12 : 2e-3) << static_cast<int>(e.sampling);
    } else {
      EXPECT_NEAR(cell_gain, e.cell_wave_gain, e.tolerance) << static_cast<int>(e.sampling);
    }
    EXPECT_NEAR(long_gain, e.long_wave_gain, e.tolerance) << static_cast<int>(e.sampling);
  }
}

TEST(RollingTyre, DampingMakesThePressureLeanForwardAndCostsRollingResistance) {
  const TyreGrid grid = small_grid();
  const double speed = 22.2;
  const double load = 3200.0;
  const auto steady = [&](double loss_factor) {
    const KroppPlate plate(small_plate(loss_factor));
    return solve_steady_rolling(RollingModes(plate, grid, grid.dx() / speed), tread(grid), load);
  };
  const SteadyRolling with_loss = steady(0.15);
  const SteadyRolling without = steady(0.0);
  EXPECT_NEAR(with_loss.force.sum(), load, 1e-12 * load);
  EXPECT_NEAR(without.force.sum(), load, 1e-12 * load);
  // Pressure centroid along x: forward (towards +x, the leading edge) with damping, where the
  // material entering the patch resists compression; exactly central without.
  const Eigen::MatrixX2d xy = grid.positions();
  const double centroid_damped = with_loss.force.dot(xy.col(0)) / load;
  const double centroid_lossless = without.force.dot(xy.col(0)) / load;
  EXPECT_GT(centroid_damped, 1e-5);  // m; far above the round-off bound below
  EXPECT_LE(std::abs(centroid_lossless), 1e-12);
  EXPECT_GT(with_loss.rolling_resistance, 0.0);
  // Without loss the contact forces do no net work: zero up to round-off of the sums.
  EXPECT_LE(std::abs(without.rolling_resistance), 1e-12 * load);
  // For light damping the dissipated power is proportional to η (first order in the damping).
  const double ratio = steady(0.02).rolling_resistance / steady(0.01).rolling_resistance;
  EXPECT_NEAR(ratio, 2.0, 0.05);
  RecordProperty("rolling_resistance_N", std::to_string(with_loss.rolling_resistance));
}

}  // namespace
}  // namespace rollnoise
