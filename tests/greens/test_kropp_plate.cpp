// Kropp's plate (MODEL.md §4) checked against evaluations that share none of its modal code:
//   - the static compliance against a finite-difference solution of the plate equation on a
//     periodic × simply-supported grid (solved by FFT/DST, its residual checked by the stencils),
//     converging as h²;
//   - free waves against the Klein–Gordon Green's function of one lateral mode (Bessel J0),
//     including the wave front, and the dispersion relation;
//   - reciprocity and rotation invariance; the receptance as the numerical Fourier transform of
//     g(t); the static limit; and the passenger-car model file.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <fftw3.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "gauss_legendre.hpp"
#include "core/case_file.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/plate_factory.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

// A tyre-like parameter set (the model file's values, rounded) with few modes.
PlateParameters tyre_like(int M, int N) {
  PlateParameters p;
  p.radius = 0.316;
  p.width = 0.18;
  p.mass_per_area = 12.0;
  p.tension_x = 6.0e4;
  p.tension_y = 9.0e3;
  p.bending_x = 7.0;
  p.bending_y = 3.0;
  p.bending_xy = 4.6;
  p.foundation_stiffness = 3.2e6;
  p.loss_factor = 0.1;
  p.circumferential_modes = M;
  p.lateral_modes = N;
  return p;
}

// ---------------------------------------------------------------------------------------------
// Quadrature helpers.

using Rule = test::GaussRule;
using test::gauss_legendre;

template <class F>
double composite(F f, double lo, double hi, int panels, const Rule& rule) {
  double sum = 0.0;
  const double h = (hi - lo) / panels;
  for (int k = 0; k < panels; ++k) {
    const double mid = lo + (k + 0.5) * h;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * f(mid + 0.5 * h * rule.nodes[i]);
  }
  return 0.5 * h * sum;
}

// ---------------------------------------------------------------------------------------------
// 1. Static compliance against a finite-difference solution.
//
// The static plate equation is discretised on x_i = i·hx (i = 0 … Nx−1, periodic) and
// y_j = j·hy (j = 0 … Ny, w_0 = w_Ny = 0) with the second difference δ² = [1 −2 1]/h² and the
// fourth difference δ⁴ = δ²δ²; simply supported edges (w_yy = 0) mean the ghost values mirror
// with opposite sign, w_{−1} = −w_1. The load is a uniform pressure on a rectangle whose edges lie
// on grid lines, sampled with trapezoid weights (½ on an edge, ¼ at a corner): second order.
// The discrete operator is diagonalised by e^{2πi·m·i/Nx} (FFT, periodic) and sin(πnj/Ny)
// (DST-I, Dirichlet with antisymmetric ghosts); the symbols of δ² are −(4/h²)sin²(θ/2). The
// solution is then checked by applying the stencils directly, so the FFT is only a solver.

struct FdGrid {
  int nx, ny;  // periodic points in x; ny intervals across the width (ny − 1 unknowns)
  double hx, hy;
  std::vector<double> w;  // w[i·(ny−1) + (j−1)], j = 1 … ny−1
  double at(int i, int j) const {
    if (j <= 0 || j >= ny) return j == 0 || j == ny ? 0.0 : -at(i, j <= 0 ? -j : 2 * ny - j);
    i = ((i % nx) + nx) % nx;
    return w[static_cast<std::size_t>(i) * (ny - 1) + (j - 1)];
  }
};

struct Patch {
  double x0, x1, y0, y1;  // edges, m
  double area() const { return (x1 - x0) * (y1 - y0); }
};

// Trapezoid weight of grid coordinate c·h in [lo, hi] (edges on grid lines).
double trapezoid_weight(double c, double lo, double hi, double h) {
  const double tol = 1e-9 * h;
  if (c < lo - tol || c > hi + tol) return 0.0;
  if (std::abs(c - lo) < tol || std::abs(c - hi) < tol) return 0.5;
  return 1.0;
}

// Pressure 1/area on the patch (1 N in total); x positions are periodic about 0.
std::vector<double> fd_load(const PlateParameters& p, int nx, int ny, const Patch& patch) {
  const double L = 2.0 * pi * p.radius;
  const double hx = L / nx, hy = p.width / ny;
  std::vector<double> load(static_cast<std::size_t>(nx) * (ny - 1), 0.0);
  for (int i = 0; i < nx; ++i) {
    const double x = (i <= nx / 2 ? i : i - nx) * hx;
    const double wx = trapezoid_weight(x, patch.x0, patch.x1, hx);
    if (wx == 0.0) continue;
    for (int j = 1; j < ny; ++j) {
      const double wy = trapezoid_weight(j * hy, patch.y0, patch.y1, hy);
      load[static_cast<std::size_t>(i) * (ny - 1) + (j - 1)] = wx * wy / patch.area();
    }
  }
  return load;
}

