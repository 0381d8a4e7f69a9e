// The two-layer stack in its half-space limits (a thick soft layer), against solutions that
// share none of its code:
//   - static: Boussinesq/Love — the surface displacement of a uniform pressure on a rectangle
//     (src/greens/tread_compliance: love_rectangle_displacement), a thick soft tread on a rigid
//     belt;
//   - dynamic: Lamb's problem — a surface point load's Rayleigh wave arrives at distance r at
//     r/c_R, c_R from the Rayleigh equation solved here.
// Both go from the stack's Ĝ(k, ω) to space by the Hankel transform (the layers are isotropic, so
// Ĝ depends on |k| only): g(r) = (1/2π)∫ Ĝ(k) J0(kr) k dk, with the static half-space's
// 2(1 − ν²)/(E k) subtracted and added back in closed form, which leaves a quickly convergent
// integral.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "greens/causal_modulus.hpp"
#include "greens/tread_compliance.hpp"
#include "greens/two_layer_stack.hpp"
#include "two_layer_test_support.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using std::numbers::pi;

double j0(double x) { return std::cyl_bessel_j(0.0, x); }

// A stack whose tread (thickness H) lies on a belt of `belt` and thickness `belt_h`.
TwoLayerStack stack_of(const OrthotropicConstants& tread, double tread_rho, double h, double tread_eta,
                       const OrthotropicConstants& belt, double belt_rho, double belt_h, double belt_eta,
                       double foundation) {
  return TwoLayerStack(ElasticLayer{orthotropic_stiffness(belt), belt_rho, belt_h, belt_eta},
                       ElasticLayer{orthotropic_stiffness(tread), tread_rho, h, tread_eta}, 0.0, 0.0, foundation, 0.0);
}

// ---------------------------------------------------------------------------------------------
// 1. Static: a thick soft tread on a rigid belt is an elastic half-space near the load.

TEST(TwoLayerHalfSpace, StaticPatchLoadIsLovesRectangle) {
  const double e = 4e6, nu = 0.48;
  const double h = 10.0;  // tread thickness, m: 250 times the farthest receiver distance
  const TwoLayerStack stack = stack_of(OrthotropicConstants::isotropic(e, nu), 1150.0, h, 0.0,
                                       OrthotropicConstants::isotropic(1e13, 0.3), 7800.0, 0.01, 0.0, 1e14);
  // g = g_half-space + Δg, Δg(r) = (1/2π)∫ ΔĜ(k) J0(kr) k dk, ΔĜ = Ĝ_zz(k, 0, 0) − 2(1 − ν²)/(E k).
  const double a_hs = 2 * (1 - nu * nu) / e;
  const auto delta = [&](double k) { return stack.surface_compliance(k, 0.0, 0.0)(2, 2).real() - a_hs / k; };
  // ΔĜ decays like e^{−2kH}: by kH = 40 it is at round-off; beyond, the stack must stay on the
  // half-space to round-off too (large k·h, up to 1e5).
  for (const double kh : {40.0, 1e2, 1e3, 1e4, 1e5}) {
    EXPECT_LT(std::abs(delta(kh / h)) / (a_hs * h / kh), 1e-12) << "kH " << kh;
  }
  const test::Quadrature q = test::composite_rule(0.0, 40.0 / h, 80, test::gauss_legendre(8));
  std::vector<double> dg(q.nodes.size());
  for (std::size_t i = 0; i < q.nodes.size(); ++i) dg[i] = delta(q.nodes[i]) * q.nodes[i] * q.weights[i] / (2 * pi);
  const auto delta_g = [&](double r) {
    double sum = 0.0;
    for (std::size_t i = 0; i < q.nodes.size(); ++i) sum += dg[i] * j0(q.nodes[i] * r);
    return sum;
  };
  // Uniform pressure on |x| ≤ a, |y| ≤ c, 1 N in total.
  const double a = 0.010, c = 0.005, p = 1.0 / (4 * a * c);
  const test::GaussRule g8 = test::gauss_legendre(8);
  double worst = 0.0;
  for (const auto& [x, y] : {std::pair{0.02, 0.0}, {0.0, 0.012}, {0.015, 0.01}, {0.03, 0.02}, {0.04, 0.0}, {0.0, 0.04}}) {
    double patch_delta = 0.0;  // ∫∫ Δg over the patch, Gauss 8 × 8 (Δg varies on the scale H)
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t j = 0; j < 8; ++j)
        patch_delta += g8.weights[i] * g8.weights[j] * a * c *
                       delta_g(std::hypot(x - a * g8.nodes[i], y - c * g8.nodes[j]));
    const double love = p * love_rectangle_displacement(x, y, a, c, e, nu);
    const double model = love + p * patch_delta;
    const double error = std::abs(model / love - 1);
    std::printf("static patch load: (%.3f, %.3f) m: model %.6e m, Love %.6e m, difference %.3f %%\n", x, y, model, love,
                100 * error);
    worst = std::max(worst, error);
    EXPECT_LT(error, 0.02) << x << ", " << y;
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
}

