// Rolling contact of the point models: the contact conditions at every step, the static
// equilibrium on a flat road, and the coupling of eq. 7.
#include <cmath>

#include <gtest/gtest.h>

#include "contact/point_contact.hpp"
#include "greens/sdof_model.hpp"
#include "road/road_profile.hpp"

namespace rollnoise {
namespace {

const SdofParameters kTable1{1.0, 50.0, 500.0, 1e5};
const SdofParameters kUnderDamped{1.0, 5.0, 500.0, 1e5};

// Test roads written out here, independent of the road module: r = 0 for x < 0.
class Sine : public RoadProfile {
 public:
  Sine(double amplitude, double wavelength, double shift = 0.0)
      : amplitude_(amplitude), wavelength_(wavelength), shift_(shift) {}
  std::string type() const override { return "sine"; }
  double height(double x) const override {
    x -= shift_;
    return x < 0.0 ? 0.0 : amplitude_ * std::sin(2.0 * M_PI * x / wavelength_);
  }

 private:
  double amplitude_, wavelength_, shift_;
};

// A rough road: a sum of incommensurate sines with a smooth start.
class Rough : public RoadProfile {
 public:
  std::string type() const override { return "rough"; }
  double height(double x) const override {
    if (x < 0.0) return 0.0;
    const double ramp = x < 0.02 ? 0.5 - 0.5 * std::cos(M_PI * x / 0.02) : 1.0;
    return ramp * (6e-4 * std::sin(2 * M_PI * x / 0.071) + 4e-4 * std::sin(2 * M_PI * x / 0.023 + 1.0) +
                   2e-4 * std::sin(2 * M_PI * x / 0.0093 + 2.0));
  }
};

class Flat : public RoadProfile {
 public:
  std::string type() const override { return "flat"; }
  double height(double) const override { return 0.0; }
};

RollingSettings settings(double duration, double dt, double load,
                         Discretisation d = Discretisation::step) {
  RollingSettings s;
  s.speed = 1.0;
  s.duration = duration;
  s.time_step = dt;
  s.static_load = load;
  s.discretisation = d;
  return s;
}

void expect_contact_conditions(const ContactTrace& t) {
  const double max_force = t.force.maxCoeff();
  const double max_gap = t.gap.maxCoeff();
  ASSERT_GT(max_force, 0.0);
  ASSERT_GT(max_gap, 0.0) << "the case is meant to lose contact";
  EXPECT_GE(t.force.minCoeff(), 0.0);
  EXPECT_GE(t.gap.minCoeff(), -1e-12);
  // Round-off: a gap of a contact point is ~1e-16 of the displacements, times the force.
  EXPECT_LE((t.force.array() * t.gap.array()).abs().maxCoeff(), 1e-13 * max_force * max_gap);
  // displacement is the position in the road's datum: ≥ road, equal in contact.
  EXPECT_LE((t.displacement - t.road - t.gap).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(PointContact, ContactConditionsHoldAtEveryStep) {
  const Sine sine(1e-3, 0.1);
  const Rough rough;
  for (const SdofParameters& p : {kTable1, kUnderDamped}) {
    const SdofModel sdof(p);
    const SdofModel coupled(p, 0.4, 0.01);
    for (const RoadProfile* road : {static_cast<const RoadProfile*>(&sine), static_cast<const RoadProfile*>(&rough)}) {
      SCOPED_TRACE("damping " + std::to_string(p.damping) + ", road " + road->type());
      expect_contact_conditions(simulate_point_contact(sdof, *road, settings(0.3, 1e-4, 4.0)));
      expect_contact_conditions(simulate_point_contact(coupled, *road, settings(0.3, 1e-4, 8.0)));
      expect_contact_conditions(
          simulate_point_contact(sdof, *road, settings(0.3, 1e-4, 4.0, Discretisation::rectangle)));
    }
  }
}

TEST(PointContact, FlatRoadKeepsTheStaticLoad) {
  const Flat flat;
  for (Discretisation d : {Discretisation::step, Discretisation::rectangle}) {
    for (const SdofParameters& p : {kTable1, kUnderDamped}) {
      const ContactTrace single = simulate_point_contact(SdofModel(p), flat, settings(0.5, 1e-4, 4.0, d));
      EXPECT_LE((single.force.array() - 4.0).abs().maxCoeff(), 1e-9 * 4.0);
      const ContactTrace pair = simulate_point_contact(SdofModel(p, 0.4, 0.01), flat, settings(0.5, 1e-4, 8.0, d));
      EXPECT_LE((pair.force.array() - 4.0).abs().maxCoeff(), 1e-9 * 4.0);
      EXPECT_LE(pair.displacement.cwiseAbs().maxCoeff(), 1e-15);
    }
  }
}

TEST(PointContact, StartsWithoutTransient) {
  // The first sample is the static equilibrium: the force is the load, the point on the road.
  const ContactTrace t = simulate_point_contact(SdofModel(kTable1), Sine(1e-3, 0.1), settings(0.01, 1e-4, 4.0));
  EXPECT_NEAR(t.force(0, 0), 4.0, 1e-12);
  EXPECT_NEAR(t.displacement(0, 0), 0.0, 1e-18);
  EXPECT_NEAR(t.indentation, 4.0 * (1.0 / 1e5 + 1.0 / 500.0), 1e-17);
}

TEST(PointContact, UncoupledPairIsTwoIndependentSdofRuns) {
  const Sine road(1e-3, 0.1);
  const RollingSettings pair_settings = settings(0.4, 1e-4, 8.0);
  const RollingSettings single_settings = settings(0.4, 1e-4, 4.0);
  const ContactTrace pair = simulate_point_contact(SdofModel(kTable1, 0.0, 0.01), road, pair_settings);
  const ContactTrace first = simulate_point_contact(SdofModel(kTable1), road, single_settings);
  // Point 2 sees the road 0.01 m behind point 1.
  const ContactTrace second = simulate_point_contact(SdofModel(kTable1), Sine(1e-3, 0.1, 0.01), single_settings);
  const double scale = first.force.maxCoeff();
  // Same arithmetic up to the order of summation inside the matrix–vector products.
  EXPECT_LE((pair.force.col(0) - first.force.col(0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LE((pair.force.col(1) - second.force.col(0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LE((pair.displacement.col(1) - second.displacement.col(0)).cwiseAbs().maxCoeff(), 1e-15);

  // With c = 0.4 the points feel each other.
  const ContactTrace coupled = simulate_point_contact(SdofModel(kTable1, 0.4, 0.01), road, pair_settings);
  EXPECT_GT((coupled.force.col(0) - first.force.col(0)).cwiseAbs().maxCoeff(), 0.1 * scale);
}

TEST(PointContact, WarnsAboutCoarseTimeSteps) {
  const SdofModel model(kTable1);  // in contact: √((k+s)/m) = 317 rad/s
  EXPECT_TRUE(check_time_step(model, 1e-4).empty());
  const auto warnings = check_time_step(model, 5e-3);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("time_step"), std::string::npos);
}

}  // namespace
}  // namespace rollnoise