FdGrid fd_solve(const PlateParameters& p, int nx, int ny, const std::vector<double>& load) {
  const double L = 2.0 * pi * p.radius;
  FdGrid g{nx, ny, L / nx, p.width / ny, load};
  std::vector<double> spectrum(load.size());
  // Rows are x (slow), columns y (fast): R2HC along x, RODFT00 (DST-I) along y.
  fftw_plan forward = fftw_plan_r2r_2d(nx, ny - 1, g.w.data(), spectrum.data(), FFTW_R2HC, FFTW_RODFT00,
                                       FFTW_ESTIMATE);
  fftw_plan backward = fftw_plan_r2r_2d(nx, ny - 1, spectrum.data(), g.w.data(), FFTW_HC2R, FFTW_RODFT00,
                                        FFTW_ESTIMATE);
  fftw_execute(forward);
  for (int k = 0; k < nx; ++k) {
    const int m = std::min(k, nx - k);  // half-complex: index k and nx − k both hold order m
    const double sx = std::sin(pi * m / nx);
    const double lx = -4.0 / (g.hx * g.hx) * sx * sx;  // symbol of δ²_x
    for (int n = 1; n < ny; ++n) {
      const double sy = std::sin(pi * n / (2.0 * ny));
      const double ly = -4.0 / (g.hy * g.hy) * sy * sy;  // symbol of δ²_y with the mirrored ghosts
      const double K = p.bending_x * lx * lx + 2.0 * p.bending_xy * lx * ly + p.bending_y * ly * ly -
                       p.tension_x * lx - p.tension_y * ly + p.foundation_stiffness;
      // R2HC→HC2R scales by nx, RODFT00 twice by 2·ny.
      spectrum[static_cast<std::size_t>(k) * (ny - 1) + (n - 1)] /= K * nx * 2.0 * ny;
    }
  }
  fftw_execute(backward);
  fftw_destroy_plan(forward);
  fftw_destroy_plan(backward);
  return g;
}

// max |stencils(w) − load| / max |load|: the FFT solution solves the difference equations.
double fd_residual(const PlateParameters& p, const FdGrid& g, const std::vector<double>& load) {
  const auto d2x = [&](int i, int j) { return (g.at(i - 1, j) - 2 * g.at(i, j) + g.at(i + 1, j)) / (g.hx * g.hx); };
  const auto d2y = [&](int i, int j) { return (g.at(i, j - 1) - 2 * g.at(i, j) + g.at(i, j + 1)) / (g.hy * g.hy); };
  const auto d2xd2y = [&](int i, int j) {
    return (d2y(i - 1, j) - 2 * d2y(i, j) + d2y(i + 1, j)) / (g.hx * g.hx);
  };
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < g.nx; ++i) {
    for (int j = 1; j < g.ny; ++j) {
      const double d4x = (g.at(i - 2, j) - 4 * g.at(i - 1, j) + 6 * g.at(i, j) - 4 * g.at(i + 1, j) +
                          g.at(i + 2, j)) / std::pow(g.hx, 4);
      const double d4y = (g.at(i, j - 2) - 4 * g.at(i, j - 1) + 6 * g.at(i, j) - 4 * g.at(i, j + 1) +
                          g.at(i, j + 2)) / std::pow(g.hy, 4);
      const double lhs = p.bending_x * d4x + 2 * p.bending_xy * d2xd2y(i, j) + p.bending_y * d4y -
                         p.tension_x * d2x(i, j) - p.tension_y * d2y(i, j) + p.foundation_stiffness * g.at(i, j);
      const double f = load[static_cast<std::size_t>(i) * (g.ny - 1) + (j - 1)];
      worst = std::max(worst, std::abs(lhs - f));
      scale = std::max(scale, std::abs(f));
    }
  }
  return worst / scale;
}

// Deflection at (x, y) under 1 N spread uniformly over the patch: the plate's static Green's
// function integrated over the source patch by tensor Gauss–Legendre (panels × panels of 8 × 8
// nodes; the truncated modal sum is a trigonometric polynomial, resolved by these nodes, which
// the test confirms by doubling the panels).
double modal_patch_deflection(const KroppPlate& plate, const Patch& patch, double x, double y, int panels = 4) {
  const Rule rule = gauss_legendre(8);
  const double integral = composite(
      [&](double xi) {
        return composite([&](double eta) { return plate.static_compliance(x - xi, y, eta); }, patch.y0,
                         patch.y1, panels, rule);
      },
      patch.x0, patch.x1, panels, rule);
  return integral / patch.area();
}

