// Discrete kernels (MODEL.md §2) checked against independent quadrature of the model's g(t),
// and the static compliance they must sum to.
#include <cmath>

#include <gtest/gtest.h>

#include "greens/discrete_kernel.hpp"
#include "greens/sdof_model.hpp"

namespace rollnoise {
namespace {

const SdofParameters kTable1{1.0, 50.0, 500.0, 1e5};

// Simpson's rule of the model's smooth response over [t0, t1], 200 panels.
double simpson(const SdofModel& model, double t0, double t1) {
  const int n = 200;
  const double h = (t1 - t0) / n;
  double sum = model.smooth_response(t0)(0, 0) + model.smooth_response(t1)(0, 0);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * model.smooth_response(t0 + i * h)(0, 0);
  return sum * h / 3.0;
}

TEST(DiscreteKernel, StepLagsAreIntervalIntegrals) {
  const SdofModel model(kTable1);
  const double dt = 1e-3;
  const DiscreteKernel kernel = make_discrete_kernel(model, dt, 400, Discretisation::step);
  ASSERT_EQ(kernel.length(), 400u);
  // G[0] = 1/s + ∫_0^Δt h.
  EXPECT_NEAR(kernel.lags[0](0, 0), 1.0 / kTable1.contact_stiffness + simpson(model, 0.0, dt), 1e-18);
  for (std::size_t k : {1u, 2u, 10u, 100u, 399u}) {
    const double t0 = static_cast<double>(k) * dt;
    const double expected = simpson(model, t0, t0 + dt);
    // Simpson with 200 panels of 5e-6 s: error ≪ 1e-12 of the lag.
    EXPECT_NEAR(kernel.lags[k](0, 0), expected, 1e-11 * std::abs(expected)) << "k = " << k;
  }
}

TEST(DiscreteKernel, StepKernelSumsToStaticCompliance) {
  const SdofModel model(kTable1);
  const double compliance = 1.0 / kTable1.contact_stiffness + 1.0 / kTable1.stiffness;
  EXPECT_NEAR(model.static_compliance()(0, 0), compliance, 1e-16);
  for (double dt : {1e-3, 1e-4}) {
    const DiscreteKernel kernel = make_discrete_kernel(model, dt, 100000000, Discretisation::step);
    // Cut where g has decayed (45 slowest decay times).
    EXPECT_LT(kernel.length(), 100000000u);
    double sum = 0.0;
    for (const auto& g : kernel.lags) sum += g(0, 0);
    // Σ G[k] telescopes to ∫_0^{KΔt} g; the cut-off tail is below e^{−45}.
    EXPECT_NEAR(sum, compliance, 1e-13 * compliance) << "dt = " << dt;
    EXPECT_EQ(kernel.total(0, 0), compliance);
  }
}

TEST(DiscreteKernel, RectangleIsThePapersEquation2) {
  const SdofModel model(kTable1);
  const double dt = 1e-3;
  const DiscreteKernel kernel = make_discrete_kernel(model, dt, 50, Discretisation::rectangle);
  EXPECT_EQ(kernel.lags[0](0, 0), 1.0 / kTable1.contact_stiffness);
  for (std::size_t k = 1; k < 50; ++k) {
    EXPECT_DOUBLE_EQ(kernel.lags[k](0, 0), model.smooth_response(static_cast<double>(k) * dt)(0, 0) * dt);
  }
}

TEST(DiscreteKernel, RectangleSumMatchesEulerMaclaurin) {
  // Σ_{k≥0} h(kΔt)·Δt with h(0) = 0 is the trapezoidal rule of ∫h, whose error by the
  // Euler–Maclaurin formula is T − I = (Δt²/12)·(h'(∞) − h'(0)) + O(Δt⁴) = −Δt²/(12m) + O(Δt⁴).
  const SdofModel model(kTable1);
  const double compliance = model.static_compliance()(0, 0);
  for (double dt : {4e-3, 2e-3, 1e-3}) {
    const DiscreteKernel kernel = make_discrete_kernel(model, dt, 1000000000, Discretisation::rectangle);
    const double expected = -dt * dt / (12.0 * kTable1.mass);
    // The next term, Δt⁴·h‴(0)/720 with h‴(0) = (r² − mk)/m³, is below 1e-2 of the first.
    EXPECT_NEAR(kernel.total(0, 0) - compliance, expected, -1e-2 * expected) << "dt = " << dt;
  }
}

TEST(DiscreteKernel, CoupledKernelIsCouplingTimesSdof) {
  const double c = 0.4;
  const SdofModel single(kTable1);
  const SdofModel coupled(kTable1, c, 0.01);
  const DiscreteKernel a = make_discrete_kernel(single, 1e-4, 100, Discretisation::step);
  const DiscreteKernel b = make_discrete_kernel(coupled, 1e-4, 100, Discretisation::step);
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_EQ(b.lags[k](0, 0), a.lags[k](0, 0));
    EXPECT_EQ(b.lags[k](1, 1), a.lags[k](0, 0));
    EXPECT_DOUBLE_EQ(b.lags[k](0, 1), c * a.lags[k](0, 0));
    EXPECT_EQ(b.lags[k](0, 1), b.lags[k](1, 0));
  }
  EXPECT_EQ(coupled.contact_point_offsets(), (std::vector<double>{0.0, 0.01}));
}

TEST(DiscreteKernel, ReceptanceOfTheModelIncludesTheContactSpring) {
  const SdofModel model(kTable1);
  EXPECT_NEAR(model.receptance(0.0)(0, 0).real(), model.static_compliance()(0, 0), 1e-18);
  // Far above resonance the mass line dominates the structural part: α − 1/s → −1/(mω²),
  // to within r/(mω) = 5e-5 at ω = 1e6 rad/s.
  const double omega = 1e6;
  const std::complex<double> structural = model.receptance(omega)(0, 0) - 1.0 / kTable1.contact_stiffness;
  EXPECT_NEAR(std::abs(structural * (-kTable1.mass * omega * omega) - 1.0), 0.0, 1e-4);
}

}  // namespace
}  // namespace rollnoise
