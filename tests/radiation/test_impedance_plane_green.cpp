// The point source over an impedance plane (radiation/impedance_plane_green.hpp) against its
// limits and against an independent evaluation of the Sommerfeld integral.
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "greens/gauss_legendre.hpp"
#include "radiation/impedance_plane_green.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr Complex i{0.0, 1.0};

Complex free_field(double k, double distance) {
  return std::exp(-i * k * distance) / (4.0 * std::numbers::pi * distance);
}

// The reflected field's correction to the rigid image by the wavenumber (Sommerfeld) integral,
// e^{+iωt}:  G − direct − image = (−i/4π) ∫₀^∞ J₀(κr)·(R_p − 1)·e^{−ik_z Z}·κ/k_z dκ,
// R_p − 1 = −2kβ/(k_z + kβ), k_z = √(k² − κ²) (−i√(κ² − k²) beyond k). Propagating part with
// κ = k sin φ, the rest with κ = k cosh u up to 2k (in 4096 slices: a surface-wave pole close to
// the axis, small Re β with Im β > 0, makes a peak of width ~Re β·|β| in u there), then in κ in
// panels of at most half a period of J₀, 24-point Gauss–Legendre each, until
// e^{−Z√(κ² − k²)} < e^{−46}.
Complex sommerfeld_correction(double k, double r, double height, Complex beta) {
  const test::GaussRule rule = test::gauss_legendre(24);
  const auto panel = [&](double a, double b, const auto& f) {
    Complex sum = 0.0;
    for (std::size_t n = 0; n < rule.nodes.size(); ++n)
      sum += rule.weights[n] * f(0.5 * (a + b) + 0.5 * (b - a) * rule.nodes[n]);
    return 0.5 * (b - a) * sum;
  };
  Complex total = 0.0;
  const auto propagating = [&](double phi) {
    const double kz = k * std::cos(phi);
    return std::cyl_bessel_j(0.0, k * r * std::sin(phi)) * (-2.0 * k * beta / (kz + k * beta)) *
           std::exp(-i * kz * height) * k * std::sin(phi);
  };
  const int slices = 64;
  for (int n = 0; n < slices; ++n)
    total += panel(0.5 * std::numbers::pi * n / slices, 0.5 * std::numbers::pi * (n + 1) / slices, propagating);
  const auto near = [&](double u) {
    return std::cyl_bessel_j(0.0, k * r * std::cosh(u)) * (-2.0 * beta / (beta - i * std::sinh(u))) *
           std::exp(-k * height * std::sinh(u)) * i * k * std::cosh(u);
  };
  const double u_end = std::acosh(2.0);
  const int near_slices = 4096;
  for (int n = 0; n < near_slices; ++n) total += panel(u_end * n / near_slices, u_end * (n + 1) / near_slices, near);
  const auto evanescent = [&](double kappa) {
    const Complex kz = -i * std::sqrt(kappa * kappa - k * k);
    return std::cyl_bessel_j(0.0, kappa * r) * (-2.0 * k * beta / (kz + k * beta)) * std::exp(-i * kz * height) *
           kappa / kz;
  };
  const double kappa_end = std::sqrt(k * k + std::pow(46.0 / height, 2));
  const double width = std::min(k, r > 0.0 ? std::numbers::pi / r : k);
  for (double a = 2.0 * k; a < kappa_end; a += width) total += panel(a, std::min(a + width, kappa_end), evanescent);
  return -i / (4.0 * std::numbers::pi) * total;
}

TEST(ImpedancePlaneGreen, ZeroAdmittanceIsTheRigidImage) {
  for (const double k : {0.5, 18.3, 183.0}) {
    const double r = 0.7, z = 0.1, zs = 0.002;
    const Complex expected = free_field(k, std::hypot(r, z - zs)) + free_field(k, std::hypot(r, z + zs));
    const Complex g = impedance_plane_green(k, r, z, zs, 0.0);
    EXPECT_LE(std::abs(g - expected), 1e-12 * std::abs(expected)) << "k = " << k;
  }
}