TEST(KroppPlate, StaticComplianceConvergesToFiniteDifferenceSolution) {
  // A small tyre-like plate (L = 0.628 m, b = 0.2 m): coarse grid 64 × 20 with hx ≈ hy ≈ 1 cm.
  PlateParameters p = tyre_like(128, 80);
  p.radius = 0.1;
  p.width = 0.2;
  const double L = 2.0 * pi * p.radius;
  const int nx0 = 64, ny0 = 20;
  const double hx0 = L / nx0, hy0 = p.width / ny0;
  // 4 × 4 coarse cells, off-centre across the width: x ∈ [−2hx, 2hx], y ∈ [5hy, 9hy].
  const Patch patch{-2 * hx0, 2 * hx0, 5 * hy0, 9 * hy0};

  // Receivers on the coarse grid (shared by all finer grids): the row through the patch centre
  // and the column through it.
  struct Receiver {
    int i, j;
  };
  std::vector<Receiver> receivers;
  for (int i = -12; i <= 12; ++i) receivers.push_back({i, 7});
  for (int j = 1; j < ny0; ++j)
    if (j != 7) receivers.push_back({0, j});

  // The modal reference. Its truncation (M = 128, N = 80: k ≈ 1270 rad/m both ways) is checked
  // against twice the modes: the change must stay far below the finest grid's error.
  const KroppPlate plate(p);
  PlateParameters p2 = p;
  p2.circumferential_modes = 256;
  p2.lateral_modes = 160;
  const KroppPlate plate2(p2);
  std::vector<double> reference;
  double scale = 0.0;
  for (const Receiver& r : receivers) {
    reference.push_back(modal_patch_deflection(plate, patch, r.i * hx0, r.j * hy0));
    scale = std::max(scale, std::abs(reference.back()));
  }
  const double truncation =
      std::abs(modal_patch_deflection(plate2, patch, 0.0, 7 * hy0) - modal_patch_deflection(plate, patch, 0.0, 7 * hy0));
  RecordProperty("modal_truncation_relative", std::to_string(truncation / scale));
  std::printf("modal truncation (M, N) = (128, 80) vs (256, 160): %.2e relative\n", truncation / scale);
  const double quadrature =
      std::abs(modal_patch_deflection(plate, patch, 0.0, 7 * hy0, 8) - modal_patch_deflection(plate, patch, 0.0, 7 * hy0));
  EXPECT_LT(quadrature / scale, 1e-9);

  std::vector<double> errors;
  for (int refine : {1, 2, 4, 8}) {
    const int nx = nx0 * refine, ny = ny0 * refine;
    const std::vector<double> load = fd_load(p, nx, ny, patch);
    const FdGrid g = fd_solve(p, nx, ny, load);
    EXPECT_LT(fd_residual(p, g, load), 1e-9) << "the FFT solution must solve the difference equations";
    double worst = 0.0;
    for (std::size_t k = 0; k < receivers.size(); ++k)
      worst = std::max(worst, std::abs(g.at(receivers[k].i * refine, receivers[k].j * refine) - reference[k]));
    errors.push_back(worst / scale);
    std::printf("FD %4d x %3d: max relative difference %.3e\n", nx, ny, worst / scale);
  }
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    const double ratio = errors[k] / errors[k + 1];
    std::printf("ratio h/(h/2): %.3f\n", ratio);
    RecordProperty("ratio_" + std::to_string(k), std::to_string(ratio));
    // Second order: halving h divides the error by 4 (the O(h⁴) remainder bends it slightly).
    EXPECT_NEAR(ratio, 4.0, 0.4) << "refinement " << k;
  }
  // At hx ≈ hy ≈ 1.2 mm the coarse grid's 2e-3 has shrunk by 4³ to a few 1e-5; the modal
  // truncation sits well below it.
  EXPECT_LT(errors.back(), 1e-4);
  EXPECT_LT(truncation / scale, 0.1 * errors.back());
  RecordProperty("finest_relative_difference", std::to_string(errors.back()));
}

// ---------------------------------------------------------------------------------------------
// 2. Free waves.

