// Radiation efficiency (radiation/radiation_efficiency.hpp), the energy budget's σ: its
// definition applied to the radiation stage's own power for a body whose σ is known exactly
// (the pulsating sphere, σ = (ka)²/(1 + (ka)²)), and the closed forms used as estimates.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/radiation_efficiency.hpp"
#include "radiation/sphere_points.hpp"

namespace rollnoise {
namespace {

constexpr double kPi = std::numbers::pi;

using test::fibonacci_sphere;

// A sphere moving uniformly (a "piston" wrapped round): the equivalent sources give W = ½qᴴSq
// for the uniform velocity amplitude v0, ⟨v²⟩ = v0²/2, S = 4πa².
TEST(RadiationEfficiency, UniformSphereGivesItsKnownEfficiency) {
  const Medium air{};
  const double a = 0.1, v0 = 1e-3;
  const Eigen::Matrix3Xd unit = fibonacci_sphere(400);
  const EquivalentSources model(fibonacci_sphere(120) * (0.5 * a), unit * a, unit, false, air);
  double worst = 0.0;
  for (double f : {100.0, 500.0, 1000.0, 3000.0}) {
    const double omega = 2 * kPi * f, ka = omega / air.sound_speed * a;
    const Eigen::VectorXcd q = model.strengths(omega, Eigen::VectorXcd::Constant(unit.cols(), v0));
    const double power = 0.5 * (q.adjoint() * model.power_matrix(omega).cast<std::complex<double>>() * q)(0).real();
    const double sigma = radiation_efficiency(power, air.density, air.sound_speed, 4 * kPi * a * a, 0.5 * v0 * v0);
    const double exact = ka * ka / (1 + ka * ka);
    // The same 2e-4 as the power test (test_equivalent_sources.cpp): σ is W scaled.
    EXPECT_NEAR(sigma, exact, 2e-4 * exact) << f << " Hz";
    worst = std::max(worst, std::abs(sigma / exact - 1));
  }
  std::printf("pulsating sphere sigma: worst relative error %.2e\n", worst);
}

TEST(RadiationEfficiency, ClosedFormsAndTheirLimits) {
  // Baffled piston: (ka)²/2 at low ka, 1 − J1(2)/1 = 0.42328 at ka = 1, → 1 at high ka.
  EXPECT_NEAR(baffled_piston_radiation_efficiency(0.01), 0.5e-4, 1e-8);
  EXPECT_NEAR(baffled_piston_radiation_efficiency(1.0), 1.0 - 0.5767248077568734, 1e-12);
  EXPECT_NEAR(baffled_piston_radiation_efficiency(200.0), 1.0, 1e-3);
  // Pulsating cylinder: πka/2 at low ka, → 1 at high ka.
  EXPECT_NEAR(pulsating_cylinder_radiation_efficiency(1e-3) / (kPi * 1e-3 / 2), 1.0, 1e-3);
  EXPECT_NEAR(pulsating_cylinder_radiation_efficiency(200.0), 1.0, 2e-3);
  EXPECT_THROW(radiation_efficiency(1.0, 1.2, 343.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_DOUBLE_EQ(radiation_efficiency(1.0, 2.0, 5.0, 0.5, 0.4), 0.5);  // 1/(2·5·0.5·0.4)
}

}  // namespace
}  // namespace rollnoise
