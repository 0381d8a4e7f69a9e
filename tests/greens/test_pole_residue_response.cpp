// The pole–residue form against the oscillator's own closed forms (sdof_oscillator.cpp), which
// are written independently (e^{−at}·sin(ω_d t)/(mω_d) and its integrals), in all regimes.
#include <gtest/gtest.h>

#include <cmath>

#include "greens/pole_residue_response.hpp"
#include "greens/sdof_oscillator.hpp"

namespace rollnoise {
namespace {

std::vector<SdofOscillator> oscillators() {
  return {{1.0, 2.0 * 0.05 * 500.0, 500.0 * 500.0},   // light damping
          {2.0, 2.0 * 2.0 * 3.0 * 40.0, 2.0 * 1600.0},  // over-damped (ζ = 3)
          {1.0, 2.0 * 0.5 * 3000.0, 9.0e6}};             // ζ = 0.5
}

TEST(PoleResidueResponse, OscillatorImpulseAndReceptance) {
  for (const auto& o : oscillators()) {
    const PoleResidueResponse p = oscillator_poles(o);
    p.validate();
    const double peak = std::abs(o.receptance(0.0));
    const double scale = 1.0 / std::sqrt(o.stiffness * o.mass);  // |h| ≲ 1/(m·ω₀)
    for (double t : {0.0, 1e-4, 1e-3, 7e-3, 0.05})
      EXPECT_NEAR(p.impulse_response(t), o.impulse_response(t), 1e-12 * scale) << "t = " << t;
    for (double w : {0.0, 10.0, 400.0, 500.0, 2e4}) {
      EXPECT_LT(std::abs(p.receptance(w) - o.receptance(w)), 1e-10 * peak) << "ω = " << w;
    }
  }
}

TEST(PoleResidueResponse, TravellingStepIntegralsMatchTheOscillator) {
  for (const auto& o : oscillators()) {
    const PoleResidueResponse p = oscillator_poles(o);
    const double dt = 1e-4;
    for (double w : {0.0, 300.0, 2.5e4}) {
      for (int k = 0; k < 2000; ++k) {
        const auto a = p.phase_integral(w, k * dt, (k + 1) * dt);
        const auto b = o.phase_integral(w, k * dt, (k + 1) * dt);
        EXPECT_LT(std::abs(a - b), 1e-11 * std::abs(o.receptance(0.0))) << "k = " << k;
      }
      // The sum over all lags is the steady total α(−ω): summed over 20 s of 1 ms steps, long
      // enough for the slowest pole here (−7/s) to decay below 1e-60.
      std::complex<double> total = 0.0;
      for (int k = 0; k < 20000; ++k) total += p.phase_integral(w, k * 1e-3, (k + 1) * 1e-3);
      EXPECT_LT(std::abs(total - p.steady_total(w)), 1e-9 * std::abs(p.steady_total(w))) << "ω = " << w;
      EXPECT_LT(std::abs(p.steady_total(w) - o.receptance(-w)), 1e-12 * std::abs(o.receptance(0.0)));
    }
  }
}

TEST(PoleResidueResponse, DirectTermIsInstantaneous) {
  PoleResidueResponse p;
  p.direct = 2e-6;
  EXPECT_EQ(p.receptance(123.0), std::complex<double>(2e-6));
  EXPECT_EQ(p.phase_integral(50.0, 0.0, 1e-3), std::complex<double>(2e-6));
  EXPECT_EQ(p.phase_integral(50.0, 1e-3, 2e-3), std::complex<double>(0.0));
}

TEST(PoleResidueResponse, ValidationRejectsUnstableAndUnpairedPoles) {
  PoleResidueResponse p;
  p.poles = {{1.0, 0.0}};
  p.residues = {1.0};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.poles = {{-1.0, 5.0}};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.poles = {{-1.0, 5.0}, {-1.0, -5.0}};
  p.residues = {{1.0, 2.0}, {1.0, 2.0}};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.residues = {{1.0, 2.0}, {1.0, -2.0}};
  EXPECT_NO_THROW(p.validate());
}

}  // namespace
}  // namespace rollnoise
