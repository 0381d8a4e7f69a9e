// simulate_point_contact (the Green's-function solver, MODEL.md §2) against an independent
// reference: the same lumped system (MODEL.md §3) integrated by CVODE with root finding at
// every contact switch (cvode_reference.hpp). The solver's `step` discretisation is first
// order in Δt, so its errors must halve with Δt; at Δt = 1e-5 s the displacement must be
// within 2 % (relative RMS) in the configuration (W = 2 N; see ConvergenceCase).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "contact/point_contact.hpp"
#include "greens/sdof_model.hpp"
#include "reference/cvode_reference.hpp"
#include "road/road_profile.hpp"

namespace rollnoise {
namespace {

using reference::CvodeOptions;
using reference::CvodeReference;
using reference::LumpedSystem;

// r = A sin(2πx/λ) on x ≥ 0 and the flat lead-in r = 0 on x < 0 (road_profile.hpp), written
// here so that the test does not depend on the road library it would share with the solver.
class SineTestRoad final : public RoadProfile {
 public:
  SineTestRoad(double amplitude, double wavelength) : amplitude_(amplitude), wavelength_(wavelength) {}
  std::string type() const override { return "sine"; }
  double height(double x) const override {
    return x < 0.0 ? 0.0 : amplitude_ * std::sin(2.0 * std::numbers::pi * x / wavelength_);
  }