TEST(KroppPlate, DispersionRelation) {
  PlateParameters p = tyre_like(20, 10);
  p.bending_xy = 2.5;  // not the geometric mean: every term distinguishable
  const KroppPlate plate(p);
  for (int m : {0, 1, 7, 20}) {
    for (int n : {1, 4, 10}) {
      const double kx = 2.0 * pi * m / (2.0 * pi * p.radius);
      const double ky = n * pi / p.width;
      const double K = p.bending_x * std::pow(kx, 4) + 2.0 * p.bending_xy * kx * kx * ky * ky +
                       p.bending_y * std::pow(ky, 4) + p.tension_x * kx * kx + p.tension_y * ky * ky +
                       p.foundation_stiffness;
      const double w = plate.natural_frequency(m, n);
      EXPECT_NEAR(w * w * p.mass_per_area, K, 1e-13 * K) << "m = " << m << ", n = " << n;
      EXPECT_NEAR(plate.modal_stiffness(m, n), K, 1e-13 * K);
    }
  }
  EXPECT_NEAR(plate.modal_mass(), p.mass_per_area * 2.0 * pi * p.radius * p.width / 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(plate.damping_ratio(), 0.05);
}

// One lateral mode without bending: m''w_tt − Tx w_xx + κ w = p with κ = Ty k1² + s_f, whose
// infinite-line Green's function is G = H(t − |x|/c) J0(ω_c √(t² − x²/c²)) / (2m''c). On the ring
// the images x + jL arrive only after t = (L − |x|)/c.
struct KleinGordon {
  double m, c, wc;
  // ∫_0^t G dτ: with s = √(τ² − x²/c²) the integrand J0(ω_c s)·s/√(s² + x²/c²) is smooth.
  double step(double x, double t) const {
    const double x0 = std::abs(x) / c;
    if (t <= x0) return 0.0;
    const double S = std::sqrt(t * t - x0 * x0);
    static const Rule rule = gauss_legendre(10);
    const double integral = composite(
        [&](double s) { return std::cyl_bessel_j(0.0, wc * s) * s / std::sqrt(s * s + x0 * x0); }, 0.0, S,
        200, rule);
    return integral / (2.0 * m * c);
  }
  double impulse(double x, double t) const {
    const double x0 = std::abs(x) / c;
    if (t <= x0) return 0.0;
    return std::cyl_bessel_j(0.0, wc * std::sqrt(t * t - x0 * x0)) / (2.0 * m * c);
  }
};

TEST(KroppPlate, OneLateralModeIsKleinGordon) {
  PlateParameters p;
  p.radius = 0.3;
  p.width = 0.2;
  p.mass_per_area = 10.0;
  p.tension_x = 5.0e4;
  p.tension_y = 5.0e3;
  p.foundation_stiffness = 2.0e6;
  p.loss_factor = 1e-4;
  p.circumferential_modes = 2000;
  p.lateral_modes = 1;
  const KroppPlate plate(p);
  const double L = plate.circumference();
  const double k1 = pi / p.width;
  const KleinGordon kg{p.mass_per_area, std::sqrt(p.tension_x / p.mass_per_area),
                       std::sqrt((p.tension_y * k1 * k1 + p.foundation_stiffness) / p.mass_per_area)};
  const int M = p.circumferential_modes;
  // At y = y0 = b/2 the lateral factor is sin² = 1 and g = (2/b)·(ring Green's function).
  const double y = p.width / 2.0;
  const double project = p.width / 2.0;
  const double zeta = plate.damping_ratio();

  double worst = 0.0;
  for (double t : {0.004, 0.01, 0.016, 0.022}) {
    // Error bounds for ∫_0^t g, independent of the plate's code:
    //  truncation: the omitted orders |m| > M each contribute (1 − E)/(m''L ω_m²) with |1 − E| ≤ 2,
    //    so |tail| ≤ 2·2·Σ_{m>M} 1/(L·Tx·k_m²) ≤ 4/(L·Tx)·(L/2π)²/M = L/(π²·Tx·M);
    //  damping: per mode |E_ζ − E_0| ≤ ζ(ω_m t + 1) to first order in ζ, summed over the kept modes.
    double damping_bound = 0.0;
    for (int m = -M; m <= M; ++m) {
      const double km = 2.0 * pi * m / L;
      const double wm = std::sqrt(kg.c * kg.c * km * km + kg.wc * kg.wc);
      damping_bound += zeta * (wm * t + 1.0) / (p.mass_per_area * L * wm * wm);
    }
    const double tolerance = L / (pi * pi * p.tension_x * M) + damping_bound;
    for (double x : {0.0, 0.05, 0.2, 0.45, 0.8, -0.3}) {
      if (t >= (L - std::abs(x)) / kg.c) continue;  // an image has arrived
      const double plate_step = project * plate.green_integral(x, y, y, 0.0, t);
      const double exact = kg.step(x, t);
      EXPECT_NEAR(plate_step, exact, tolerance) << "x = " << x << ", t = " << t;
      worst = std::max(worst, std::abs(plate_step - exact) / (t / (2.0 * kg.m * kg.c)));
      // The wave front: nothing arrives before |x|/c (the analytic integral is exactly 0 there).
      if (t < std::abs(x) / kg.c) {
        EXPECT_NEAR(plate_step, 0.0, tolerance) << "ahead of the front, x = " << x << ", t = " << t;
      }
    }
  }
  RecordProperty("klein_gordon_worst_relative", std::to_string(worst));
  std::printf("Klein-Gordon step response: worst difference %.2e of t/(2m''c)\n", worst);

  // Pointwise, the truncated sum rings (Gibbs) around the jump of G at the front, decaying as
  // 1/(k_M·distance): 0.1 m or more from the front that is 1/(π·k_M·0.1) ≈ 5e-4 of the jump
  // 1/(2m''c) (k_M = 2πM/L = 6.7e3 rad/m). Light damping shifts it by less: allow 2e-3.
  const double jump = 1.0 / (2.0 * kg.m * kg.c);
  double worst_point = 0.0;
  for (double t : {0.004, 0.01, 0.016}) {
    for (double x : {0.0, 0.15, 0.5, 0.9}) {
      const double front = kg.c * t;
      if (std::abs(std::abs(x) - front) < 0.1 || t >= (L - std::abs(x)) / kg.c) continue;
      const double g = project * plate.green(x, y, y, t);
      const double exact = kg.impulse(x, t);
      EXPECT_NEAR(g, exact, 2e-3 * jump) << "x = " << x << ", t = " << t;
      worst_point = std::max(worst_point, std::abs(g - exact) / jump);
    }
  }
  RecordProperty("klein_gordon_pointwise_relative", std::to_string(worst_point));
  std::printf("Klein-Gordon impulse response: worst difference %.2e of the jump\n", worst_point);
}

// ---------------------------------------------------------------------------------------------
// 3. Reciprocity and rotation invariance.

TEST(KroppPlate, ReciprocalAndRotationInvariant) {
  const KroppPlate plate(tyre_like(64, 8));
  const double L = plate.circumference();
  const double b = plate.parameters().width;
  const double scale_g = std::abs(plate.green(0.0, b / 2, b / 2, 1e-3));
  const double scale_c = plate.static_compliance(0.0, b / 2, b / 2);
  const double scale_r = std::abs(plate.receptance(0.0, b / 2, b / 2, 700.0));  // near ω_01
  for (double dx : {0.0, 0.013, -0.27, 0.9}) {
    for (double y : {0.01, 0.07, 0.15}) {
      for (double y0 : {0.03, 0.09}) {
        for (double t : {2e-4, 1.7e-3, 9e-3}) {
          const double g = plate.green(dx, y, y0, t);
          // Reciprocity: swapping the points reverses dx and swaps y, y0.
          EXPECT_NEAR(plate.green(-dx, y0, y, t), g, 1e-13 * scale_g);
          // Symmetric plate: the response ahead equals the response behind.
          EXPECT_NEAR(plate.green(-dx, y, y0, t), g, 1e-13 * scale_g);
          // Rotation by whole turns: the same dx anywhere around the circumference.
          for (int turns : {-2, 1, 3}) {
            EXPECT_NEAR(plate.green(dx + turns * L, y, y0, t), g, 1e-12 * scale_g) << turns;
          }
          const double gi = plate.green_integral(dx, y, y0, t, 2 * t);
          EXPECT_NEAR(plate.green_integral(-dx, y0, y, t, 2 * t), gi, 1e-13 * scale_c);
          EXPECT_NEAR(plate.green_integral(dx + L, y, y0, t, 2 * t), gi, 1e-12 * scale_c);
        }
        const std::complex<double> a = plate.receptance(dx, y, y0, 700.0);
        EXPECT_LT(std::abs(plate.receptance(-dx, y0, y, 700.0) - a), 1e-13 * scale_r);
        EXPECT_LT(std::abs(plate.receptance(dx - 2 * L, y, y0, 700.0) - a), 1e-12 * scale_r);
      }
    }
  }
  // Simply supported edges: no response there.
  EXPECT_NEAR(plate.static_compliance(0.1, 0.0, 0.05), 0.0, 1e-15 * scale_c);
  EXPECT_NEAR(plate.static_compliance(0.1, b, 0.05), 0.0, 1e-15 * scale_c);
}

// ---------------------------------------------------------------------------------------------
// 4./5. Frequency domain and integrals.

TEST(KroppPlate, ReceptanceIsFourierTransformOfGreen) {
  // Six modes with 5% damping: g has decayed to e^{−40} by T = 40/(ζ·ω_min).
  PlateParameters p = tyre_like(2, 2);
  p.loss_factor = 0.1;
  const KroppPlate plate(p);
  const double dx = 0.1, y = 0.05, y0 = 0.12;
  const double T = 40.0 / plate.slowest_decay_rate();
  const double dt = 0.02 / plate.fastest_rate();
  const int n = 2 * static_cast<int>(std::ceil(T / dt / 2.0));
  const double h = T / n;
  std::vector<double> g(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) g[static_cast<std::size_t>(k)] = plate.green(dx, y, y0, k * h);
  const double w01 = plate.natural_frequency(0, 1);
  for (double omega : {0.0, 300.0, w01, 1000.0, 2500.0}) {
    // Composite Simpson: error ~ h⁴·(ω_max + ω)⁴/180 relative, below 1e-8 here.
    std::complex<double> sum = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      sum += weight * g[static_cast<std::size_t>(k)] * std::exp(std::complex<double>(0.0, -omega * k * h));
    }
    sum *= h / 3.0;
    const std::complex<double> alpha = plate.receptance(dx, y, y0, omega);
    EXPECT_LT(std::abs(sum - alpha), 1e-7 * std::abs(alpha)) << "omega = " << omega;
    const std::complex<double> Y = plate.mobility(dx, y, y0, omega);
    EXPECT_LT(std::abs(Y - std::complex<double>(0.0, omega) * alpha), 1e-15 * std::abs(Y) + 1e-300);
  }
  // The mode oscillators agree with the modal stiffness and the loss factor.
  const SdofOscillator o = plate.mode_oscillator(1, 2);
  EXPECT_DOUBLE_EQ(o.stiffness, plate.modal_stiffness(1, 2) / p.mass_per_area);
  EXPECT_DOUBLE_EQ(o.damping, p.loss_factor * plate.natural_frequency(1, 2));
  // The hysteretic and the viscous forms agree at resonance (the documented choice).
  const double w = plate.natural_frequency(1, 2);
  EXPECT_NEAR(std::abs(o.receptance(w)), 1.0 / (p.loss_factor * w * w), 1e-12 / (w * w));
}