// ---------------------------------------------------------------------------------------------
// 2. Lamb's problem: the Rayleigh wave of a surface point load on a thick layer.

// ξ = c_R/c_S from (2 − ξ²)² = 4√(1 − κ²ξ²)√(1 − ξ²), κ = c_S/c_P, by bisection on (0, 1).
double rayleigh_ratio(double nu) {
  const double kappa2 = (1 - 2 * nu) / (2 * (1 - nu));
  const auto f = [&](double xi) {
    const double x2 = xi * xi;
    return (2 - x2) * (2 - x2) - 4 * std::sqrt(1 - kappa2 * x2) * std::sqrt(1 - x2);
  };
  double lo = 0.5, hi = 0.999999;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0) == (f(lo) > 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(TwoLayerHalfSpace, LambsProblemRayleighArrival) {
  // Rubber-like but with ν = 0.25 (c_P = √3·c_S), E at 1 kHz; light causal loss. The belt is
  // the same material, so the two layers are one 0.41 m layer: its bottom reflections reach
  // the receivers after the Rayleigh pulse has passed.
  const double e = 4e6, nu = 0.25, rho = 1150.0, eta = 0.02;
  const OrthotropicConstants rubber = OrthotropicConstants::isotropic(e, nu);
  const TwoLayerStack stack = stack_of(rubber, rho, 0.40, eta, rubber, rho, 0.01, eta, 1e9);
  const CausalModulus modulus(eta);
  const double cs = std::sqrt(e / (2 * (1 + nu)) / rho);  // at 1 kHz, where Re ψ = 1
  const double xi = rayleigh_ratio(nu);
  const double cr = xi * cs;
  // The envelope travels at the group velocity: with a causal loss the moduli, and so c_R ∝ √μ,
  // rise slowly with frequency. From the modulus alone: c(ω) = ω/Re k, k = ω√(ρ/μ*(ω))/ξ.
  const double wc = 2 * pi * 1000.0;
  const auto phase_speed = [&](double w) {
    const cd k = w * std::sqrt(rho / (e / (2 * (1 + nu)) * modulus.factor(w))) / xi;
    return w / k.real();
  };
  const double dw = 1e-3 * wc;
  const double dk = wc / phase_speed(wc) - (wc - dw) / phase_speed(wc - dw);
  const double dk2 = (wc + dw) / phase_speed(wc + dw) - wc / phase_speed(wc);
  const double group = 2 * dw / (dk + dk2);

  // Source: f(t) = e^{−t²Δω²/2} cos(ω_c t), one-sided spectrum ∝ e^{−(ω−ω_c)²/(2Δω²)}: the
  // analytic displacement u_a(t) = (1/π)∫₀^∞ F(ω) g(r, ω) e^{iωt} dω, whose modulus is the
  // envelope.
  const double spread = 0.2 * wc;
  const test::Quadrature wq = test::composite_rule(wc - 4.5 * spread, wc + 4.5 * spread, 16, test::gauss_legendre(6));
  const std::vector<double> distances = {0.2, 0.3};
  const double a_hs = 2 * (1 - nu * nu) / e;
  std::vector<std::vector<cd>> g(distances.size(), std::vector<cd>(wq.nodes.size()));
  const test::GaussRule g8 = test::gauss_legendre(8);
  for (std::size_t iw = 0; iw < wq.nodes.size(); ++iw) {
    const double w = wq.nodes[iw];
    const double ks = w / cs;
    // k up to 1.3 k_S finely (the Rayleigh pole and the layer's guided modes, widths ~ηk/2),
    // then coarsely to 5 k_S; beyond, Ĝ − A/k is O((k_S/k)²) and J0 oscillates.
    test::Quadrature kq = test::composite_rule(0.0, 1.3 * ks, static_cast<int>(std::ceil(1.3 * ks / 2.5)), g8);
    const test::Quadrature tail = test::composite_rule(1.3 * ks, 5 * ks, static_cast<int>(std::ceil(3.7 * ks / 20)), g8);
    kq.nodes.insert(kq.nodes.end(), tail.nodes.begin(), tail.nodes.end());
    kq.weights.insert(kq.weights.end(), tail.weights.begin(), tail.weights.end());
    const cd a = a_hs / modulus.factor(w);  // the half-space's static 2(1 − ν²)/(E*(ω) k)
    std::vector<cd> integrand(kq.nodes.size());
    for (std::size_t ik = 0; ik < kq.nodes.size(); ++ik) {
      const double k = kq.nodes[ik];
      integrand[ik] = (stack.surface_compliance(k, 0.0, w)(2, 2) - a / k) * k * kq.weights[ik] / (2 * pi);
    }
    for (std::size_t ir = 0; ir < distances.size(); ++ir) {
      const double r = distances[ir];
      cd sum = a / (2 * pi * r);
      for (std::size_t ik = 0; ik < kq.nodes.size(); ++ik) sum += integrand[ik] * j0(kq.nodes[ik] * r);
      g[ir][iw] = sum;
    }
  }
  std::vector<double> arrival(distances.size());
  for (std::size_t ir = 0; ir < distances.size(); ++ir) {
    const double r = distances[ir], expected = r / cr;
    const auto envelope = [&](double t) {
      cd sum = 0.0;
      for (std::size_t iw = 0; iw < wq.nodes.size(); ++iw) {
        const double w = wq.nodes[iw];
        const double f = std::exp(-0.5 * (w - wc) * (w - wc) / (spread * spread));
        sum += wq.weights[iw] * f * g[ir][iw] * std::polar(1.0, w * t);
      }
      return std::abs(sum) / pi;
    };
    // The envelope's maximum over 0.7–1.3 r/c_R, refined by a parabola through the best sample.
    const double step = 0.02 / spread;
    double best_t = 0.0, best = -1.0;
    for (double t = 0.7 * expected; t <= 1.3 * expected; t += step) {
      const double v = envelope(t);
      if (v > best) {
        best = v;
        best_t = t;
      }
    }
    const double e0 = envelope(best_t - step), e1 = best, e2 = envelope(best_t + step);
    const double t_peak = best_t + 0.5 * step * (e0 - e2) / (e0 - 2 * e1 + e2);
    arrival[ir] = t_peak;
    const double error = t_peak / expected - 1;
    std::printf("Lamb: r = %.2f m: envelope peak at %.4f ms; r/c_R = %.4f ms (%+.2f %%), r/c_group = %.4f ms (%+.2f %%)\n",
                r, 1e3 * t_peak, 1e3 * expected, 100 * error, 1e3 * r / group, 100 * (t_peak * group / r - 1));
    EXPECT_LT(std::abs(error), 0.02) << r;
    EXPECT_LT(std::abs(t_peak * group / r - 1), 0.005) << r;
  }
  // The speed between the two receivers (free of any offset near the source).
  const double speed = (distances[1] - distances[0]) / (arrival[1] - arrival[0]);
  std::printf("Lamb: speed between receivers %.3f m/s; c_R = %.3f m/s (Rayleigh equation, xi = %.5f), group %.3f m/s\n",
              speed, cr, xi, group);
  EXPECT_NEAR(speed / cr, 1.0, 0.02);
}

}  // namespace
}  // namespace rollnoise
