// Interpolated transfer functions against direct equivalent-source solves between the anchors,
// on a body near the road with receivers at CPX and SPB distances: with the propagation delay
// taken out, linear interpolation on anchors 100 Hz apart must follow the exact transfer.
#include <cmath>
#include <complex>
#include <numbers>

#include <gtest/gtest.h>

#include "radiation/sphere_points.hpp"
#include "radiation/transfer_table.hpp"

namespace rollnoise {
namespace {

using test::fibonacci_sphere;

TEST(TransferTable, InterpolatesBetweenAnchors) {
  // A sphere of 0.1 m radius, 0.15 m above the road (a stand-in for a tyre's size).
  const Eigen::Vector3d centre(0.0, 0.0, 0.15);
  const Eigen::Matrix3Xd unit = fibonacci_sphere(200);
  const EquivalentSources model((fibonacci_sphere(60) * 0.05).colwise() + centre, (unit * 0.1).colwise() + centre, unit,
                                true);
  Eigen::Matrix3Xd receivers(3, 2);
  receivers << 0.2, 0.0,  //
      0.3, 7.5,           //
      0.1, 1.2;
  std::vector<double> anchors;
  for (double f = 100.0; f <= 2000.0; f += 100.0) anchors.push_back(f);
  const TransferTable table(model, receivers, anchors, centre, Medium{}.sound_speed);
  // A surface velocity pattern: a pulsation plus a rocking motion.
  Eigen::VectorXcd v(unit.cols());
  for (Eigen::Index m = 0; m < v.size(); ++m) v(m) = 1e-3 * (1.0 + 0.5 * unit(0, m));
  double worst_cpx = 0.0, worst_spb = 0.0;
  for (double f = 150.0; f < 2000.0; f += 100.0) {
    const Eigen::VectorXcd exact = model.transfer(2 * std::numbers::pi * f, receivers) * v;
    const Eigen::VectorXcd interpolated = table.at(f) * v;
    worst_cpx = std::max(worst_cpx, std::abs(interpolated(0) - exact(0)) / std::abs(exact(0)));
    worst_spb = std::max(worst_spb, std::abs(interpolated(1) - exact(1)) / std::abs(exact(1)));
  }
  // Without the delay the SPB transfer turns by 2π·100 Hz·22 ms ≈ 14 rad between anchors and
  // interpolation would be meaningless; with it the error is that of the body's own scale.
  EXPECT_LT(worst_cpx, 0.05);
  EXPECT_LT(worst_spb, 0.05);
  RecordProperty("worst_relative_error_cpx", std::to_string(worst_cpx));
  RecordProperty("worst_relative_error_spb", std::to_string(worst_spb));
  // At an anchor the table is the solve itself.
  EXPECT_LE((table.at(1000.0) * v - model.transfer(2 * std::numbers::pi * 1000.0, receivers) * v).norm(),
            1e-12 * (model.transfer(2 * std::numbers::pi * 1000.0, receivers) * v).norm());
  EXPECT_THROW((void)table.at(50.0), std::out_of_range);
}

}  // namespace
}  // namespace rollnoise