TEST(KroppPlate, IntegralsAndStaticLimit) {
  const KroppPlate plate(tyre_like(64, 8));
  const double dx = 0.05, y = 0.06, y0 = 0.1;
  const double C = plate.green_integral(dx, y, y0, 0.0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(C, plate.static_compliance(dx, y, y0));
  // Receptance at ω → 0 is the static compliance.
  EXPECT_NEAR(plate.receptance(dx, y, y0, 0.0).real(), C, 1e-13 * std::abs(C));
  EXPECT_NEAR(plate.receptance(dx, y, y0, 0.0).imag(), 0.0, 1e-20);
  EXPECT_NEAR(plate.receptance(dx, y, y0, 1e-3).real(), C, 1e-9 * std::abs(C));
  // Intervals add up: ∫_0^t1 + ∫_t1^∞ = C, and a long interval converges to it.
  const double t1 = 3e-3;
  EXPECT_NEAR(plate.green_integral(dx, y, y0, 0.0, t1) +
                  plate.green_integral(dx, y, y0, t1, std::numeric_limits<double>::infinity()),
              C, 1e-13 * std::abs(C));
  EXPECT_NEAR(plate.green_integral(dx, y, y0, 0.0, 60.0 / plate.slowest_decay_rate()), C, 1e-13 * std::abs(C));
  EXPECT_NEAR(plate.green_integral(dx, y, y0, t1, 0.0), -plate.green_integral(dx, y, y0, 0.0, t1), 1e-25);
  // Interval integrals against Simpson quadrature of green() (400 panels over 0.5 ms:
  // error ~ (h·ω_max)⁴/180 ≈ 1e-10 relative).
  for (double t0 : {0.0, 1e-3, 2.5e-2}) {
    const double ta = t0, tb = t0 + 5e-4;
    const int n = 400;
    const double h = (tb - ta) / n;
    double sum = plate.green(dx, y, y0, ta) + plate.green(dx, y, y0, tb);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * plate.green(dx, y, y0, ta + k * h);
    const double simpson = sum * h / 3.0;
    EXPECT_NEAR(plate.green_integral(dx, y, y0, ta, tb), simpson, 1e-8 * std::abs(C)) << "t0 = " << t0;
  }
  // Causality: nothing before the impulse.
  EXPECT_EQ(plate.green(dx, y, y0, -1e-3), 0.0);
  EXPECT_EQ(plate.green(dx, y, y0, 0.0), 0.0);
  EXPECT_EQ(plate.green_integral(dx, y, y0, -1.0, 0.0), 0.0);
  // Rates: the slowest decay is ζ·ω_01, the fastest rate ω_MN.
  EXPECT_NEAR(plate.slowest_decay_rate(), 0.05 * plate.natural_frequency(0, 1), 1e-12);
  EXPECT_NEAR(plate.fastest_rate(), plate.natural_frequency(64, 8), 1e-9);
}

TEST(KroppPlate, OverDampedModesStillIntegrate) {
  PlateParameters p = tyre_like(4, 2);
  p.loss_factor = 2.5;  // ζ = 1.25: every mode over-damped
  const KroppPlate plate(p);
  const double C = plate.static_compliance(0.02, 0.05, 0.08);
  EXPECT_NEAR(plate.green_integral(0.02, 0.05, 0.08, 0.0, 200.0 / plate.slowest_decay_rate()), C,
              1e-12 * std::abs(C));
  EXPECT_NEAR(plate.receptance(0.02, 0.05, 0.08, 0.0).real(), C, 1e-13 * std::abs(C));
}

TEST(KroppPlate, RejectsInvalidParameters) {
  const auto message = [](PlateParameters p) {
    try {
      KroppPlate plate(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const PlateParameters ok = tyre_like(4, 2);
  const auto expect_names = [&](auto mutate, const std::string& name) {
    PlateParameters p = ok;
    mutate(p);
    EXPECT_NE(message(p).find(name), std::string::npos) << message(p);
  };
  expect_names([](PlateParameters& p) { p.radius = 0.0; }, "radius");
  expect_names([](PlateParameters& p) { p.width = -1.0; }, "width");
  expect_names([](PlateParameters& p) { p.mass_per_area = std::nan(""); }, "mass_per_area");
  expect_names([](PlateParameters& p) { p.tension_x = -1.0; }, "tension_x");
  expect_names([](PlateParameters& p) { p.tension_y = -1.0; }, "tension_y");
  expect_names([](PlateParameters& p) { p.bending_x = -1.0; }, "bending_x");
  expect_names([](PlateParameters& p) { p.bending_y = -1.0; }, "bending_y");
  expect_names([](PlateParameters& p) { p.bending_xy = -1.0; }, "bending_xy");
  expect_names([](PlateParameters& p) { p.foundation_stiffness = -1.0; }, "foundation_stiffness");
  expect_names(
      [](PlateParameters& p) {
        p.foundation_stiffness = 0.0;
        p.tension_y = 0.0;
        p.bending_y = 0.0;
      },
      "foundation_stiffness");
  expect_names([](PlateParameters& p) { p.loss_factor = -0.1; }, "loss_factor");
  EXPECT_EQ(message([&] { PlateParameters p = ok; p.loss_factor = 0.0; return p; }()), "no exception");  // undamped: allowed
  expect_names([](PlateParameters& p) { p.circumferential_modes = -1; }, "circumferential_modes");
  expect_names([](PlateParameters& p) { p.lateral_modes = 0; }, "lateral_modes");
  // A plate held only by lateral tension is fine; M = 0 is allowed.
  PlateParameters membrane = ok;
  membrane.foundation_stiffness = 0.0;
  membrane.circumferential_modes = 0;
  EXPECT_EQ(message(membrane), "no exception");
  // Points outside the width are rejected.
  const KroppPlate plate(ok);
  EXPECT_THROW(plate.green(0.0, -0.01, 0.05, 1e-3), std::invalid_argument);
  EXPECT_THROW(plate.static_compliance(0.0, 0.05, 0.19), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// 6. The passenger-car model file.

TEST(KroppPlate, PassengerCarModelFile) {
  const std::string path = std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/passenger_205_55R16.toml";
  const toml::table t = toml::parse_file(path);
  ASSERT_EQ(t["model"].value<std::string>(), "plate");
  const auto number = [&](const char* key) {
    const auto v = t[key].value<double>();
    if (!v) throw std::runtime_error(std::string("missing ") + key);
    return *v;
  };
  const auto integer = [&](const char* key) {
    const auto v = t[key].value<int64_t>();
    if (!v) throw std::runtime_error(std::string("missing ") + key);
    return static_cast<int>(*v);
  };
  PlateParameters p;
  p.radius = number("radius");
  p.width = number("width");
  p.mass_per_area = number("mass_per_area");
  p.tension_x = number("tension_x");
  p.tension_y = number("tension_y");
  p.bending_x = number("bending_x");
  p.bending_y = number("bending_y");
  p.bending_xy = number("bending_xy");
  p.foundation_stiffness = number("foundation_stiffness");
  p.loss_factor = number("loss_factor");
  p.circumferential_modes = integer("circumferential_modes");
  p.lateral_modes = integer("lateral_modes");
  const KroppPlate plate(p);

  // The project's own reader accepts the file (unknown keys rejected) and reads the same plate.
  const PlateTyre read = read_plate_tyre(CaseFile::load_model(path).top());
  EXPECT_EQ(read.plate.foundation_stiffness, p.foundation_stiffness);
  EXPECT_EQ(read.plate.lateral_modes, p.lateral_modes);
  // The tread: Winkler springs of a thin layer, k = E/t with E = 2–5 MPa and t ≈ 6–10 mm.
  EXPECT_EQ(t["tread"]["type"].value<std::string>(), "winkler");
  EXPECT_EQ(read.tread.type, TreadSettings::Type::winkler);
  EXPECT_GT(read.tread.stiffness_per_area, 2e6 / 0.010);
  EXPECT_LT(read.tread.stiffness_per_area, 5e6 / 0.006);
  EXPECT_LE(read.tread_width, read.plate.width);

  // 205/55 R16: R = 0.2032 + 0.55·0.205 ≈ 0.316 m.
  EXPECT_NEAR(p.radius, 0.4064 / 2 + 0.55 * 0.205, 0.005);
  // The first radial resonance of the belt on its foundation, 80–100 Hz.
  const double f0 = std::sqrt(p.foundation_stiffness / p.mass_per_area) / (2 * pi);
  EXPECT_GE(f0, 80.0);
  EXPECT_LE(f0, 100.0);
  RecordProperty("foundation_resonance_Hz", std::to_string(f0));
  RecordProperty("lowest_mode_f01_Hz", std::to_string(plate.natural_frequency(0, 1) / (2 * pi)));
  RecordProperty("wave_speed_x_m_per_s", std::to_string(std::sqrt(p.tension_x / p.mass_per_area)));

  // Static stiffness at the belt centre line: a point force, and 1 N spread uniformly over a
  // 0.1 m × 0.15 m patch on the contact grid (512 around, 20 across the 0.15 m).
  const double b = p.width;
  const double point = 1.0 / plate.static_compliance(0.0, b / 2, b / 2);
  const double hx = plate.circumference() / 512, hy = 0.15 / 20;
  const int nx = static_cast<int>(std::lround(0.1 / hx)), ny = 20;
  std::vector<double> ys(static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j) ys[static_cast<std::size_t>(j)] = b / 2 + (j - (ny - 1) / 2.0) * hy;
  // C depends on (i − i', j, j'): tabulate, then assemble.
  std::vector<double> table(static_cast<std::size_t>(nx * ny * ny));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < ny; ++k)
        table[static_cast<std::size_t>((i * ny + j) * ny + k)] =
            plate.static_compliance(i * hx, ys[static_cast<std::size_t>(j)], ys[static_cast<std::size_t>(k)]);
  const int P = nx * ny;
  Eigen::MatrixXd C(P, P);
  for (int a = 0; a < P; ++a)
    for (int c = 0; c < P; ++c)
      C(a, c) = table[static_cast<std::size_t>((std::abs(a / ny - c / ny) * ny + a % ny) * ny + c % ny)];
  // Uniform load F/P on every point: mean deflection F·ΣC/P².
  const double uniform = static_cast<double>(P) * P / C.sum();
  // A rigid flat indentation (equal deflection): 1ᵀC⁻¹1.
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(P);
  const double rigid = one.dot(C.llt().solve(one));
  RecordProperty("point_stiffness_N_per_m", std::to_string(point));
  RecordProperty("patch_uniform_stiffness_N_per_m", std::to_string(uniform));
  RecordProperty("patch_rigid_stiffness_N_per_m", std::to_string(rigid));
  std::printf("f0 = %.1f Hz, f01 = %.1f Hz; point %.3g N/m, patch (uniform load) %.3g N/m, patch (rigid) %.3g N/m\n",
              f0, plate.natural_frequency(0, 1) / (2 * pi), point, uniform, rigid);
  // The order of a car tyre's vertical stiffness, 200–250 kN/m (the model file explains why the
  // plate lands somewhat above it).
  EXPECT_GT(uniform, 1.5e5);
  EXPECT_LT(uniform, 3.5e5);
}

}  // namespace
}  // namespace rollnoise

namespace rollnoise {
namespace {

// green_along shares the per-mode time factors between points: it must equal green() point by
// point (bit for bit: the same sums in the same order), and reject a size mismatch.
TEST(KroppPlate, GreenAlongEqualsGreenAtEachPoint) {
  const KroppPlate plate(tyre_like(32, 5));
  const double y = 0.5 * plate.parameters().width;
  const std::vector<double> dx{-0.4, -0.05, 0.0, 0.013, 0.2, 0.9};
  for (const double t : {0.0, 1e-4, 2.5e-3}) {
    std::vector<double> out(dx.size());
    plate.green_along(dx, y, 0.3 * y, t, out);
    for (std::size_t i = 0; i < dx.size(); ++i) EXPECT_EQ(out[i], plate.green(dx[i], y, 0.3 * y, t)) << dx[i] << " " << t;
  }
  std::vector<double> short_out(2);
  EXPECT_THROW(plate.green_along(dx, y, y, 1e-3, short_out), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
