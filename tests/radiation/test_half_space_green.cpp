// The half-space Green's function the radiation uses (radiation/half_space_green.hpp): the
// rigid road's limit, the pressure-release limit, reciprocity, and the tabulated absorbing
// road against the exact line integral (radiation/impedance_plane_green.hpp), values and the
// first and second derivatives the velocity matrix and the combined sources need.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "radiation/equivalent_sources.hpp"
#include "radiation/half_space_green.hpp"
#include "radiation/impedance_plane_green.hpp"
#include "radiation/reflected_field_table.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

// Admittances of porous asphalt's size (pa16 between its resonances and at its peak, both signs
// of Im β) and a large one.
const Complex kAdmittances[] = {{0.02, 0.05}, {0.01, -0.03}, {0.8, 0.1}, {0.3, -0.4}, {2.5, 0.5}};

TEST(HalfSpaceGreen, ZeroAdmittanceIsTheRigidRoadBitForBit) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-0.4, 0.4), h(0.002, 0.6);
  for (const double k : {0.4, 18.0, 103.0}) {
    const Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Random(3, 4).cwiseAbs() + Eigen::Matrix3Xd::Constant(3, 4, 0.01);
    const HalfSpaceGreen rigid(k, 0.0, reflection_region(points, points));
    EXPECT_EQ(rigid.table_nodes(), 0u);
    for (int n = 0; n < 200; ++n) {
      const Eigen::Vector3d x(u(random), u(random), h(random)), s(u(random), u(random), h(random));
      EXPECT_EQ(rigid(x, s), helmholtz_green(x, s, k, true));
      const Eigen::Vector3cd g = rigid.gradient(x, s), reference = helmholtz_green_gradient(x, s, k, true);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(g(c), reference(c));
    }
  }
}

TEST(HalfSpaceGreen, LargeAdmittanceTendsToPressureRelease) {
  // G − (direct − image) = O(1/|β|): the line integral's first term, −2·image/(β·…)… bounded
  // here by 5/|β| of the image's field at every geometry.
  const Eigen::Vector3d x(0.3, 0.1, 0.1), s(0.0, 0.0, 0.05);
  for (const double k : {2.0, 20.0, 100.0})
    for (const double beta : {1e3, 1e5}) {
      const HalfSpaceGreen plane(k, Complex(beta, 0.0));
      const Eigen::Vector3d image(s.x(), s.y(), -s.z());
      const double r1 = (x - s).norm(), r2 = (x - image).norm();
      const Complex release = std::exp(Complex(0.0, -k * r1)) / (4.0 * std::numbers::pi * r1) -
                              std::exp(Complex(0.0, -k * r2)) / (4.0 * std::numbers::pi * r2);
      const double image_field = 1.0 / (4.0 * std::numbers::pi * r2);
      EXPECT_LT(std::abs(plane(x, s) - release), 5.0 / beta * image_field) << "k " << k << " β " << beta;
    }
}

TEST(HalfSpaceGreen, SourceAndReceiverExchangeGiveTheSameField) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3), h(0.003, 0.5);
  Eigen::Matrix3Xd points(3, 40);
  for (Eigen::Index n = 0; n < points.cols(); ++n) points.col(n) = Eigen::Vector3d(u(random), u(random), h(random));
  for (const Complex beta : kAdmittances) {
    const HalfSpaceGreen table(60.0, beta, reflection_region(points, points)), exact(60.0, beta);
    for (Eigen::Index a = 0; a < points.cols(); ++a)
      for (Eigen::Index b = a + 1; b < points.cols(); b += 7) {
        EXPECT_LT(std::abs(table(points.col(a), points.col(b)) - table(points.col(b), points.col(a))),
                  1e-14 * std::abs(table(points.col(a), points.col(b))));
        EXPECT_LT(std::abs(exact(points.col(a), points.col(b)) - exact(points.col(b), points.col(a))),
                  1e-13 * std::abs(exact(points.col(a), points.col(b))));
      }
  }
}