TEST(ImpedancePlaneGreen, InfiniteAdmittanceIsPressureRelease) {
  const double k = 18.3, r = 0.4, z = 0.1, zs = 0.05;
  const Complex release = free_field(k, std::hypot(r, z - zs)) - free_field(k, std::hypot(r, z + zs));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_LE(std::abs(impedance_plane_green(k, r, z, zs, inf) - release), 1e-15 * std::abs(release));
  // And the integral tends to it: 2kβ∫e^{−kβs} f(s) ds = 2f(0) + 2f'(0)/(kβ) + …, f the image
  // line's field, |f'(0)| ≤ |f(0)|·(k + 1/R₂)·Z/R₂: the difference falls as 1/|β|.
  const double r2 = std::hypot(r, z + zs);
  for (const Complex beta : {Complex(1e5, 0.0), Complex(3e4, 4e4), Complex(1e7, 0.0)}) {
    const Complex g = impedance_plane_green(k, r, z, zs, beta);
    const double bound = 3.0 * std::abs(free_field(k, r2)) * (1.0 + 1.0 / (k * r2)) * (z + zs) / (r2 * std::abs(beta));
    EXPECT_LE(std::abs(g - release), bound) << beta;
    EXPECT_GE(std::abs(g - release), 0.1 * bound) << beta;  // the 1/|β| law, not an accident
  }
}

TEST(ImpedancePlaneGreen, Reciprocity) {
  const Complex beta(0.35, -0.42);
  for (const double k : {1.0, 30.0, 150.0}) {
    const Complex a = impedance_plane_green(k, 0.6, 0.1, 0.002, beta);
    const Complex b = impedance_plane_green(k, 0.6, 0.002, 0.1, beta);
    EXPECT_LE(std::abs(a - b), 1e-13 * std::abs(a));
  }
}

// The line-integral form against the wavenumber integral, at kR₂ from 0.1 to 100, a source 2 mm
// above the road, and admittances of porous asphalt's size with both signs of Im β (a surface
// wave for one of them). The reference's quadrature error is below 1e-10 of the field (it does
// not change at 32 points per panel); 1e-8 of the rigid field's size leaves room for it.
TEST(ImpedancePlaneGreen, AgreesWithTheSommerfeldIntegral) {
  struct Geometry {
    double r, z, zs;
  };
  for (const Geometry geometry : {Geometry{0.2, 0.1, 0.002}, Geometry{0.5, 0.01, 0.002}, Geometry{0.0, 0.3, 0.1},
                                  Geometry{1.0, 0.3, 0.2}}) {
    const double r2 = std::hypot(geometry.r, geometry.z + geometry.zs);
    for (const double kr2 : {0.1, 1.0, 10.0, 100.0}) {
      const double k = kr2 / r2;
      for (const Complex beta : {Complex(0.3, 0.4), Complex(0.5, -0.2), Complex(0.05, -0.8), Complex(2.0, 1.5)}) {
        const double r1 = std::hypot(geometry.r, geometry.z - geometry.zs);
        const Complex rigid = free_field(k, r1) + free_field(k, r2);
        const Complex expected = rigid + sommerfeld_correction(k, geometry.r, geometry.z + geometry.zs, beta);
        const Complex g = impedance_plane_green(k, geometry.r, geometry.z, geometry.zs, beta);
        EXPECT_LE(std::abs(g - expected), 1e-8 * std::abs(free_field(k, r2)))
            << "r " << geometry.r << " z " << geometry.z << " zs " << geometry.zs << " kR2 " << kr2 << " beta " << beta
            << ": " << g << " vs " << expected;
      }
    }
  }
}

// The ground-effect geometry of the road reports (a source 0.05 m high heard 1.2 m high 7.5 m
// away) up to 10 kHz, with the nearly rigid admittance porous asphalt has between its
// resonances (|β| ≈ 0.016, Re β ≈ 0.015): the line integral then runs over the whole
// oscillating range s < R₂ before the factor e^{−kβs} ends it.
TEST(ImpedancePlaneGreen, AgreesWithTheSommerfeldIntegralAtThePassByGeometry) {
  const double r = 7.5, z = 1.2, zs = 0.05;
  const double r1 = std::hypot(r, z - zs), r2 = std::hypot(r, z + zs);
  for (const double f : {100.0, 1000.0, 2000.0, 10000.0}) {
    const double k = 2.0 * std::numbers::pi * f / 343.2;
    for (const Complex beta : {Complex(0.0146, -0.0059), Complex(0.002, 0.0226), Complex(0.45, 0.3)}) {
      const Complex expected = free_field(k, r1) + free_field(k, r2) + sommerfeld_correction(k, r, z + zs, beta);
      const Complex g = impedance_plane_green(k, r, z, zs, beta);
      EXPECT_LE(std::abs(g - expected), 1e-8 * std::abs(free_field(k, r2))) << f << " Hz, beta " << beta;
    }
  }
}

TEST(ImpedancePlaneGreen, RejectsBadArguments) {
  EXPECT_THROW(impedance_plane_green(0.0, 1.0, 0.1, 0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(impedance_plane_green(1.0, 1.0, 0.0, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(impedance_plane_green(1.0, 0.0, 0.1, 0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(impedance_plane_green(1.0, 1.0, 0.1, 0.1, Complex(-0.1, 0.2)), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
