// The SDOF impulse response in all three damping regimes, checked against what defines it:
// the equation of motion m·h'' + r·h' + k·h = 0 with h(0) = 0, h'(0) = 1/m (by finite
// differences), the receptance 1/(k − mω² + iωr) (by numerical Fourier transform), and
// continuity through critical damping.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "greens/sdof_oscillator.hpp"

namespace rollnoise {
namespace {

// m = 1 kg, k = 500 N/m: critical damping at r = 2√(km) = 44.72 N·s/m.
const SdofOscillator kUnder{1.0, 5.0, 500.0};      // ζ = 0.11
const SdofOscillator kTable1{1.0, 50.0, 500.0};    // the paper's Table 1, ζ = 1.118
const SdofOscillator kCritical{1.0, 2.0 * std::sqrt(500.0), 500.0};

class SdofRegimes : public ::testing::TestWithParam<SdofOscillator> {};

TEST_P(SdofRegimes, SatisfiesEquationOfMotion) {
  const SdofOscillator o = GetParam();
  const double h = 1e-5;
  const double scale = 1.0 / (o.mass * std::sqrt(o.stiffness / o.mass));  // peak order of |h|
  for (double t = 0.01; t < 0.5; t += 0.0137) {
    const double y = o.impulse_response(t);
    const double dy = (o.impulse_response(t + h) - o.impulse_response(t - h)) / (2 * h);
    const double ddy = (o.impulse_response(t + h) - 2 * y + o.impulse_response(t - h)) / (h * h);
    // Central differences: truncation O(h²·ω⁴·|h|) ≈ 1e-10·2.5e5 relative; round-off of the
    // second difference ≈ 1e-16/h² ≈ 1e-6 relative to k·|h|.
    EXPECT_NEAR(o.mass * ddy + o.damping * dy + o.stiffness * y, 0.0, 1e-5 * o.stiffness * scale)
        << "t = " << t;
  }
}

TEST_P(SdofRegimes, StartsAtRestWithUnitImpulseVelocity) {
  const SdofOscillator o = GetParam();
  EXPECT_EQ(o.impulse_response(0.0), 0.0);
  EXPECT_EQ(o.impulse_response(-1.0), 0.0);
  const double h = 1e-7;
  // h(t) = t/m − (r/2m²)·t² + …: the forward difference is 1/m to O(r·h/m).
  EXPECT_NEAR(o.impulse_response(h) / h, 1.0 / o.mass, 1e-5 / o.mass);
}

TEST_P(SdofRegimes, StepResponseIsTheIntegral) {
  const SdofOscillator o = GetParam();
  EXPECT_NEAR(o.step_response(1e3), 1.0 / o.stiffness, 1e-15 / o.stiffness);
  EXPECT_EQ(o.step_response(std::numeric_limits<double>::infinity()), 1.0 / o.stiffness);
  // Composite Simpson over [0, T] with 20000 panels: error ~ (Δt)⁴·max|h''''| ≪ 1e-12 relative.
  const double T = 0.3;
  const int n = 20000;
  const double dt = T / n;
  double sum = o.impulse_response(0.0) + o.impulse_response(T);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * o.impulse_response(i * dt);
  EXPECT_NEAR(sum * dt / 3.0, o.step_response(T), 1e-12 / o.stiffness);
}

TEST_P(SdofRegimes, FourierTransformIsTheReceptance) {
  const SdofOscillator o = GetParam();
  // α(ω) = ∫ h e^{−iωt} dt by Simpson's rule over 40 slowest decay times (tail < e^{−40}).
  const double T = 40.0 / o.slowest_decay_rate();
  const int n = 400000;
  const double dt = T / n;
  for (double omega : {0.0, 10.0, 22.36, 60.0, 300.0}) {
    std::complex<double> sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double t = i * dt;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += w * o.impulse_response(t) * std::exp(std::complex<double>(0.0, -omega * t));
    }
    sum *= dt / 3.0;
    const std::complex<double> expected = o.receptance(omega);
    EXPECT_NEAR(std::abs(sum - expected), 0.0, 1e-7 * std::abs(expected)) << "omega = " << omega;
  }
}

INSTANTIATE_TEST_SUITE_P(AllDampingRegimes, SdofRegimes,
                         ::testing::Values(kUnder, kTable1, kCritical));

TEST(SdofOscillator, Table1IsOverDamped) {
  // MODEL.md §3: with Table 1 the system is over-damped, ζ = 50/(2√500) = 1.118.
  EXPECT_NEAR(kTable1.damping_ratio(), 1.118, 5e-4);
  // The slow root of λ² + 50λ + 500: −25 + √125 = −13.82 /s.
  EXPECT_NEAR(kTable1.slowest_decay_rate(), 25.0 - std::sqrt(125.0), 1e-12);
}

TEST(SdofOscillator, ContinuousThroughCriticalDamping) {
  // Just below and just above critical damping (r = r_c ∓ δ) the response differs from
  // t·e^{−at}/m by O(δ), with opposite signs, so their mean meets it to O(δ²).
  const double rc = kCritical.damping;
  const double delta = 1e-6;
  const SdofOscillator below{1.0, rc - delta, 500.0};
  const SdofOscillator above{1.0, rc + delta, 500.0};
  for (double t : {0.01, 0.05, 0.2, 1.0}) {
    const double h = kCritical.impulse_response(t);
    EXPECT_NEAR(below.impulse_response(t), h, 1e-4 * h) << "t = " << t;
    EXPECT_NEAR(above.impulse_response(t), h, 1e-4 * h) << "t = " << t;
    EXPECT_NEAR(0.5 * (below.impulse_response(t) + above.impulse_response(t)), h, 1e-9 * h) << "t = " << t;
    const double s = kCritical.step_response(t);
    EXPECT_NEAR(0.5 * (below.step_response(t) + above.step_response(t)), s, 1e-9 * s) << "t = " << t;
  }
}

TEST(SdofOscillator, UnderDampedMatchesClosedForm) {
  // h = e^{−at} sin(ω_d t)/(m ω_d) with a = r/2m, ω_d = √(k/m − a²) (eq. 6, corrected).
  const double a = 2.5;
  const double wd = std::sqrt(500.0 - a * a);
  for (double t : {0.001, 0.03, 0.1, 0.7}) {
    EXPECT_NEAR(kUnder.impulse_response(t), std::exp(-a * t) * std::sin(wd * t) / wd, 1e-15);
  }
}

TEST(SdofOscillator, OverDampedMatchesClosedForm) {
  // h = e^{−at} sinh(βt)/(mβ), β = √(a² − k/m).
  const double a = 25.0;
  const double b = std::sqrt(625.0 - 500.0);
  for (double t : {0.001, 0.03, 0.1, 0.7, 3.0}) {
    const double expected = std::exp(-a * t) * std::sinh(b * t) / b;
    EXPECT_NEAR(kTable1.impulse_response(t), expected, 1e-14 * expected);
  }
  // No overflow far out, where cosh(βt) alone would overflow.
  EXPECT_TRUE(std::isfinite(kTable1.impulse_response(100.0)));
  EXPECT_TRUE(std::isfinite(kTable1.step_response(100.0)));
}

}  // namespace
}  // namespace rollnoise
