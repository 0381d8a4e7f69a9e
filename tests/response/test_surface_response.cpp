// The response stage against the contact run it follows: the belt displacement it evaluates
// over the whole circumference (its own modal recursion, all Nθ positions by FFT) must equal,
// at the contact window, what the contact solver computed through its history engine and G[0].
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact/rolling_tyre.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/tread_compliance.hpp"
#include "response/surface_response.hpp"
#include "response_test_road_and_plate.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {
namespace {

using response_test::Texture;
using response_test::test_grid;
using response_test::test_plate;

// step() multiplies the lateral shapes by the transforms' fields where FFTW leaves them (rows of a
// row-major matrix) instead of by a column-major copy: Eigen's product packs either into the
// same blocks, so the fields are the same bit for bit (the outputs' byte identity rests on it).
// Sizes of the 5 kHz grids (20 × 25 by 25 × 1638 and 1024) and of the tests.
TEST(SurfaceResponse, ProductFromTheTransformsInPlaceIsTheCopysBitForBit) {
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (const auto [rows, modes, around] : {std::array{20, 25, 1638}, std::array{20, 25, 1024}, std::array{8, 6, 128},
                                            std::array{24, 25, 128}, std::array{3, 7, 11}}) {
    const Eigen::MatrixXd shapes = Eigen::MatrixXd::Random(rows, modes);
    const RowMajor field = RowMajor::Random(modes, around) * 1e-3;
    const Eigen::MatrixXd copy = field;  // column-major, as step() had copied it
    Eigen::MatrixXd from_copy(rows, around), in_place(rows, around);
    from_copy.noalias() = shapes * copy;
    in_place.noalias() = shapes * Eigen::Map<const RowMajor>(field.data(), modes, around);
    EXPECT_EQ(std::memcmp(from_copy.data(), in_place.data(), sizeof(double) * static_cast<std::size_t>(from_copy.size())), 0)
        << rows << " x " << modes << " x " << around;
  }
}

TEST(SurfaceResponse, MatchesTheContactSolutionAtTheWindow) {
  const TyreGrid grid = test_grid(128, 24);
  // circumferential_modes = Nθ/2: the Nyquist order is included
  const KroppPlate plate(test_plate(64));
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const TyreContactTrace t = simulate_rolling_tyre(rolling, local, Texture(), {speed, 150 * grid.dx() / speed, 3000.0, HistoryKind::modal});
  ASSERT_LT(t.contact_area.minCoeff(), t.contact_area.maxCoeff());  // contact changes

  // The contact solver's belt displacement: its surface position less the geometry and the
  // tread, with G[0]'s skew part taken at the previous step's force when the solver lags it
  // (rolling_tyre.cpp; on this coarse grid G0 is skewed enough that it does not).
  const Eigen::MatrixXd g0 = rolling.sheared_lag(0);
  const Eigen::MatrixXd skew = t.skew_part_lagged ? Eigen::MatrixXd(0.5 * (g0 - g0.transpose()))
                                                  : Eigen::MatrixXd::Zero(g0.rows(), g0.cols());
  const Eigen::VectorXd h = grid.undeformed_gap();
  SurfaceResponse response(rolling, t.steady_force, grid.lateral);
  for (int j = 0; j < grid.lateral; ++j) EXPECT_NEAR(response.lateral_position(j), grid.y(j), 1e-15);
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  Eigen::VectorXd previous = t.steady_force;
  double worst = 0.0;
  double scale = 0.0;
  for (Eigen::Index n = 0; n < t.time.size(); ++n) {
    const Eigen::VectorXd force = t.force.row(n).transpose();
    response.step(force, u, v);
    const Eigen::VectorXd belt = t.displacement.row(n).transpose() - h + Eigen::VectorXd::Constant(h.size(), t.indentation) -
                                 local * force + skew * (force - previous);
    for (int j = 0; j < grid.lateral; ++j)
      for (int i = 0; i < grid.window; ++i) {
        const Eigen::Index q = i + static_cast<Eigen::Index>(grid.window) * j;
        worst = std::max(worst, std::abs(u(j, grid.grid_index(i)) - belt(q)));
        scale = std::max(scale, std::abs(belt(q)));
      }
    previous = force;
  }
  EXPECT_LE(worst, 1e-9 * scale) << "scale " << scale;
  // Far from the patch, on top of the tyre, the belt barely moves.
  EXPECT_LT(u.col(grid.circumferential / 2).cwiseAbs().maxCoeff(), 0.05 * scale);
}

TEST(SurfaceResponse, VelocityAloneIsTheSameBitForBit) {
  // The run's outputs ask for the displacement only on some steps (tyre_step_outputs.cpp): the
  // velocity of a step evaluated alone must equal the one evaluated beside the displacement, and
  // skipping the displacement must not disturb the steps after it.
  const TyreGrid grid = test_grid(256, 8);
  const KroppPlate plate(test_plate(64));
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const TyreContactTrace t = simulate_rolling_tyre(rolling, local, Texture(), {speed, 40 * grid.dx() / speed, 3000.0, HistoryKind::modal});
  SurfaceResponse both(rolling, t.steady_force, grid.lateral), alone(rolling, t.steady_force, grid.lateral);
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  Eigen::MatrixXd u_alone = Eigen::MatrixXd::Constant(grid.lateral, grid.circumferential, 7.0);
  Eigen::MatrixXd v_alone(grid.lateral, grid.circumferential);
  double moving = 0.0;
  for (Eigen::Index n = 0; n < t.time.size(); ++n) {
    const Eigen::VectorXd force = t.force.row(n).transpose();
    both.step(force, u, v);
    const bool with_displacement = n % 3 == 0;
    alone.step(force, with_displacement ? &u_alone : nullptr, v_alone);
    ASSERT_TRUE(v_alone == v) << "step " << n;
    if (with_displacement) ASSERT_TRUE(u_alone == u) << "step " << n;
    else ASSERT_FALSE(u_alone == u) << "step " << n;  // untouched since the last step that asked
    moving = std::max(moving, v.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(moving, 0.0);
}

TEST(SurfaceResponse, SteadyRollingOnASmoothRoadIsStill) {
  // In steady rolling the deformed shape stands still under the axle while material moves
  // through it. The surface at every fixed position does not move, so nothing radiates
  // (issue 10): ∂u/∂t = 0 to round-off, although the material passing each position moves
  // radially at −V·∂u/∂x (checked too, so that the test sees a deformed belt).
  const TyreGrid grid = test_grid(512, 48);
  const KroppPlate plate(test_plate(256));
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const SteadyRolling steady = solve_steady_rolling(rolling, local, 3000.0);
  SurfaceResponse response(rolling, steady.force, grid.lateral);
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  Eigen::MatrixXd u_first;
  for (int n = 0; n < 20; ++n) {
    response.step(steady.force, u, v);
    if (n == 0) u_first = u;
  }
  const int big_n = grid.circumferential;
  double swept = 0.0;  // the material's radial speed, V·|∂u/∂x| (central differences)
  for (int j = 0; j < grid.lateral; ++j)
    for (int g = 0; g < big_n; ++g)
      swept = std::max(swept, speed * std::abs(u(j, (g + 1) % big_n) - u(j, (g + big_n - 1) % big_n)) / (2.0 * grid.dx()));
  EXPECT_GT(swept, 0.1);  // m/s: the patch deforms the belt by millimetres over centimetres
  // Round-off: the modal sum of terms as large as V·k_m·|X|, cancelling.
  EXPECT_LE(v.cwiseAbs().maxCoeff(), 1e-9 * swept);
  EXPECT_LE((u - u_first).cwiseAbs().maxCoeff(), 1e-12 * u.cwiseAbs().maxCoeff());
  RecordProperty("material_speed_m_per_s", std::to_string(swept));
  RecordProperty("surface_speed_m_per_s", std::to_string(v.cwiseAbs().maxCoeff()));
}

// The relative RMS difference between the surface velocity and central differences in time of
// the displacement at fixed positions (first), and between the material's radial velocity and
// the surface velocity (second), over a run on a long road wave with Nθ points around.
struct RateCheck {
  double surface = 0.0;
  double material = 0.0;
};

RateCheck rate_check(int around) {
  class LongWave : public RoadSurface {
   public:
    std::string type() const override { return "long wave"; }
    double height(double x, double y) const override {
      return x < 0.0 ? 0.0 : 1e-3 * (1.0 - std::cos(2 * M_PI * x / 0.2)) * (1.0 + 0.3 * y / 0.08);
    }
  };
  const TyreGrid grid = test_grid(around, 48 * around / 1024);
  const KroppPlate plate(test_plate(96));
  const double speed = 20.0;
  const double dt = grid.dx() / speed;
  const RollingModes rolling(plate, grid, dt);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const double duration = 0.04;  // s: 0.8 m of road, four waves
  const TyreContactTrace t = simulate_rolling_tyre(rolling, local, LongWave(), {speed, duration, 3000.0, HistoryKind::modal});
  SurfaceResponse response(rolling, t.steady_force, grid.lateral);
  std::vector<Eigen::MatrixXd> u(static_cast<std::size_t>(t.time.size())), v(u.size());
  for (std::size_t n = 0; n < u.size(); ++n) {
    u[n].resize(grid.lateral, grid.circumferential);
    v[n].resize(grid.lateral, grid.circumferential);
    response.step(t.force.row(static_cast<Eigen::Index>(n)).transpose(), u[n], v[n]);
  }
  double error = 0.0, norm = 0.0, material = 0.0;
  const int big_n = grid.circumferential;
  for (std::size_t n = u.size() / 10; n + 1 < u.size(); ++n) {
    const Eigen::MatrixXd rate = (u[n + 1] - u[n - 1]) / (2.0 * dt);
    error += (rate - v[n]).squaredNorm();
    norm += v[n].squaredNorm();
    // The material's radial velocity, ∂u/∂t − V·∂u/∂x (the material moves through the window
    // towards −x): what the radiation was handed before issue 10.
    for (int j = 0; j < grid.lateral; ++j)
      for (int g = 0; g < big_n; ++g) {
        const double slope = (u[n](j, (g + 1) % big_n) - u[n](j, (g + big_n - 1) % big_n)) / (2.0 * grid.dx());
        material += std::pow(rate(j, g) - speed * slope - v[n](j, g), 2);
      }
  }
  return {std::sqrt(error / norm), std::sqrt(material / norm)};
}

TEST(SurfaceResponse, VelocityIsTheRateOfTheDisplacementAtFixedPositions) {
  // On a road the surface velocity must be ∂u/∂t of the displacement the same stage writes, at
  // fixed positions. Central differences in time differ from it by Δt²/6·∂³u/∂t³: on a long
  // road wave the difference must be small and fall as Δt² when the grid (and so Δt = dx/V) is
  // refined twice (measured: 3.0 % at 512 points, 0.72 % at 1024).
  const RateCheck coarse = rate_check(512);
  const RateCheck fine = rate_check(1024);
  RecordProperty("relative_rms_difference_512", std::to_string(coarse.surface));
  RecordProperty("relative_rms_difference_1024", std::to_string(fine.surface));
  RecordProperty("material_velocity_relative_rms_difference", std::to_string(fine.material));
  EXPECT_LT(fine.surface, 0.012);
  EXPECT_GT(coarse.surface / fine.surface, 3.0);  // second order: 4
  // The material velocity differs by V·∂u/∂x, larger than v itself near the patch.
  EXPECT_GT(fine.material, 0.5);
}

TEST(SurfaceResponse, DisplacementAtOnePointIsTheFieldsToRoundOff) {
  // displacement_at sums the modes at one point directly; step() transforms them to the whole
  // field by FFT. Every point of every step, rolling on texture with an out-of-roundness (the
  // Nyquist order included: 2·M ≥ Nθ here), within round-off of the field's largest value.
  const TyreGrid grid = test_grid(128, 6);
  const KroppPlate plate(test_plate(64));
  const double speed = 20.0;
  const RollingModes rolling(plate, grid, grid.dx() / speed);
  ASSERT_GE(2 * rolling.orders(), grid.circumferential);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const TyreContactTrace t = simulate_rolling_tyre(rolling, local, Texture(), {speed, 20 * grid.dx() / speed, 3000.0, HistoryKind::modal});
  SurfaceResponse response(rolling, t.steady_force, grid.lateral);
  response.add_out_of_roundness(3, 1, 1e-4, 0.3);
  response.add_out_of_roundness(grid.circumferential / 2, 0, 2e-5, 1.1);
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  for (Eigen::Index n = 0; n < t.time.size(); ++n) {
    response.step(t.force.row(n).transpose(), u, v);
    const double scale = u.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    for (int j = 0; j < grid.lateral; ++j)
      for (int g = 0; g < grid.circumferential; ++g)
        ASSERT_NEAR(response.displacement_at(j, g), u(j, g), 1e-12 * scale) << "step " << n << " at " << j << ", " << g;
  }
  EXPECT_THROW(static_cast<void>(response.displacement_at(grid.lateral, 0)), std::out_of_range);
}

TEST(SurfaceResponse, OutOfRoundnessRadiatesAtTheRotationHarmonic) {
  // A sinusoidal out-of-roundness of order m and amplitude a fixed on the tread of a tyre
  // rotating at Ω, with no road contact: at every fixed position the surface moves with
  // amplitude a·m·Ω at the frequency m·Ω (issue 10). Measured by projecting one revolution of
  // the velocity at each position on e^{−imΩt} (exact for a pure harmonic sampled over a whole
  // period).
  const TyreGrid grid = test_grid(256, 32);
  const KroppPlate plate(test_plate(128));
  const double speed = 20.0;
  const double dt = grid.dx() / speed;
  const RollingModes rolling(plate, grid, dt);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(grid.points());
  SurfaceResponse response(rolling, none, grid.lateral);
  const int order = 7;
  const double amplitude = 2e-4;
  response.add_out_of_roundness(order, 0, amplitude, 0.4);  // the first lateral shape, sin(πy/b)
  const double omega = speed / grid.radius;  // Ω (rad/s)
  const int steps = grid.circumferential;    // one revolution
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  Eigen::MatrixXcd projection = Eigen::MatrixXcd::Zero(grid.lateral, grid.circumferential);
  double other = 0.0;  // what is left after the harmonic
  std::vector<Eigen::MatrixXd> history;
  for (int n = 0; n < steps; ++n) {
    response.step(none, u, v);
    history.push_back(v);
    projection += v * std::polar(2.0 / steps, -order * omega * (n + 1) * dt);
  }
  for (int j = 0; j < grid.lateral; ++j) {
    const double expected = amplitude * order * omega * std::sin(plate.wavenumber_y(1) * response.lateral_position(j));
    for (int g = 0; g < grid.circumferential; ++g) {
      EXPECT_NEAR(std::abs(projection(j, g)), expected, 1e-9 * amplitude * order * omega) << j << " " << g;
      for (int n = 0; n < steps; ++n) {
        const double harmonic = std::real(projection(j, g) * std::polar(1.0, order * omega * (n + 1) * dt));
        other = std::max(other, std::abs(history[static_cast<std::size_t>(n)](j, g) - harmonic));
      }
    }
  }
  EXPECT_LT(other, 1e-9 * amplitude * order * omega);
}

}  // namespace
}  // namespace rollnoise
