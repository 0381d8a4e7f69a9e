// Air pumping (contact/air_pumping.hpp, radiation/monopole_radiation.hpp) against references that
// do not come from the code: a cavity of known geometry squeezed at a known rate (its volume flow,
// and the pressure of a monopole over a rigid plane, ρ·q̇(t − r/c)/(4πr) with its image); a
// groove open at one end (its air leaves there, none is closed); the monopole's sound power over
// the plane; and a rigidly indented patterned tyre, whose pumping pressure grows as v².
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "contact/air_pumping.hpp"
#include "contact/tread_pattern.hpp"
#include "radiation/monopole_radiation.hpp"

namespace rollnoise {
namespace {

constexpr double rho = 1.204, c = 343.2;

// A smooth burst: s(t) = exp(−((t − t0)/τ)²)·sin(ω(t − t0)), and its derivatives.
struct Burst {
  double t0, tau, omega;
  double value(double t) const {
    const double u = t - t0;
    return std::exp(-(u / tau) * (u / tau)) * std::sin(omega * u);
  }
  double first(double t) const {
    const double u = t - t0, e = std::exp(-(u / tau) * (u / tau));
    return e * (omega * std::cos(omega * u) - 2.0 * u / (tau * tau) * std::sin(omega * u));
  }
  double second(double t) const {
    const double u = t - t0, e = std::exp(-(u / tau) * (u / tau));
    const double a = -2.0 * u / (tau * tau);
    // d/dt[e·(ω cos − (2u/τ²) sin)] = e·a·(ω cos + a sin) + e·(−ω² sin + a ω cos − (2/τ²) sin)
    return e * (a * (omega * std::cos(omega * u) + a * std::sin(omega * u)) - omega * omega * std::sin(omega * u) +
                a * omega * std::cos(omega * u) - 2.0 / (tau * tau) * std::sin(omega * u));
  }
};

// A patch in contact over columns [first, last] of every line; the air ahead and behind 1 mm
// deep; a cavity of `columns` × lines [j0, j1] whose gap is `depth(n)`, moving with the material
// one column every p steps, its front column at `start` at step 0. Line `open_line` (if ≥ 0) is
// in contact only from column `open_from`: the cavity, reaching into it, opens there.
struct Scene {
  int window = 0, lateral = 9, first = 5, last = 0, start = 0, columns = 4, j0 = 3, j1 = 5, p = 1;
  int open_line = -1, open_from = 0;
  void fill(std::size_t n, double depth, Eigen::VectorXd& gap, Eigen::VectorXd& force) const {
    const int front = start - static_cast<int>(n) / p;
    for (int j = 0; j < lateral; ++j)
      for (int i = 0; i < window; ++i) {
        const Eigen::Index k = i + static_cast<Eigen::Index>(window) * j;
        const int from = j == open_line ? open_from : first;
        const bool in_patch = i >= from && i <= last;
        const bool cavity = i <= front && i > front - columns && j >= j0 && j <= j1;
        force(k) = in_patch && !cavity ? 1.0 : 0.0;
        gap(k) = cavity ? depth : in_patch ? 0.0 : 1e-3;
      }
  }
};

// 12 cells of 2 × 2 mm (the Scene's cavity) squeezed by a burst at 1 kHz, 100 steps a period,
// one column a step: the cavity (4 columns) stays ahead of the centre (299.5) to step 277.
struct SqueezedCavity {
  Scene scene;
  double dx = 2e-3, dy = 2e-3, dt = 1e-5;
  Burst burst{1.35e-3, 0.45e-3, 2.0 * std::numbers::pi * 1000.0};  // 1.2e-4 of its peak at the ends
  std::size_t steps = 270;
  SqueezedCavity() {
    scene.window = 600;
    scene.last = 594;
    scene.start = 580;
  }
  double area() const { return scene.columns * (scene.j1 - scene.j0 + 1) * dx * dy; }
  AirPumpingGeometry geometry() const { return {scene.window, scene.lateral, dx, dy, 1, dt}; }
  // The air a cavity `depth − squeeze·burst(t)` deep gives up over step n (n ≥ 1): −ΔV/Δt.
  double flow(std::size_t n, double squeeze) const {
    const double t = static_cast<double>(n) * dt;
    return squeeze * area() * (burst.value(t) - burst.value(t - dt)) / dt;
  }
};

TEST(AirPumping, ACavityThinnerThanTheSealingGapSeepsOutAtTheNearerEdgeAsThinFlow) {
  // The squeezed cavity 0.1 mm deep (below the 0.14 mm sealing gap), squeezed by 0.05 mm: no
  // region forms, and the air the cells give up, −ΔV/Δt, counts as thin flow at the nearer edge.
  const SqueezedCavity cavity;
  const double depth = 0.1e-3, squeeze = 0.05e-3;
  AirPumping air(cavity.geometry());
  Eigen::VectorXd gap(cavity.scene.window * cavity.scene.lateral), force(gap.size());
  for (std::size_t n = 0; n < cavity.steps; ++n) {
    cavity.scene.fill(n, depth - squeeze * cavity.burst.value(static_cast<double>(n) * cavity.dt), gap, force);
    const AirPumpingStep s = air.step(gap, force);
    EXPECT_EQ(s.closed_regions + s.open_regions, 0);
    if (n == 0) continue;
    EXPECT_NEAR(s.front_flow, cavity.flow(n, squeeze), 1e-12 * squeeze * cavity.area() * cavity.burst.omega);
    EXPECT_EQ(s.rear_flow, 0.0);
    EXPECT_EQ(s.closed_flow, 0.0);
    EXPECT_NEAR(s.thin_flow, s.front_flow, 1e-18);
  }
}

TEST(AirPumping, ClosedCavitySqueezedAtAKnownRateGivesItsFlowAndTheMonopolePressure) {
  // The squeezed cavity 3 mm deep, squeezed by 0.5 mm.
  const SqueezedCavity cavity;
  const Scene& scene = cavity.scene;
  const double dt = cavity.dt, depth = 3e-3, squeeze = 0.5e-3;
  const Burst& burst = cavity.burst;
  const std::size_t steps = cavity.steps;
  AirPumping air(cavity.geometry());
  Eigen::VectorXd gap(scene.window * scene.lateral), force(gap.size());
  const double area = cavity.area();
  Eigen::MatrixXd flows(steps, 2);
  double largest = 0.0, worst = 0.0;
  for (std::size_t n = 0; n < steps; ++n) {
    const double t = static_cast<double>(n) * dt;
    scene.fill(n, depth - squeeze * burst.value(t), gap, force);
    const AirPumpingStep s = air.step(gap, force);
    EXPECT_EQ(s.ready, n >= 1);
    EXPECT_EQ(s.closed_regions, 1);
    EXPECT_NEAR(s.closed_volume, area * (depth - squeeze * burst.value(t)), 1e-15);
    flows(static_cast<Eigen::Index>(n), 0) = s.front_flow;
    flows(static_cast<Eigen::Index>(n), 1) = s.rear_flow;
    if (n == 0) continue;
    // The air the cavity gives up over the step: −ΔV/Δt, exactly.
    const double expected = cavity.flow(n, squeeze);
    EXPECT_NEAR(s.front_flow, expected, 1e-12 * squeeze * area * burst.omega);
    EXPECT_EQ(s.rear_flow, 0.0);
    EXPECT_NEAR(s.closed_flow, s.front_flow, 1e-18);
    EXPECT_EQ(s.thin_flow, 0.0);  // 3 mm deep: every cell conducts
    largest = std::max(largest, std::abs(expected));
    worst = std::max(worst, std::abs(s.front_flow - squeeze * area * burst.first(t - 0.5 * dt)));
  }
  // The difference over a step is the flow at the step's middle to (ωΔt)²/24: 1.6e-4 at 1 kHz,
  // 3.7e-4 at 1.5 kHz, where the burst's spectrum is still 0.6 of its peak.
  EXPECT_LT(worst, 5e-4 * largest);
  flows(0, 0) = flows(1, 0);

  // The pressure 0.5 m to the side, 0.1 m up: ρ·q̇(t − r/c)/(4πr) from the source and its image,
  // q = area·squeeze·ṡ. The delay of the receiver is taken off (the vibration's retarded time).
  Eigen::Matrix3Xd sources(3, 2), receivers(3, 1);
  sources.col(0) = Eigen::Vector3d(0.06, 0.0, 0.004);
  sources.col(1) = Eigen::Vector3d(-0.06, 0.0, 0.004);
  receivers.col(0) = Eigen::Vector3d(0.2, 0.5, 0.1);
  const double r_direct = (receivers.col(0) - sources.col(0)).norm();
  const Eigen::Vector3d image(0.06, 0.0, -0.004);
  const double r_image = (receivers.col(0) - image).norm();
  Eigen::VectorXd delays(1);
  delays(0) = 0.45 / c;
  const MonopoleSound sound = radiate_monopoles(MonopoleSources{sources, flows}, 1.0 / dt, receivers, delays, 20.0, 20000.0,
                                                Eigen::VectorXd(), Medium{rho, c}, rigid_road_green());
  double peak = 0.0, error = 0.0;
  for (std::size_t n = 0; n < steps; ++n) {
    const double t = static_cast<double>(n) * dt + delays(0);
    const double exact = rho * area * squeeze / (4.0 * std::numbers::pi) *
                         (burst.second(t - r_direct / c) / r_direct + burst.second(t - r_image / c) / r_image);
    peak = std::max(peak, std::abs(exact));
    error = std::max(error, std::abs(sound.pressure(static_cast<Eigen::Index>(n), 0) - exact));
  }
  // The step difference of the flow is its derivative at the step's middle to (ωΔt)²/24, 1.6e-4
  // at 1 kHz and 1.5e-3 at 3 kHz where the burst's spectrum still is 1/10 of its peak; the
  // burst's ends, 1.2e-4 of its peak.
  EXPECT_GT(peak, 0.0);
  EXPECT_LT(error, 3e-3 * peak) << "peak " << peak;
  std::printf("measured: flow at mid-step within %.2e of the peak flow, pressure within %.2e of the peak pressure\n",
              worst / largest, error / peak);
}

TEST(AirPumping, AGrooveOpenAtTheRearLetsItsAirOutThere) {
  // The cavity reaches line 6, which is in contact only from column 250: beside the cavity
  // (columns 215-240) line 6 lies behind its contact, so the cavity opens at the rear, though it
  // lies ahead of the patch's centre (column 199.5). Sub-steps: p = 20.
  Scene scene;
  scene.window = 400;
  scene.last = 394;
  scene.start = 240;
  scene.p = 20;
  scene.j1 = 6;
  scene.open_line = 6;
  scene.open_from = 250;
  const double dx = 2e-3, dy = 2e-3, dt = 1e-5, depth = 3e-3;
  const Burst burst{2.5e-3, 0.7e-3, 2.0 * std::numbers::pi * 1000.0};
  AirPumping air(AirPumpingGeometry{scene.window, scene.lateral, dx, dy, scene.p, dt});
  Eigen::VectorXd gap(scene.window * scene.lateral), force(gap.size());
  std::vector<double> volume;
  double largest = 0.0;
  for (std::size_t n = 0; n < 500; ++n) {
    const double d = depth - 0.5e-3 * burst.value(static_cast<double>(n) * dt);
    scene.fill(n, d, gap, force);
    const AirPumpingStep s = air.step(gap, force);
    EXPECT_EQ(s.closed_regions, 0);
    EXPECT_EQ(s.open_regions, 1);
    EXPECT_EQ(s.closed_volume, 0.0);
    EXPECT_EQ(s.closed_flow, 0.0);
    EXPECT_EQ(s.front_flow, 0.0);
    volume.push_back(s.enclosed_volume);
    if (n < 20) continue;
    // Over the last p steps, −ΔV/(pΔt) of the cavity's 4 × 3 cells inside the patch (its cells
    // on line 6 lie outside it, in the open air behind line 6's contact).
    const double expected = -(volume[n] - volume[n - 20]) / (20 * dt);
    EXPECT_NEAR(volume[n], 12 * dx * dy * d, 1e-15);
    EXPECT_NEAR(s.rear_flow, expected, 1e-9 * 12 * dx * dy * 0.5e-3 * burst.omega);
    largest = std::max(largest, std::abs(expected));
  }
  EXPECT_GT(largest, 1e-6);  // m³/s: the burst does pump
}

TEST(MonopoleRadiation, SoundPowerOfAMonopoleOnARigidPlaneIsTwiceItsFreeFieldPower) {
  // q = Q·sin(ωt) on a whole number of periods: W = ρck²⟨q²⟩/(4π) in free field, doubled on the
  // plane (source and image in phase); at a height h, (1 + sin 2kh/(2kh)) times the free field.
  const double fs = 48000.0, f = 1500.0, amplitude = 1e-4;
  const Eigen::Index samples = 32000;  // 1000 periods
  Eigen::MatrixXd flows(samples, 1);
  for (Eigen::Index n = 0; n < samples; ++n) flows(n, 0) = amplitude * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(n) / fs);
  const double k = 2.0 * std::numbers::pi * f / c;
  const double free_field = rho * c * k * k * 0.5 * amplitude * amplitude / (4.0 * std::numbers::pi);
  for (const double h : {0.0, 0.004, 0.05}) {
    Eigen::Matrix3Xd at(3, 1);
    at.col(0) = Eigen::Vector3d(0.1, 0.0, h);
    const MonopoleSound sound = radiate_monopoles(MonopoleSources{at, flows}, fs, Eigen::Matrix3Xd(3, 0), Eigen::VectorXd(),
                                                  20.0, 20000.0, Eigen::VectorXd(), Medium{rho, c}, rigid_road_green());
    const double factor = h == 0.0 ? 2.0 : 1.0 + std::sin(2.0 * k * h) / (2.0 * k * h);
    // The record starts and stops with the flow's slope, which spreads its power onto bins
    // beside 1.5 kHz, where k² and the image's factor differ: −7e-6 at h = 4 mm, −4.8e-5 at 5 cm
    // for 1000 periods (numpy's sum over the same bins, 2026-11-28; ×10 for 100 periods).
    EXPECT_NEAR(sound.total_power_w / (factor * free_field), 1.0, 1e-4) << "h = " << h;
    std::printf("measured: h = %g m, power %+.2e relative to the analytic\n", h, sound.total_power_w / (factor * free_field) - 1.0);
  }
}

// A tyre rigidly indented onto a smooth road (no solved contact: the gap is the undeformed
// tread, x²/2R plus the pattern's grooves, minus the indentation), rolled at two speeds with one
// step per cell: the gaps follow the same sequence at both speeds, so the flows grow as v and
// their radiated pressure as v² (40 dB per decade), whatever the pattern does. The slick pumps
// nothing that changes, and radiates nothing.
TEST(AirPumping, GeometricContactPumpsAsTheSquareOfTheSpeed) {
  const double radius = 0.316, dx = 2e-3, dy = 7e-3, indentation = 4e-3;
  const int window = 100, lateral = 20, steps = 400;
  TreadPatternGeometry geometry;
  geometry.pitch_lengths = {0.8, 1.0, 1.2, 1.0, 0.8, 1.2, 1.0, 1.0};
  geometry.groove_width = 5e-3;
  geometry.groove_depth = 7e-3;
  geometry.groove_angle = 15.0 * std::numbers::pi / 180.0;
  geometry.ribs = {{-0.047, 0.009, 0.008}, {0.02, 0.009, 0.008}};
  const TreadPattern pattern(geometry, 0.25);  // eight pitches in 25 cm: several pass in a run
  const auto rms_pressure = [&](double speed, bool patterned) {
    const double dt = dx / speed;
    AirPumping air(AirPumpingGeometry{window, lateral, dx, dy, 1, dt});
    Eigen::VectorXd gap(window * lateral), force(gap.size());
    Eigen::MatrixXd flows(steps, 2);
    for (int n = 0; n < steps; ++n) {
      for (int j = 0; j < lateral; ++j)
        for (int i = 0; i < window; ++i) {
          const double x = (i - window / 2) * dx, y = (j + 0.5) * dy - 0.5 * lateral * dy;
          const double g = x * x / (2.0 * radius) - indentation - (patterned ? pattern.height(x + n * dx, y) : 0.0);
          const Eigen::Index k = i + static_cast<Eigen::Index>(window) * j;
          force(k) = g <= 0.0 ? 1.0 : 0.0;
          gap(k) = std::max(g, 0.0);
        }
      const AirPumpingStep s = air.step(gap, force);
      flows(n, 0) = s.front_flow;
      flows(n, 1) = s.rear_flow;
    }
    flows.row(0) = flows.row(1);
    // Sources on the road, the receiver as far from each: the pressure is ρ(q̇_f + q̇_r)/(2πr)
    // delayed alike, so that only the flows' own scaling shows.
    Eigen::Matrix3Xd sources(3, 2), receivers(3, 1);
    sources.col(0) = Eigen::Vector3d(0.08, 0.0, 0.0);
    sources.col(1) = Eigen::Vector3d(-0.08, 0.0, 0.0);
    receivers.col(0) = Eigen::Vector3d(0.0, 0.3, 0.1);
    Eigen::VectorXd delays(1);
    delays(0) = (receivers.col(0) - sources.col(0)).norm() / c;  // the same from both
    const MonopoleSound sound = radiate_monopoles(MonopoleSources{sources, flows}, 1.0 / dt, receivers, delays, 0.0,
                                                  1e9, Eigen::VectorXd(), Medium{rho, c}, rigid_road_green());
    return std::sqrt(sound.pressure.col(0).array().square().mean());
  };
  const double slow = rms_pressure(50.0 / 3.6, true), fast = rms_pressure(80.0 / 3.6, true);
  ASSERT_GT(slow, 0.0);
  EXPECT_NEAR(20.0 * std::log10(fast / slow) / std::log10(80.0 / 50.0), 40.0, 1e-6);
  std::printf("measured: %.9f dB per decade\n", 20.0 * std::log10(fast / slow) / std::log10(80.0 / 50.0));
  EXPECT_LT(rms_pressure(80.0 / 3.6, false), 1e-9 * fast);
}

}  // namespace
}  // namespace rollnoise