 private:
  double amplitude_;
  double wavelength_;
};

class FlatTestRoad final : public RoadProfile {
 public:
  std::string type() const override { return "flat"; }
  double height(double) const override { return 0.0; }
};

// Table 1 of the paper (over-damped, ζ = 1.118) and the same with r = 5 N·s/m (ζ = 0.112).
constexpr SdofParameters kOverDamped{1.0, 50.0, 500.0, 1e5};
constexpr SdofParameters kUnderDamped{1.0, 5.0, 500.0, 1e5};
constexpr double kSpeed = 1.0;       // m/s (Table 1)
constexpr double kCoupling = 0.4;    // c (paper §4.2)
constexpr double kSpacing = 0.01;    // m (paper §4.2)
// A 1 mm, 0.1 m sine at 1 m/s (10 Hz): holding the mass on the road would need
// F = W + A·((k − mω²) sin + rω cos), amplitude 4.7 N (r = 50) or 3.5 N (r = 5) per point.
// With less load the contact is lost, and the stiff contact spring (no damping of its own)
// makes the mass bounce: measured airborne fractions of the samples are 85–90 % under
// W = 2 N (short impacts) and 49 % (sdof, r = 50) to 82 % under W = 4 N.
constexpr double kStaticLoad = 2.0;      // N
constexpr double kHeavyLoad = 4.0;       // N
constexpr double kAmplitude = 1e-3;      // m
constexpr double kWavelength = 0.1;      // m
constexpr double kDuration = 0.3;        // s: three road periods, ≥ 3 losses of contact per point
constexpr double kFinestStep = 1e-5;     // s

struct ConvergenceCase {
  std::string name;
  LumpedSystem system;
  double static_load;  // W, N
  // The accuracy criterion, relative RMS displacement error at Δt = 1e-5 s, set for
  // the W = 2 N configuration and the demo's W = 4 N. One case checks the order of convergence
  // only, the under-damped sdof under 4 N: there the mass bounces off the road again and again, each landing time inherits the error of
  // the flight before it, and the error constant grows with the number of bounces (measured:
  // under-damped sdof 2.7 % at Δt = 1e-5 s, landing times off by up to 0.9 ms = 90 Δt after
  // four bounces, all halving exactly with Δt: a first-order error, not a defect).
  std::optional<double> max_displacement_error;
};

// Names the case in test listings (instead of gtest's byte dump of the struct).
void PrintTo(const ConvergenceCase& c, std::ostream* os) { *os << c.name; }

LumpedSystem sdof(const SdofParameters& p) { return {p, 1, 0.0, 0.0}; }
LumpedSystem coupled(const SdofParameters& p) { return {p, 2, kCoupling, kSpacing}; }

Eigen::VectorXd sample_times(double duration, double dt) {
  const auto steps = static_cast<Eigen::Index>(std::llround(duration / dt));
  Eigen::VectorXd t(steps + 1);
  for (Eigen::Index n = 0; n <= steps; ++n) t(n) = static_cast<double>(n) * dt;  // as the solver
  return t;
}

ContactTrace run_solver(const LumpedSystem& system, const RoadProfile& road, double static_load, double dt) {
  const SdofModel model = reference::make_model(system);
  RollingSettings settings;
  settings.speed = kSpeed;
  settings.duration = kDuration;
  settings.time_step = dt;
  settings.static_load = static_load;
  settings.history = HistoryKind::direct;
  settings.discretisation = Discretisation::step;
  return simulate_point_contact(model, road, settings);
}

// Every `stride`-th row: the reference on the fine grid, seen at the samples of a coarser Δt.
Eigen::MatrixXd every(const Eigen::MatrixXd& m, Eigen::Index stride) {
  return m(Eigen::seq(0, m.rows() - 1, stride), Eigen::all);
}

// RMS of the difference over RMS of the reference (over all samples and points).
double relative_rms(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).norm() / reference.norm();
}

void report(const std::string& key, double value) {
  std::ostringstream text;
  text << std::setprecision(4) << value;
  ::testing::Test::RecordProperty(key, text.str());
}

class CvodeConvergence : public ::testing::TestWithParam<ConvergenceCase> {};

TEST_P(CvodeConvergence, SolverConvergesFirstOrderToReference) {
  const ConvergenceCase& c = GetParam();
  const SineTestRoad road(kAmplitude, kWavelength);
  const CvodeReference ref = reference::simulate_cvode_reference(
      c.system, road, kSpeed, c.static_load, sample_times(kDuration, kFinestStep));

  // The case must exercise loss of contact: every point has samples with F exactly 0 (the
  // reference's LCP sets inactive forces to 0, not to round-off), and it loses and regains
  // contact several times.
  for (Eigen::Index i = 0; i < ref.force.cols(); ++i) {
    const auto f = ref.force.col(i);
    int losses = 0;
    int landings = 0;
    for (Eigen::Index n = 1; n < f.size(); ++n) {
      if (f(n - 1) > 0.0 && f(n) == 0.0) ++losses;
      if (f(n - 1) == 0.0 && f(n) > 0.0) ++landings;
    }
    std::cout << "[" << c.name << "] point " << i << ": " << losses << " losses of contact, " << landings
              << " landings, airborne " << (f.array() == 0.0).count() << " of " << f.size() << " samples\n";
    EXPECT_GE(losses, 3) << "point " << i;
    EXPECT_GE(landings, 2) << "point " << i;
    // Complementarity of the reference itself: no point below the road (to round-off).
    EXPECT_GE((ref.displacement.col(i) - ref.road.col(i)).minCoeff(), -1e-12) << "point " << i;
  }

  const double steps[] = {4.0 * kFinestStep, 2.0 * kFinestStep, kFinestStep};
  double displacement_error[3];
  double force_error[3];
  for (int k = 0; k < 3; ++k) {
    const ContactTrace trace = run_solver(c.system, road, c.static_load, steps[k]);
    const auto stride = static_cast<Eigen::Index>(std::llround(steps[k] / kFinestStep));
    const Eigen::MatrixXd ref_displacement = every(ref.displacement, stride);
    const Eigen::MatrixXd ref_force = every(ref.force, stride);
    ASSERT_EQ(trace.displacement.rows(), ref_displacement.rows());
    ASSERT_EQ(trace.displacement.cols(), ref_displacement.cols());
    EXPECT_NEAR(trace.indentation, ref.indentation, 1e-12 * std::abs(ref.indentation));
    displacement_error[k] = relative_rms(trace.displacement, ref_displacement);
    force_error[k] = relative_rms(trace.force, ref_force);
  }

  std::cout << std::setprecision(4) << "[" << c.name << "] contact switches " << ref.contact_switches
            << " (mode corrections " << ref.mode_corrections << "), CVODE steps " << ref.cvode_steps << "\n";
  for (int k = 0; k < 3; ++k) {
    std::cout << "[" << c.name << "] dt = " << steps[k] << " s: displacement error " << displacement_error[k]
              << ", force error " << force_error[k] << "\n";
    report("displacement_error_dt" + std::to_string(k), displacement_error[k]);
    report("force_error_dt" + std::to_string(k), force_error[k]);
  }
  // Halving Δt must at least halve the error, within 30 %: ratio ≥ 2/1.3.
  const double minimum_ratio = 2.0 / 1.3;
  for (int k = 0; k < 2; ++k) {
    const double displacement_ratio = displacement_error[k] / displacement_error[k + 1];
    const double force_ratio = force_error[k] / force_error[k + 1];
    std::cout << "[" << c.name << "] ratio dt " << steps[k] << " -> " << steps[k + 1] << ": displacement "
              << displacement_ratio << ", force " << force_ratio << "\n";
    report("displacement_ratio_" + std::to_string(k), displacement_ratio);
    report("force_ratio_" + std::to_string(k), force_ratio);
    EXPECT_GE(displacement_ratio, minimum_ratio) << "displacement, dt " << steps[k] << " -> " << steps[k + 1];
    EXPECT_GE(force_ratio, minimum_ratio) << "force, dt " << steps[k] << " -> " << steps[k + 1];
  }
  if (c.max_displacement_error) {
    EXPECT_LE(displacement_error[2], *c.max_displacement_error) << "relative RMS displacement error at dt = 1e-5 s";
  }
}

INSTANTIATE_TEST_SUITE_P(
    PointModels, CvodeConvergence,
    ::testing::Values(ConvergenceCase{"overdamped_sdof_W2", sdof(kOverDamped), kStaticLoad, 0.02},
                      ConvergenceCase{"overdamped_coupled_sdof_W2", coupled(kOverDamped), kStaticLoad, 0.02},
                      ConvergenceCase{"underdamped_sdof_W2", sdof(kUnderDamped), kStaticLoad, 0.02},
                      ConvergenceCase{"underdamped_coupled_sdof_W2", coupled(kUnderDamped), kStaticLoad, 0.02},
                      ConvergenceCase{"overdamped_sdof_W4", sdof(kOverDamped), kHeavyLoad, 0.02},
                      ConvergenceCase{"overdamped_coupled_sdof_W4", coupled(kOverDamped), kHeavyLoad, 0.02},
                      ConvergenceCase{"underdamped_sdof_W4", sdof(kUnderDamped), kHeavyLoad, std::nullopt},
                      ConvergenceCase{"underdamped_coupled_sdof_W4", coupled(kUnderDamped), kHeavyLoad, 0.02}),
    [](const ::testing::TestParamInfo<ConvergenceCase>& param) { return param.param.name; });

// The reference must not depend on its own tolerance. rtol 1e-8 against 1e-10: ~1e-6 in
// displacement; the force F_A = s·M_AA⁻¹(r_A + d − (M y)_A) is a small difference of
// displacements times s, so it magnifies their relative error by about s·y/F = s/k = 200 and
// gets 1e-5. The default reference (Adams, rtol 1e-10) against rtol 1e-12 and BDF at rtol
// 1e-10 against the same: within 1e-7 and 1e-6, far below the solver errors it judges (≥ 1e-3).
// The bouncing case (under-damped sdof, W = 4 N; see ConvergenceCase) magnifies every error,
// the reference's as well (measured: rtol 1e-8 vs 1e-10 6.8e-6 / 2.3e-5, BDF 4.0e-7 / 1.3e-6):
// there only the default reference against rtol 1e-12 is held to 1e-7 and 1e-6.
TEST(CvodeReference, IndependentOfTolerance) {
  struct ToleranceCase {
    LumpedSystem system;
    double load;
    bool bouncing;
  };
  const SineTestRoad road(kAmplitude, kWavelength);
  const Eigen::VectorXd times = sample_times(kDuration, kFinestStep);
  const ToleranceCase cases[] = {{sdof(kOverDamped), kStaticLoad, false},
                                 {coupled(kOverDamped), kStaticLoad, false},
                                 {sdof(kUnderDamped), kStaticLoad, false},
                                 {coupled(kUnderDamped), kStaticLoad, false},
                                 {sdof(kUnderDamped), kHeavyLoad, true}};
  for (const ToleranceCase& c : cases) {
    CvodeOptions loose;
    loose.relative_tolerance = 1e-8;
    CvodeOptions truth;
    truth.relative_tolerance = 1e-12;
    CvodeOptions bdf;
    bdf.method = reference::CvodeMethod::bdf;
    const auto run = [&](const CvodeOptions& options) {
      return reference::simulate_cvode_reference(c.system, road, kSpeed, c.load, times, options);
    };
    const CvodeReference a = run(loose);
    const CvodeReference b = run(CvodeOptions{});
    const CvodeReference t = run(truth);
    const CvodeReference d = run(bdf);
    const std::string label = std::to_string(c.system.points) + " point(s), r = " +
                              std::to_string(static_cast<int>(c.system.parameters.damping)) +
                              ", W = " + std::to_string(static_cast<int>(c.load));
    std::cout << std::setprecision(3) << "[reference, " << label << "] rtol 1e-8 vs 1e-10: displacement "
              << relative_rms(a.displacement, b.displacement) << ", force " << relative_rms(a.force, b.force)
              << "; 1e-10 vs 1e-12: displacement " << relative_rms(b.displacement, t.displacement) << ", force "
              << relative_rms(b.force, t.force) << "; BDF 1e-10 vs Adams 1e-12: displacement "
              << relative_rms(d.displacement, t.displacement) << ", force " << relative_rms(d.force, t.force)
              << "\n";
    EXPECT_LE(relative_rms(b.displacement, t.displacement), 1e-7) << label;
    EXPECT_LE(relative_rms(b.force, t.force), 1e-6) << label;
    EXPECT_EQ(a.contact_switches, b.contact_switches) << label;
    EXPECT_EQ(d.contact_switches, b.contact_switches) << label;
    if (c.bouncing) continue;
    EXPECT_LE(relative_rms(a.displacement, b.displacement), 1e-6) << label;
    EXPECT_LE(relative_rms(a.force, b.force), 1e-5) << label;
    // BDF is a different integrator (other order, other restarts after each switch).
    EXPECT_LE(relative_rms(d.displacement, t.displacement), 1e-7) << label;
    EXPECT_LE(relative_rms(d.force, t.force), 1e-6) << label;
  }
}

// On a flat road the static equilibrium is a fixed point: the masses never move, the contact
// points stay on the road (p = 0) and carry the static forces.
TEST(CvodeReference, FlatRoadStaysInStaticEquilibrium) {
  const FlatTestRoad road;
  const Eigen::VectorXd times = sample_times(0.5, 1e-3);
  for (const LumpedSystem& system : {sdof(kOverDamped), coupled(kOverDamped), sdof(kUnderDamped)}) {
    const CvodeReference ref = reference::simulate_cvode_reference(system, road, kSpeed, kStaticLoad, times);
    EXPECT_NEAR(ref.preload_force.sum(), kStaticLoad, 1e-12 * kStaticLoad);
    for (Eigen::Index n = 0; n < times.size(); ++n) {
      for (Eigen::Index i = 0; i < ref.force.cols(); ++i) {
        ASSERT_NEAR(ref.force(n, i), ref.preload_force(i), 1e-9 * kStaticLoad) << "t = " << times(n);
        ASSERT_NEAR(ref.displacement(n, i), 0.0, 1e-14) << "t = " << times(n);
      }
    }
    EXPECT_EQ(ref.contact_switches, 0);
  }
}

}  // namespace
}  // namespace rollnoise
