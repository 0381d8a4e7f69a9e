// The boundary-element contact of the tread rubber on fine road texture
// (halfspace_texture_contact.hpp) against classic results: Hertz's sphere on a half-space (force
// and contact radius over a decade of approach), Boussinesq's flat circular punch, and the full
// contact of a flat cell against Love's uniformly loaded rectangle (a lower bound).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "contact/halfspace_texture_contact.hpp"
#include "greens/tread_compliance.hpp"

namespace rollnoise {
namespace {

constexpr double E = 4e6;    // Pa, tread rubber at kHz rates (order of magnitude)
constexpr double nu = 0.45;  // nearly incompressible

TEST(HalfspaceTextureContact, HertzSphereForceAndRadius) {
  // A paraboloidal bump h = -r²/(2R), R = 10 mm, on a 256 × 256 grid of 5 µm. Hertz (rigid
  // indenter, elastic half-space): F = (4/3) E* sqrt(R) δ^(3/2), a = sqrt(R δ), E* = E/(1 − ν²).
  const std::size_t n = 256;
  const double h = 5e-6, radius = 0.01;
  std::vector<double> heights(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double x = (static_cast<double>(i) - 127.5) * h, y = (static_cast<double>(j) - 127.5) * h;
      heights[i * n + j] = -(x * x + y * y) / (2.0 * radius);
    }
  const HalfspaceTextureContact contact(n, n, h, h, E, nu);
  const double e_star = E / (1.0 - nu * nu);
  for (double approach : {1e-6, 3e-6, 1e-5}) {
    // The grid's highest cell sits 0.5·(h/√2)²/R below the apex: the approach from the apex.
    const double apex = (2.0 * 0.25 * h * h) / (2.0 * radius);
    const HalfspaceContactResult r = contact.solve(heights, approach - apex);
    ASSERT_TRUE(r.converged) << approach;
    const double hertz = 4.0 / 3.0 * e_star * std::sqrt(radius) * std::pow(approach, 1.5);
    const double a = std::sqrt(radius * approach);
    EXPECT_NEAR(r.force / hertz, 1.0, 0.02) << "δ = " << approach;
    EXPECT_NEAR(std::sqrt(r.contact_area / std::numbers::pi) / a, 1.0, 0.03) << "δ = " << approach;
  }
}

TEST(HalfspaceTextureContact, FlatCircularPunchIsBoussinesqs) {
  // A flat-topped circular plateau of radius a = 0.4 mm (40 cells of 10 µm), the rest 1 mm lower:
  // the rigid flat punch of Boussinesq, F = 2 a E* δ, exactly.
  const std::size_t n = 128;
  const double h = 1e-5, a = 4e-4;
  std::vector<double> heights(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double x = (static_cast<double>(i) - 63.5) * h, y = (static_cast<double>(j) - 63.5) * h;
      heights[i * n + j] = x * x + y * y <= a * a ? 0.0 : -1e-3;
    }
  const HalfspaceTextureContact contact(n, n, h, h, E, nu);
  const double approach = 1e-5;
  const HalfspaceContactResult r = contact.solve(heights, approach);
  ASSERT_TRUE(r.converged);
  // The pixelated disc's area, as an equivalent radius.
  const double a_grid = std::sqrt(r.contact_area / std::numbers::pi);
  EXPECT_NEAR(a_grid / a, 1.0, 0.01);
  EXPECT_NEAR(r.force / (2.0 * a_grid * E / (1.0 - nu * nu) * approach), 1.0, 0.02);
}

TEST(HalfspaceTextureContact, FlatCellInFullContactAgainstLovesRectangle) {
  // A flat 4 mm × 12.8 mm cell (a contact cell of the tyre grid) pressed δ into the rubber: full
  // contact, a rigid rectangular punch. Love's uniformly loaded rectangle, its displacement
  // averaged over the cell by a 200 × 200 midpoint quadrature, gives F_L = δ A / ū: a lower bound
  // on the punch's force (uniform pressure is one admissible distribution; the punch's, gathered
  // at the edges, has the least compliance). For a circle the ratio is 32/(3π²) = 1.081
  // (2aE* against 3π²aE*/16); the rectangle comes out 1.075.
  const std::size_t nx = 40, ny = 128;
  const double dx = 1e-4, dy = 1e-4, a = 0.5 * nx * dx, b = 0.5 * ny * dy;
  const HalfspaceTextureContact contact(nx, ny, dx, dy, E, nu);
  const double approach = 1e-5;
  const HalfspaceContactResult r = contact.solve(std::vector<double>(nx * ny, 0.0), approach);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.contact_area, 4 * a * b, 1e-12);
  double mean = 0.0;
  const int q = 200;
  for (int i = 0; i < q; ++i)
    for (int j = 0; j < q; ++j)
      mean += love_rectangle_displacement(-a + 2 * a * (i + 0.5) / q, -b + 2 * b * (j + 0.5) / q, a, b, E, nu);
  mean /= q * q;
  const double love = approach * 4 * a * b / mean;
  EXPECT_GT(r.force, love);
  EXPECT_NEAR(r.force / love, 1.075, 0.02) << r.force << " N against " << love << " N";
}

TEST(HalfspaceTextureContact, RandomTexturePressureFallsExponentiallyWithSeparation) {
  // A self-affine random texture (Hurst 0.8, wavelengths from 64 µm to half the 1.28 mm patch,
  // rms 10 µm) on a 128 × 128 grid of 10 µm. At low load the mean pressure falls exponentially
  // with the mean separation, p ∝ exp(−ū/u₀) (Persson; measured on road surfaces by Wang, Persson
  // et al., Tribol. Lett. 56 (2014)): ln p is close to linear in ū. u₀/h_rms is reported, not
  // forced (published about 0.4-0.5 for large systems). Measured here (2026-11-27): u₀/h_rms =
  // 0.25 and R² = 0.981 over approaches of 0.4 to 1.6 h_rms; at 0.2 to 1.0 h_rms (fewer
  // contacts on this small grid) R² falls to 0.975.
  const std::size_t n = 128;
  const double h = 1e-5, length = h * n;
  std::vector<double> heights(n * n, 0.0);
  std::mt19937_64 engine(11);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  const double hurst = 0.8;
  for (int kx = -32; kx <= 32; ++kx)
    for (int ky = 0; ky <= 32; ++ky) {
      if (ky == 0 && kx <= 0) continue;  // one of each ± pair
      const double q = std::hypot(kx, ky);
      if (q < 2.0 || q > 20.0) continue;  // 1.28 mm / 2 ... 64 µm
      const double amplitude = std::pow(q, -(1.0 + hurst));
      const double phi = phase(engine);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
          heights[i * n + j] += amplitude * std::cos(2.0 * std::numbers::pi * (kx * static_cast<double>(i) + ky * static_cast<double>(j)) / n + phi);
    }
  double mean = 0.0, square = 0.0;
  for (double v : heights) mean += v / (n * n);
  for (double& v : heights) v -= mean;
  for (double v : heights) square += v * v / (n * n);
  const double rms_target = 1e-5, scale = rms_target / std::sqrt(square);
  for (double& v : heights) v *= scale;
  const double top = *std::max_element(heights.begin(), heights.end());
  const HalfspaceTextureContact contact(n, n, h, h, E, nu);
  std::vector<double> separation, log_pressure;
  std::vector<double> u(n * n);
  for (double approach = 4e-6; approach <= 1.6e-5; approach += 2e-6) {
    const HalfspaceContactResult r = contact.solve(heights, approach, 1e-8);
    ASSERT_TRUE(r.converged);
    contact.displacement(r.pressure, u);
    double gap = 0.0;
    for (std::size_t i = 0; i < n * n; ++i) gap += (top - approach + u[i] - heights[i]) / (n * n);
    separation.push_back(gap);
    log_pressure.push_back(std::log(r.force / (length * length)));
  }
  // Least-squares line ln p = c − ū/u₀, and its coefficient of determination.
  const double m = static_cast<double>(separation.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (std::size_t k = 0; k < separation.size(); ++k) {
    sx += separation[k];
    sy += log_pressure[k];
    sxx += separation[k] * separation[k];
    sxy += separation[k] * log_pressure[k];
    syy += log_pressure[k] * log_pressure[k];
  }
  const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  const double r2 = std::pow(m * sxy - sx * sy, 2) / ((m * sxx - sx * sx) * (m * syy - sy * sy));
  std::printf("  u0/h_rms = %.3f (R² of ln p against ū: %.4f; ū from %.2f to %.2f h_rms)\n", -1.0 / slope / rms_target, r2,
              separation.back() / rms_target, separation.front() / rms_target);
  EXPECT_LT(slope, 0.0);
  EXPECT_GT(r2, 0.98);
}

TEST(HalfspaceTextureContact, NoApproachNoForce) {
  const HalfspaceTextureContact contact(8, 8, 1e-4, 1e-4, E, nu);
  const HalfspaceContactResult r = contact.solve(std::vector<double>(64, 1e-3), 0.0);
  EXPECT_EQ(r.force, 0.0);
  EXPECT_THROW(contact.solve(std::vector<double>(63, 0.0), 1e-6), std::invalid_argument);
  EXPECT_THROW(contact.solve(std::vector<double>(64, 0.0), -1e-6), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