// The table against the exact C over the tyre's region (sources 3 mm above the road and up, r
// to 0.7 m), from 20 Hz to 5.6 kHz: the value within 5e-5 of the image's field |E| = 1/(4πR₂),
// the first derivatives within 1e-4 of (k + 1/R₂)|E|, the second within 1e-3 of (k + 1/R₂)²|E|
// (the derivatives of the exact C by central differences, good to about 1e-7 of those).
// Measured 2026-11-28: at worst 1.3e-5, 2.9e-5 and 1.1e-4 (5.6 kHz, β = 0.3 − 0.4i, grazing).
TEST(HalfSpaceGreen, TableAgreesWithTheExactFunction) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ReflectionRegion region{0.7, 0.006, 1.3};
  double worst[3] = {0.0, 0.0, 0.0};
  for (const double hz : {20.0, 400.0, 1000.0, 3000.0, 5623.0}) {
    const double k = 2.0 * std::numbers::pi * hz / 343.2;
    for (const Complex beta : kAdmittances) {
      const HalfSpaceGreen green(k, beta, region);
      for (int n = 0; n < 60; ++n) {
        // Half the points near the road and near grazing, where the table is hardest.
        const double z = n % 2 ? region.z_min * std::pow(region.z_max / region.z_min, unit(random))
                               : region.z_min + 0.05 * unit(random);
        const double r = region.r_max * unit(random);
        if (!(std::hypot(r, z) > 0.0)) continue;
        const ReflectedField t = green.correction(r, z), e = green.exact_correction(r, z);
        const double radius = std::hypot(r, z);
        const double image = 1.0 / (4.0 * std::numbers::pi * radius), scale = k + 1.0 / radius;
        const double value = std::abs(t.value - e.value) / image;
        const double first = std::max(std::abs(t.dr - e.dr), std::abs(t.dz - e.dz)) / (scale * image);
        const double second = std::max({std::abs(t.drr - e.drr), std::abs(t.drz - e.drz), std::abs(t.dzz - e.dzz),
                                         std::abs(t.dr_over_r - e.dr_over_r)}) /
                              (scale * scale * image);
        worst[0] = std::max(worst[0], value);
        worst[1] = std::max(worst[1], first);
        worst[2] = std::max(worst[2], second);
        EXPECT_LT(value, 5e-5) << hz << " Hz, β " << beta << ", r " << r << ", Z " << z;
        EXPECT_LT(first, 1e-4) << hz << " Hz, β " << beta << ", r " << r << ", Z " << z;
        EXPECT_LT(second, 1e-3) << hz << " Hz, β " << beta << ", r " << r << ", Z " << z;
      }
    }
  }
  RecordProperty("worst_value", std::to_string(worst[0]));
  RecordProperty("worst_first_derivative", std::to_string(worst[1]));
  RecordProperty("worst_second_derivative", std::to_string(worst[2]));
  std::printf("worst relative errors: value %.2e, first %.2e, second %.2e\n", worst[0], worst[1], worst[2]);
}

TEST(HalfSpaceGreen, GradientIsTheDerivativeOfTheField) {
  // ∇_x G against central differences of G itself, table and exact paths.
  const Eigen::Vector3d s(0.02, -0.01, 0.004);
  for (const Complex beta : kAdmittances) {
    const double k = 50.0;
    Eigen::Matrix3Xd box(3, 2);
    box << -0.5, 0.5, -0.5, 0.5, 0.003, 0.4;
    const HalfSpaceGreen green(k, beta, reflection_region(box, box));
    for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.2, 0.1, 0.05), Eigen::Vector3d(0.01, 0.0, 0.3),
                                     Eigen::Vector3d(0.4, -0.3, 0.01)}) {
      const Eigen::Vector3cd g = green.gradient(x, s);
      const double step = 1e-6;
      for (int c = 0; c < 3; ++c) {
        Eigen::Vector3d plus = x, minus = x;
        plus(c) += step;
        minus(c) -= step;
        const Complex difference = (green(plus, s) - green(minus, s)) / (2.0 * step);
        EXPECT_LT(std::abs(g(c) - difference), 1e-4 * g.norm()) << "β " << beta << " component " << c;
      }
    }
  }
}

}  // namespace
}  // namespace rollnoise
