// The response stage against the contact run it follows: the belt displacement it evaluates
// over the whole circumference (its own modal recursion, all Nθ positions by FFT) must equal,
// at the contact window, what the contact solver computed through its history engine and G[0].
#include <cmath>

#include <gtest/gtest.h>

#include "contact/rolling_tyre.hpp"
#include "greens/tread_compliance.hpp"
#include "response/surface_response.hpp"
#include "road/road_surface.hpp"

namespace rollnoise {
namespace {

class Texture : public RoadSurface {
 public:
  std::string type() const override { return "texture"; }
  double height(double x, double y) const override {
    if (x < 0.0) return 0.0;
    return 1e-3 * std::sin(2 * M_PI * x / 0.07) * std::cos(2 * M_PI * y / 0.11) +
           4e-4 * std::sin(2 * M_PI * x / 0.023 + 1.0);
  }
};

TEST(SurfaceResponse, MatchesTheContactSolutionAtTheWindow) {
  PlateParameters p;
  p.radius = 0.3;
  p.width = 0.16;
  p.mass_per_area = 10.0;
  p.tension_x = 8e4;
  p.tension_y = 1e4;
  p.bending_x = 6.0;
  p.bending_y = 3.0;
  p.bending_xy = 4.0;
  p.foundation_stiffness = 3e6;
  p.loss_factor = 0.1;
  p.circumferential_modes = 64;  // = Nθ/2: the Nyquist order is included
  p.lateral_modes = 6;
  TyreGrid grid;
  grid.radius = 0.3;
  grid.width = 0.16;
  grid.circumferential = 128;
  grid.lateral = 6;
  grid.window = 24;
  const KroppPlate plate(p);
  const double speed = 20.0;
  const RollingPlate rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const TyreContactTrace t = simulate_rolling_tyre(rolling, local, Texture(), {speed, 150 * grid.dx() / speed, 3000.0, HistoryKind::modal});
  ASSERT_LT(t.contact_area.minCoeff(), t.contact_area.maxCoeff());  // contact changes

  // The contact solver's belt displacement: its surface position less the geometry and the
  // tread, with G[0]'s skew part taken at the previous step's force (rolling_tyre.cpp).
  const Eigen::MatrixXd g0 = rolling.sheared_lag(0);
  const Eigen::MatrixXd skew = 0.5 * (g0 - g0.transpose());
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

TEST(SurfaceResponse, SteadyRollingVelocityIsTheDeformationSweptPast) {
  // In steady rolling the deformed shape u(x) stands still under the axle while material moves
  // through it at −V: the material's radial velocity is v = −V·∂u/∂x. ∂u/∂x by central
  // differences over the grid (error O(dx²)).
  PlateParameters p;
  p.radius = 0.3;
  p.width = 0.16;
  p.mass_per_area = 10.0;
  p.tension_x = 8e4;
  p.tension_y = 1e4;
  p.bending_x = 6.0;
  p.bending_y = 3.0;
  p.bending_xy = 4.0;
  p.foundation_stiffness = 3e6;
  p.loss_factor = 0.1;
  p.circumferential_modes = 256;
  p.lateral_modes = 6;
  TyreGrid grid;
  grid.radius = 0.3;
  grid.width = 0.16;
  grid.circumferential = 512;
  grid.lateral = 6;
  grid.window = 48;
  const KroppPlate plate(p);
  const double speed = 20.0;
  const RollingPlate rolling(plate, grid, grid.dx() / speed);
  const Eigen::MatrixXd local = winkler_compliance(grid.points(), grid.dx(), grid.dy(), 5e8);
  const SteadyRolling steady = solve_steady_rolling(rolling, local, 3000.0);
  SurfaceResponse response(rolling, steady.force, grid.lateral);
  Eigen::MatrixXd u(grid.lateral, grid.circumferential), v(grid.lateral, grid.circumferential);
  response.step(steady.force, u, v);
  const int big_n = grid.circumferential;
  double worst = 0.0;
  for (int j = 0; j < grid.lateral; ++j)
    for (int g = 0; g < big_n; ++g) {
      const double slope = (u(j, (g + 1) % big_n) - u(j, (g + big_n - 1) % big_n)) / (2.0 * grid.dx());
      worst = std::max(worst, std::abs(v(j, g) + speed * slope));
    }
  const double scale = v.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.1);  // m/s: the patch deforms the belt by millimetres over centimetres
  EXPECT_LE(worst, 0.05 * scale);
  RecordProperty("max_velocity_m_per_s", std::to_string(scale));
  RecordProperty("max_difference_m_per_s", std::to_string(worst));
}

}  // namespace
}  // namespace rollnoise
