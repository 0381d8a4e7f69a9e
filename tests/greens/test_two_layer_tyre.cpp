// The two-layer tyre (src/greens/two_layer_tyre.hpp) as a whole:
//   - the plate limit: a thin stiff belt with a thin soft tread is Kropp's Kirchhoff plate
//     (src/greens/kropp_plate: KroppPlate) with the laminate's bending stiffness, the tension,
//     the foundation and the mass: per-mode natural frequencies and the point receptance;
//   - the modal sum against the continuous spatial transform of the same stack (a wide strip):
//     the modes' normalisation and the cell averages;
//   - reciprocity and rotation invariance, all components, both side conditions;
//   - passivity of the point mobility;
//   - causality of the time-domain Green's functions (and a constant hysteretic loss, which is
//     not causal, failing the same check);
//   - the static case and the side conditions;
//   - the passenger-car model file's figures and the cost of the reference grid;
//   - bad keys in a model file.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/case_file.hpp"
#include "core/error.hpp"
#include "greens/kropp_plate.hpp"
#include "greens/layer_stiffness.hpp"
#include "greens/model_factory.hpp"
#include "greens/tread_compliance.hpp"
#include "greens/two_layer_factory.hpp"
#include "greens/two_layer_greens_functions.hpp"
#include "greens/two_layer_tyre.hpp"
#include "road/road_test_support.hpp"
#include "two_layer_test_support.hpp"

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using std::numbers::pi;
using Dir = SurfaceDirection;

// A lossless copy of the parameters.
TwoLayerParameters lossless(TwoLayerParameters p) {
  p.belt_loss_factor = p.tread_loss_factor = p.foundation_loss_factor = 0.0;
  return p;
}

// The lowest frequency in [f0, f1] (Hz) at which the real function `stiffness` (a lossless
// dynamic stiffness, 1/receptance) crosses zero, refined by bisection: a resonance. Crossings
// where |stiffness| does not fall (a pole of the stiffness, an anti-resonance) are skipped.
double resonance(const std::function<double(double)>& stiffness, double f0, double f1, int steps = 400) {
  double a = f0, sa = stiffness(2 * pi * f0);
  for (int i = 1; i <= steps; ++i) {
    const double b = f0 + (f1 - f0) * i / steps, sb = stiffness(2 * pi * b);
    if ((sa > 0) != (sb > 0)) {
      double lo = a, hi = b, slo = sa;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi), sm = stiffness(2 * pi * mid);
        if ((sm > 0) == (slo > 0)) {
          lo = mid;
          slo = sm;
        } else {
          hi = mid;
        }
      }
      const double f = 0.5 * (lo + hi);
      if (std::abs(stiffness(2 * pi * f)) < 1e-6 * std::max(std::abs(sa), std::abs(sb))) return f;
    }
    a = b;
    sa = sb;
  }
  return -1.0;
}

// ---------------------------------------------------------------------------------------------
// 1. The plate limit.

// Plane-stress stiffness [Q11 Q12 0; Q12 Q22 0; 0 0 Q66] of orthotropic constants.
Eigen::Matrix3d plane_stress(const OrthotropicConstants& c) {
  const double nu_yx = c.poisson_xy * c.youngs_y / c.youngs_x;
  const double d = 1.0 - c.poisson_xy * nu_yx;
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
  q(0, 0) = c.youngs_x / d;
  q(1, 1) = c.youngs_y / d;
  q(0, 1) = q(1, 0) = c.poisson_xy * c.youngs_y / d;
  q(2, 2) = c.shear_xy;
  return q;
}

TEST(TwoLayerTyre, PlateLimitIsKroppsPlate) {
  // A thin, stiff orthotropic belt (2 mm; transverse shear and E_z high so that it bends as a
  // Kirchhoff plate over the modes kept) under a thin, soft tread (1 mm), lossless.
  TwoLayerParameters p;
  p.radius = 0.316;
  p.width = 0.18;
  p.belt = {3e9, 1.3e9, 3e9, 8e8, 5e8, 5e8, 0.3, 0.3, 0.3};
  p.belt_thickness = 0.002;
  p.belt_density = 2000.0;
  p.tread_thickness = 0.001;
  p.tread_density = 1150.0;
  p.tread_youngs_modulus = 3e7;
  p.tread_poisson_ratio = 0.45;
  p.tension_x = 6e4;
  p.tension_y = 9e3;
  p.foundation_stiffness = 1.5e6;
  p.circumferential_modes = 20;  // k_x up to 63 rad/m
  p.lateral_modes = 3;           // k_y up to 52 rad/m
  const TwoLayerTyre tyre(p);

  // The equivalent Kirchhoff plate: the laminate's bending stiffness about its neutral plane,
  // D* = D − B A⁻¹ B (in-plane forces free), the total mass, the same tension and foundation.
  const Eigen::Matrix3d qb = plane_stress(p.belt);
  const Eigen::Matrix3d qt = plane_stress(OrthotropicConstants::isotropic(p.tread_youngs_modulus, p.tread_poisson_ratio));
  const double z0 = 0.0, z1 = p.belt_thickness, z2 = z1 + p.tread_thickness;
  const Eigen::Matrix3d a = qb * (z1 - z0) + qt * (z2 - z1);
  const Eigen::Matrix3d b = qb * (z1 * z1 - z0 * z0) / 2 + qt * (z2 * z2 - z1 * z1) / 2;
  const Eigen::Matrix3d d = qb * (z1 * z1 * z1 - z0 * z0 * z0) / 3 + qt * (z2 * z2 * z2 - z1 * z1 * z1) / 3;
  const Eigen::Matrix3d dstar = d - b * a.inverse() * b;
  PlateParameters plate;
  plate.radius = p.radius;
  plate.width = p.width;
  plate.mass_per_area = p.belt_density * p.belt_thickness + p.tread_density * p.tread_thickness;
  plate.tension_x = p.tension_x;
  plate.tension_y = p.tension_y;
  plate.bending_x = dstar(0, 0);
  plate.bending_y = dstar(1, 1);
  plate.bending_xy = dstar(0, 1) + 2 * dstar(2, 2);
  plate.foundation_stiffness = p.foundation_stiffness;
  plate.loss_factor = 0.0;
  plate.circumferential_modes = p.circumferential_modes;
  plate.lateral_modes = p.lateral_modes;
  const KroppPlate kirchhoff(plate);
  // The first thickness resonance: the tread's shear layer on the belt, c_S/(4 h_t).
  const double cs = std::sqrt(p.tread_youngs_modulus / (2 * (1 + p.tread_poisson_ratio)) / p.tread_density);
  const double thickness_resonance = cs / (4 * p.tread_thickness);
  std::printf("plate limit: Bx %.4f By %.4f Bxy %.4f N·m, m'' %.3f kg/m², first thickness resonance %.0f Hz\n",
              plate.bending_x, plate.bending_y, plate.bending_xy, plate.mass_per_area, thickness_resonance);

  // Every mode's natural frequency: the zero of 1/H_zz(m, n, ω) near the plate's ω_mn.
  double worst_frequency = 0.0, highest = 0.0;
  for (int n = 1; n <= p.lateral_modes; ++n) {
    for (int m = 0; m <= p.circumferential_modes; ++m) {
      const double fp = kirchhoff.natural_frequency(m, n) / (2 * pi);
      const double f = resonance([&](double w) { return (1.0 / tyre.modal_compliance(m, n, w)(2, 2)).real(); },
                                 0.95 * fp, 1.05 * fp, 20);
      ASSERT_GT(f, 0.0) << "no resonance of mode (" << m << ", " << n << ") near the plate's " << fp << " Hz";
      worst_frequency = std::max(worst_frequency, std::abs(f / fp - 1));
      highest = std::max(highest, fp);
    }
  }
  ASSERT_LT(highest, 0.2 * thickness_resonance);
  // The point receptance at the belt's centre line, statically and along ω − iσ (σ = 5 % of ω
  // and 5 Hz: a smoothing of the peaks both sides share, the plate's from its natural
  // frequencies and modal mass).
  const SurfaceLocation centre{0.0, p.width / 2};
  const auto plate_receptance = [&](cd w) {
    cd sum = 0.0;
    for (int n = 1; n <= p.lateral_modes; ++n) {
      const double s = std::sin(kirchhoff.wavenumber_y(n) * centre.y);
      for (int m = 0; m <= p.circumferential_modes; ++m) {
        const double wn = kirchhoff.natural_frequency(m, n);
        sum += (m == 0 ? 1.0 : 2.0) * s * s / (kirchhoff.modal_mass() * (wn * wn - w * w));
      }
    }
    return sum;
  };
  double worst_receptance = 0.0;
  const double static_error = std::abs(tyre.response(0.0).receptance(centre, centre) / plate_receptance(0.0) - 1.0);
  for (double f = 20.0; f <= 1.2 * highest; f *= 1.08) {
    const cd w(2 * pi * f, -(0.05 * 2 * pi * f + 2 * pi * 5));
    worst_receptance =
        std::max(worst_receptance, std::abs(tyre.response(w).receptance(centre, centre) / plate_receptance(w) - 1.0));
  }
  std::printf("plate limit: %d modes up to %.0f Hz: natural frequencies within %.3f %%; point receptance: static %.3f %%, "
              "up to %.0f Hz (smoothed) within %.3f %%\n",
              (p.circumferential_modes + 1) * p.lateral_modes, highest, 100 * worst_frequency, 100 * static_error,
              1.2 * highest, 100 * worst_receptance);
  EXPECT_LT(worst_frequency, 0.005);
  EXPECT_LT(static_error, 0.05);
  EXPECT_LT(worst_receptance, 0.05);
}

// ---------------------------------------------------------------------------------------------
// 2. The modal sum against the continuous transform.

TEST(TwoLayerTyre, ModalSumIsTheSpatialTransformOnAWideStrip) {
  // A 5 mm tread on a rigid belt: its static response dies out within a few centimetres, so on a
  // strip 0.3 m around and 0.1 m wide the periodic images and the edges are far away and the
  // modal sum is the continuous inverse Fourier transform, (1/2π)∫Ĝ(k) J0(kr) k dk by Hankel
  // (Love's rectangle for the half-space part, as in test_two_layer_halfspace.cpp). Source and
  // receiver are 10 mm × 10 mm cells: the receiver's mean over its cell.
  const double e = 4e6, nu = 0.48, h = 0.005;
  TwoLayerParameters p;
  p.radius = 0.3 / (2 * pi);
  p.width = 0.1;
  p.belt = OrthotropicConstants::isotropic(1e13, 0.3);
  p.belt_thickness = 0.005;
  p.belt_density = 7800.0;
  p.tread_thickness = h;
  p.tread_density = 1150.0;
  p.tread_youngs_modulus = e;
  p.tread_poisson_ratio = nu;
  p.foundation_stiffness = 1e14;
  p.circumferential_modes = 240;  // k_m·(cell/2) up to 25
  p.lateral_modes = 160;
  const TwoLayerTyre tyre(p);
  const double cell = 0.01, half = cell / 2;
  const SurfaceLocation source{0.0, p.width / 2, cell, cell};
  const TwoLayerResponse static_response = tyre.response(0.0);

  // Reference: w = Love + Δg, Δg(r) = (1/2π)∫(Ĝ − 2(1 − ν²)/(E k)) J0(kr) k dk.
  const double a_hs = 2 * (1 - nu * nu) / e;
  const test::Quadrature q = test::composite_rule(0.0, 40.0 / h, 80, test::gauss_legendre(8));
  std::vector<double> dg(q.nodes.size());
  for (std::size_t i = 0; i < q.nodes.size(); ++i) {
    const double k = q.nodes[i];
    dg[i] = (tyre.wavenumber_compliance(k, 0.0, 0.0)(2, 2).real() - a_hs / k) * k * q.weights[i] / (2 * pi);
  }
  // Δg varies on the scale of h: tabulated every 0.05 mm to 6 cm and interpolated linearly
  // (relative error ~ (0.05/5)²/8 ≈ 1e-5), which spares millions of Bessel functions.
  const double dr = 5e-5;
  std::vector<double> table(1201);
  for (std::size_t t = 0; t < table.size(); ++t) {
    double sum = 0.0;
    for (std::size_t i = 0; i < q.nodes.size(); ++i) sum += dg[i] * std::cyl_bessel_j(0.0, q.nodes[i] * dr * static_cast<double>(t));
    table[t] = sum;
  }
  const auto delta_g = [&](double r) {
    const double u = r / dr;
    const std::size_t t = std::min(static_cast<std::size_t>(u), table.size() - 2);
    return table[t] + (u - static_cast<double>(t)) * (table[t + 1] - table[t]);
  };
  const test::GaussRule g = test::gauss_legendre(12);
  const auto point_response = [&](double x, double y) {  // per unit force on the source cell
    double patch = 0.0;
    for (std::size_t i = 0; i < g.nodes.size(); ++i)
      for (std::size_t j = 0; j < g.nodes.size(); ++j)
        patch += g.weights[i] * g.weights[j] * delta_g(std::hypot(x - half * g.nodes[i], y - half * g.nodes[j])) / 4;
    return love_rectangle_displacement(x, y, half, half, e, nu) / (cell * cell) + patch;
  };
  double worst = 0.0;
  for (const double dx : {0.0, 0.01, 0.02, 0.035}) {
    const SurfaceLocation receiver{dx, p.width / 2 + 0.005, cell, cell};
    // The receiver cell's mean of the reference, Gauss 12 × 12 in two halves along each axis
    // (the response's slope has a logarithmic kink at the source cell's edges).
    double expected = 0.0;
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5})
        for (std::size_t i = 0; i < g.nodes.size(); ++i)
          for (std::size_t j = 0; j < g.nodes.size(); ++j)
            expected += g.weights[i] * g.weights[j] / 16 *
                        point_response(receiver.x + half * (sx + 0.5 * g.nodes[i]) - source.x,
                                       receiver.y - source.y + half * (sy + 0.5 * g.nodes[j]));
    const double got = static_response.receptance(receiver, source).real();
    const double error = std::abs(got / expected - 1);
    std::printf("wide strip: receiver cell at dx = %.3f m: modal %.6e m/N, transform %.6e m/N, difference %.4f %%\n", dx,
                got, expected, 100 * error);
    worst = std::max(worst, error);
  }
  EXPECT_LT(worst, 0.005);
}

// ---------------------------------------------------------------------------------------------
// 3. Symmetries.

TEST(TwoLayerTyre, ReciprocityAndRotationInvariance) {
  for (const SideCondition side : {SideCondition::simply_supported, SideCondition::sliding}) {
    TwoLayerParameters p = test::tyre_like_two_layer(6, 3);
    p.side_condition = side;
    const TwoLayerTyre tyre(p);
    const double length = tyre.circumference();
    const SurfaceLocation r{0.1, 0.05, 0.004, 0.007}, s{0.37, 0.12, 0.0, 0.0};
    double worst_reciprocity = 0.0, worst_rotation = 0.0;
    for (const cd w : {cd(0.0), cd(2 * pi * 250), cd(2 * pi * 1200, -50.0)}) {
      const TwoLayerResponse response = tyre.response(w);
      double scale = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          if (w == 0.0 && side == SideCondition::sliding && (i != 2 || j != 2)) continue;  // unbounded: below
          scale = std::max(scale, std::abs(response.receptance(r, s, Dir(i), Dir(j))));
        }
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          if (w == 0.0 && side == SideCondition::sliding && (i != 2 || j != 2)) continue;
          const cd rs = response.receptance(r, s, Dir(i), Dir(j));
          const cd sr = response.receptance(s, r, Dir(j), Dir(i));
          worst_reciprocity = std::max(worst_reciprocity, std::abs(rs - sr) / scale);
          for (const double shift : {0.73, length + 0.2, -3.0 * length + 1.1}) {
            const SurfaceLocation r2{r.x + shift, r.y, r.length, r.width}, s2{s.x + shift, s.y, s.length, s.width};
            worst_rotation = std::max(worst_rotation, std::abs(response.receptance(r2, s2, Dir(i), Dir(j)) - rs) / scale);
          }
        }
      }
    }
    std::printf("%s: reciprocity %.2e, rotation invariance %.2e (relative to the largest receptance)\n",
                side == SideCondition::sliding ? "sliding" : "simply supported", worst_reciprocity, worst_rotation);
    EXPECT_LT(worst_reciprocity, 1e-12);
    EXPECT_LT(worst_rotation, 1e-12);
  }
}

// ---------------------------------------------------------------------------------------------
// 4. Passivity.

TEST(TwoLayerTyre, PointMobilityIsPassive) {
  for (const SideCondition side : {SideCondition::simply_supported, SideCondition::sliding}) {
    TwoLayerParameters p = test::tyre_like_two_layer(32, 6);
    p.side_condition = side;
    const TwoLayerTyre tyre(p);
    const SurfaceLocation point{0.0, 0.07}, cell{0.0, 0.09, 0.0039, 0.0072};
    double lowest = 1e300;
    for (double f = 1.0; f <= 2e4; f *= 1.06) {
      const TwoLayerResponse response = tyre.response(2 * pi * f);
      for (const SurfaceLocation& at : {point, cell}) {
        const cd y = response.mobility(at, at);
        lowest = std::min(lowest, y.real() / std::abs(y));
        EXPECT_GE(y.real(), 0.0) << f << " Hz";
      }
      // Tangential too: the power of a tangential force is ≥ 0.
      EXPECT_GE(response.mobility(point, point, Dir::x, Dir::x).real(), 0.0) << f << " Hz";
      EXPECT_GE(response.mobility(point, point, Dir::y, Dir::y).real(), 0.0) << f << " Hz";
    }
    std::printf("passivity (%s): smallest Re Y/|Y| over 1 Hz–20 kHz %.3e\n",
                side == SideCondition::sliding ? "sliding" : "simply supported", lowest);
  }
}

// ---------------------------------------------------------------------------------------------
// 5. Causality of the Green's functions.

// The tyre's stack condensed here from layer_stiffness with given complex moduli factors and
// foundation stiffness: the test's own condensation, so that a modulus other than the causal
// one can be tried.
cd normal_compliance(const TwoLayerParameters& p, cd psi_belt, cd psi_tread, cd foundation, double kx, double ky,
                     cd w) {
  const Matrix6cd kb = layer_stiffness(orthotropic_stiffness(p.belt), psi_belt, p.belt_density, p.belt_thickness,
                                       kx, ky, w)
                           .matrix();
  const Matrix6cd kt = layer_stiffness(
                           orthotropic_stiffness(OrthotropicConstants::isotropic(p.tread_youngs_modulus,
                                                                                 p.tread_poisson_ratio)),
                           psi_tread, p.tread_density, p.tread_thickness, kx, ky, w)
                           .matrix();
  // Global 9×9: interfaces 0 (belt bottom), 1, 2 (tread surface); load at 2.
  Eigen::Matrix<cd, 9, 9> k = Eigen::Matrix<cd, 9, 9>::Zero();
  k.block<6, 6>(0, 0) += kb;
  k.block<6, 6>(3, 3) += kt;
  k(2, 2) += foundation + p.tension_x * kx * kx + p.tension_y * ky * ky;
  Eigen::Matrix<cd, 9, 1> f = Eigen::Matrix<cd, 9, 1>::Zero();
  f(8) = 1.0;
  return k.fullPivLu().solve(f)(8);
}

// g(t_k), step means, by a direct inverse DFT of H(ω_j − iσ)·B(ω_j − iσ) with the library's
// sampling (two_layer_greens_functions.hpp), for the samples at t < 0 and the largest at t ≥ 0.
struct Precursor {
  double before = 0.0;  // max |g| at t < 0
  double peak = 0.0;    // max |g| at t ≥ 0
};

// The sum runs to `oversampling` times the Nyquist frequency: the samples of a function see all
// the aliases of its spectrum (e^{iω_J t_k} repeats with period K in J).
Precursor direct_inverse(const std::function<cd(cd)>& h, double dt, int samples, int oversampling) {
  const double period = dt * samples, sigma = std::log(1e4) / period;
  const int count = oversampling * samples / 2;
  std::vector<cd> spectrum(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const cd w(2 * pi * j / period, -sigma);
    const cd x = cd(0.0, 1.0) * w * dt;
    spectrum[static_cast<std::size_t>(j)] = h(w) * (1.0 - std::exp(-x)) / x / period * (j == 0 ? 1.0 : 2.0);
  }
  Precursor out;
  for (int k = -samples / 2; k < samples / 2; ++k) {
    cd sum = 0.0;
    for (int j = 0; j < count; ++j) sum += spectrum[static_cast<std::size_t>(j)] * std::polar(1.0, 2 * pi * j * k / samples);
    const double g = sum.real() * std::exp(sigma * k * dt);
    double& side = k < 0 ? out.before : out.peak;
    side = std::max(side, std::abs(g));
  }
  return out;
}

TEST(TwoLayerTyre, GreensFunctionsAreCausal) {
  const TwoLayerParameters p = test::tyre_like_two_layer(10, 2);
  const TwoLayerTyre tyre(p);
  const double dt = 4e-4;
  const int samples = 1024;  // 0.41 s
  const TwoLayerGreensFunctions greens(tyre, dt, samples);
  ASSERT_EQ(greens.time(samples / 2), 0.0);
  const auto split = [&](const std::vector<double>& g) {
    Precursor out;
    for (int k = 0; k < samples; ++k) {
      double& side = greens.time(k) < 0 ? out.before : out.peak;
      side = std::max(side, std::abs(g[static_cast<std::size_t>(k)]));
    }
    return out;
  };
  const auto precursor_of = [&](const std::vector<double>& g) {
    const Precursor s = split(g);
    return s.before / s.peak;
  };
  // Every mode, and the Green's function of a contact cell on itself and on a neighbour.
  double worst_mode = 0.0;
  for (int n = 1; n <= 2; ++n)
    for (int m = 0; m <= 10; ++m) worst_mode = std::max(worst_mode, precursor_of(greens.mode(m, n)));
  const SurfaceLocation cell{0.0, 0.09, 0.0039, 0.0072}, next{0.0039, 0.09, 0.0039, 0.0072};
  const double cell_precursor = precursor_of(greens.between(cell, cell)), next_precursor = precursor_of(greens.between(next, cell));

  // The same mode through the test's own condensation and inverse DFT: with the causal moduli
  // it reproduces the library; with the constant hysteretic moduli 1 + iη it starts before the
  // load.
  const CausalModulus belt(p.belt_loss_factor), tread(p.tread_loss_factor), foundation(p.foundation_loss_factor);
  const double kx = tyre.wavenumber_x(0), ky = tyre.wavenumber_y(1);
  const auto causal = [&](cd w) {
    return normal_compliance(p, belt.factor(w), tread.factor(w), p.foundation_stiffness * foundation.factor(w), kx, ky, w);
  };
  EXPECT_LT(std::abs(causal(cd(600.0, -3.0)) / tyre.wavenumber_compliance(kx, ky, cd(600.0, -3.0))(2, 2) - 1.0), 1e-12);
  const Precursor own = direct_inverse(causal, dt, samples, 8);
  const auto hysteretic = [&](cd w) {
    return normal_compliance(p, cd(1.0, p.belt_loss_factor), cd(1.0, p.tread_loss_factor),
                             p.foundation_stiffness * cd(1.0, p.foundation_loss_factor), kx, ky, w);
  };
  const Precursor nc = direct_inverse(hysteretic, dt, samples, 8);
  std::printf("causality: before t = 0 / peak: modes %.2e, cell on itself %.2e, on its neighbour %.2e; "
              "test's own transform %.2e; constant hysteretic loss %.2e\n",
              worst_mode, cell_precursor, next_precursor, own.before / own.peak, nc.before / nc.peak);
  EXPECT_LT(worst_mode, 1e-3);
  EXPECT_LT(cell_precursor, 1e-3);
  EXPECT_LT(next_precursor, 1e-3);
  EXPECT_LT(own.before / own.peak, 1e-3);
  // (The library also subtracts the asymptote and folds the aliases: close, not equal.)
  EXPECT_NEAR(own.peak, split(greens.mode(0, 1)).peak, 1e-3 * own.peak);
  EXPECT_GT(nc.before / nc.peak, 3e-3);  // the check has teeth
}

TEST(TwoLayerTyre, StepKernelConvergesAndSumsToTheStaticCompliance) {
  // A well-damped tyre (its lowest mode rings out within the record's half), few modes. Halving
  // Δt must not change the step means (the coarse step's mean is the mean of the two fine ones),
  // and the step kernel must sum to the static compliance: Σ G[k] = ∫₀^∞ g = α(0).
  TwoLayerParameters p = test::tyre_like_two_layer(3, 2);
  p.belt_loss_factor = 0.2;
  p.foundation_loss_factor = 0.3;
  const TwoLayerTyre tyre(p);
  const double dt = 4e-4;
  const int samples = 1024;  // 0.41 s
  const TwoLayerGreensFunctions coarse(tyre, dt, samples), fine(tyre, dt / 2, 2 * samples);
  const SurfaceLocation cell{0.0, 0.09, 0.0039, 0.0072};
  const std::vector<double> gc = coarse.between(cell, cell), gf = fine.between(cell, cell);
  double peak = 0.0, difference = 0.0, integral = 0.0;
  for (int k = 0; k < samples; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    const std::size_t j = static_cast<std::size_t>(2 * k);  // fine index of the same time t_k
    const double halves = j >= 1 ? 0.5 * (gf[j] + gf[j - 1]) : 0.5 * gf[j];
    peak = std::max(peak, std::abs(gc[i]));
    difference = std::max(difference, std::abs(gc[i] - halves));
    if (coarse.time(k) > 0.0) integral += dt * gc[i];
  }
  const double static_receptance = tyre.response(0.0).receptance(cell, cell).real();
  std::printf("step kernel: halving dt changes it by %.2e of its peak; sum %.6e m/N, static receptance %.6e m/N (%+.3f %%)\n",
              difference / peak, integral, static_receptance, 100 * (integral / static_receptance - 1));
  EXPECT_LT(difference / peak, 1e-3);
  EXPECT_NEAR(integral / static_receptance, 1.0, 2e-3);
}

// The modes are shared out to threads batch by batch: any thread count gives the same values,
// bit for bit (several batches of 64 modes, the last one partly filled).
TEST(TwoLayerTyre, GreensFunctionsDoNotDependOnTheThreadCount) {
  const TwoLayerTyre tyre(test::tyre_like_two_layer(40, 4));  // 41 × 4 = 164 modes: 3 batches
  const TwoLayerGreensFunctions one(tyre, 4e-4, 64, 4, 1), three(tyre, 4e-4, 64, 4, 3);
  for (int n = tyre.first_lateral_order(); n <= tyre.last_lateral_order(); ++n) {
    for (int m = 0; m <= 40; ++m) EXPECT_EQ(one.mode(m, n), three.mode(m, n)) << "m = " << m << ", n = " << n;
  }
}

// ---------------------------------------------------------------------------------------------
// 6. The static case and the side conditions.

TEST(TwoLayerTyre, StaticCaseAndSideConditions) {
  const TwoLayerParameters p = test::tyre_like_two_layer(24, 5);
  const TwoLayerTyre tyre(p);
  const SurfaceLocation cell{0.0, 0.09, 0.0039, 0.0072}, other{0.02, 0.06, 0.0039, 0.0072};
  // ω = 0 exactly is the limit ω → 0: with the causal loss the difference is first order in ω
  // (the relaxation of the moduli, ψ(ω) − ψ(0) ≈ iωτ₂·cψ₀ with τ₂ = 1/(2π·10 Hz)).
  const cd s0 = tyre.response(0.0).receptance(other, cell);
  const double d1 = std::abs(tyre.response(1e-3).receptance(other, cell) - s0) / std::abs(s0);
  const double d2 = std::abs(tyre.response(1e-5).receptance(other, cell) - s0) / std::abs(s0);
  std::printf("static: |alpha(1e-3) - alpha(0)| = %.3e, |alpha(1e-5) - alpha(0)| = %.3e (relative)\n", d1, d2);
  EXPECT_LT(d1, 1e-4);
  EXPECT_NEAR(d1 / d2, 100.0, 1.0);
  EXPECT_LT(std::abs(s0.imag()), 1e-12 * s0.real());  // real, up to the rounding of complex arithmetic
  EXPECT_GT(s0.real(), 0.0);

  // Simply supported edges do not move normally; sliding ones do, and the strip is softer.
  TwoLayerParameters ps = p;
  ps.side_condition = SideCondition::sliding;
  const TwoLayerTyre sliding(ps);
  const SurfaceLocation edge{0.05, 0.0}, centre{0.0, 0.09};
  const TwoLayerResponse ss0 = tyre.response(0.0), sl0 = sliding.response(0.0);
  EXPECT_EQ(ss0.receptance(edge, centre), 0.0);
  EXPECT_GT(sl0.receptance(edge, centre).real(), 0.0);
  EXPECT_GT(sl0.receptance(centre, centre).real(), ss0.receptance(centre, centre).real());
  // Simply supported: u_x = 0 at the edges, u_y not; sliding: the reverse.
  EXPECT_EQ(tyre.response(600.0).receptance(edge, centre, Dir::x, Dir::z), 0.0);
  EXPECT_NE(tyre.response(600.0).receptance(edge, centre, Dir::y, Dir::z), 0.0);
  EXPECT_EQ(sliding.response(600.0).receptance(edge, centre, Dir::y, Dir::z), 0.0);
  // The sliding strip's uniform in-plane translation is free: no static tangential compliance.
  EXPECT_THROW(sl0.receptance(centre, centre, Dir::x, Dir::x), std::domain_error);
  EXPECT_TRUE(std::isfinite(std::abs(sl0.receptance(centre, centre))));
  // Locations outside the width are rejected.
  EXPECT_THROW(ss0.receptance(SurfaceLocation{0.0, 0.19}, centre), std::invalid_argument);
  EXPECT_THROW(ss0.receptance(SurfaceLocation{0.0, 0.179, 0.0, 0.01}, centre), std::invalid_argument);
  EXPECT_THROW(tyre.response(cd(100.0, 1.0)), std::invalid_argument);  // Im ω > 0: not the window
}

// ---------------------------------------------------------------------------------------------
// 7. The passenger-car model file.

TEST(TwoLayerTyre, PassengerModelFile) {
  const std::string path = std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/passenger_205_55R16_two_layer.toml";
  const TwoLayerParameters p = read_two_layer_tyre(CaseFile::load_model(path).top());
  const TwoLayerTyre tyre(p);
  // The factory of surface-receptance models builds the same tyre; the point-model factory
  // names what it takes.
  const std::unique_ptr<SurfaceReceptanceModel> made = make_surface_receptance_model(CaseFile::load_model(path).top());
  EXPECT_EQ(made->name(), "two_layer");
  EXPECT_EQ(made->circumference(), tyre.circumference());
  EXPECT_THROW(make_greens_model(CaseFile::load_model(path).top()), InputError);
  // The same tyre as the plate file, 205/55 R16.
  EXPECT_NEAR(p.radius, 0.4064 / 2 + 0.55 * 0.205, 0.005);
  EXPECT_EQ(p.circumferential_modes, 256);
  EXPECT_EQ(p.lateral_modes, 25);
  EXPECT_EQ(p.side_condition, SideCondition::simply_supported);
  // A tread rubber of a few MPa; steel-cord plies: high E_x, lower E_y, small E_z.
  EXPECT_GE(p.tread_youngs_modulus, 2e6);
  EXPECT_LE(p.tread_youngs_modulus, 8e6);
  EXPECT_GE(p.belt.youngs_x, 1e9);
  EXPECT_LT(p.belt.youngs_y, p.belt.youngs_x);
  EXPECT_LT(p.belt.youngs_z, 0.1 * p.belt.youngs_y);

  // Resonances where the real part of the dynamic stiffness 1/H crosses zero, with the loss (the
  // moduli at each frequency, below their 1 kHz values at 91 Hz) and without (the 1 kHz moduli).
  const TwoLayerTyre elastic(lossless(p));
  const auto radial = [](const TwoLayerTyre& t) {
    // The first radial resonance: mode (0, 1), the lowest of the simply supported tyre.
    return resonance([&](double w) { return (1.0 / t.modal_compliance(0, 1, w)(2, 2)).real(); }, 20, 300);
  };
  const auto ring_of = [&](const TwoLayerTyre& t) {
    // The ring frequency: the in-plane (extensional) wave at k = 1/R, the pole of Ĝ_xx.
    return resonance([&](double w) { return (1.0 / t.wavenumber_compliance(1.0 / p.radius, 0.0, w)(0, 0)).real(); },
                     150, 1000);
  };
  const double f01 = radial(tyre), ring = ring_of(tyre);
  const double f01_elastic = radial(elastic), ring_elastic = ring_of(elastic);
  // Static vertical stiffness: 1 N spread uniformly over a 0.10 m × 0.15 m patch at the belt's
  // centre, the mean deflection over it.
  const SurfaceLocation patch{0.0, p.width / 2, 0.10, 0.15};
  const auto start = std::chrono::steady_clock::now();
  const TwoLayerResponse static_response = tyre.response(0.0);
  const double static_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double stiffness = 1.0 / static_response.receptance(patch, patch).real();
  const SurfaceLocation cell{0.0, p.width / 2, tyre.circumference() / 512, p.width / 25};
  const double cell_stiffness = 1.0 / static_response.receptance(cell, cell).real();
  // The reference grid at 1 kHz: the table, then one receptance.
  const auto t0 = std::chrono::steady_clock::now();
  const TwoLayerResponse at_1k = tyre.response(2 * pi * 1000);
  const auto t1 = std::chrono::steady_clock::now();
  const cd alpha = at_1k.receptance(cell, cell);
  const auto t2 = std::chrono::steady_clock::now();
  EXPECT_EQ(made->at(2 * pi * 1000)->receptance(cell, cell), alpha);
  const double table_seconds = std::chrono::duration<double>(t1 - t0).count();
  const double sum_seconds = std::chrono::duration<double>(t2 - t1).count();
  std::printf("passenger two_layer: first radial resonance %.1f Hz (%.1f Hz with the 1 kHz moduli, lossless), ring "
              "frequency %.1f Hz (%.1f Hz), static stiffness %.1f kN/m (0.10 m x 0.15 m patch), one contact cell %.1f kN/m\n",
              f01, f01_elastic, ring, ring_elastic, stiffness / 1e3, cell_stiffness / 1e3);
  std::printf("passenger two_layer: reference grid M = 256, N = 25 (6425 modes): table at 0 Hz %.3f s, at 1 kHz %.3f s; "
              "one receptance from the table %.2e s; cell receptance at 1 kHz %.3e %+.3ei m/N\n",
              static_seconds, table_seconds, sum_seconds, alpha.real(), alpha.imag());
  RecordProperty("first_radial_resonance_Hz", std::to_string(f01));
  RecordProperty("ring_frequency_Hz", std::to_string(ring));
  RecordProperty("static_patch_stiffness_N_per_m", std::to_string(stiffness));
  RecordProperty("table_seconds_1kHz", std::to_string(table_seconds));
  EXPECT_GE(f01, 80.0);
  EXPECT_LE(f01, 100.0);
  EXPECT_GE(ring, 370.0);
  EXPECT_LE(ring, 430.0);
  EXPECT_GE(stiffness, 200e3);
  EXPECT_LE(stiffness, 250e3);
}

// ---------------------------------------------------------------------------------------------
// 8. Bad keys.

TEST(TwoLayerTyre, BadKeysAreNamedWithWhatIsAllowed) {
  const std::string good_path = std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/passenger_205_55R16_two_layer.toml";
  std::string good;
  {
    std::ifstream in(good_path);
    good.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const test::TempFolder folder("two_layer_keys");
  bool good_path_text_swap = false;  // also make the edges sliding
  const auto message = [&](const std::string& from, const std::string& to) -> std::string {
    std::string text = good;
    if (good_path_text_swap) {
      const std::string ss = "side_condition = \"simply_supported\"";
      text.replace(text.find(ss), ss.size(), "side_condition = \"sliding\"");
    }
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return "test setup: '" + from + "' not in the model file";
    text.replace(at, from.size(), to);
    const std::filesystem::path file = folder.write("bad.toml", text);
    try {
      read_two_layer_tyre(CaseFile::load_model(file).top());
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
      return error.what();
    }
    return "no error";
  };
  // A misspelt key: named, and the allowed keys listed.
  std::string m = message("belt_youngs_modulus_x =", "belt_youngs_modulus_X =");
  EXPECT_MENTIONS(m, "belt_youngs_modulus_X");
  EXPECT_MENTIONS(m, "unknown key");
  EXPECT_MENTIONS(m, "\"belt_youngs_modulus_x\"");
  EXPECT_MENTIONS(m, "\"side_condition\"");
  // A missing key.
  EXPECT_MENTIONS(message("tread_density = 1150.0", "# tread_density"), "tread_density: is required");
  // Bad values, each naming its key and what is allowed.
  m = message("tread_poisson_ratio = 0.48", "tread_poisson_ratio = 0.5");
  EXPECT_MENTIONS(m, "tread_poisson_ratio");
  EXPECT_MENTIONS(m, "between -1 and 0.5");
  m = message("belt_youngs_modulus_z = 3.0e7", "belt_youngs_modulus_z = -3.0e7");
  EXPECT_MENTIONS(m, "belt_youngs_modulus_z: must be > 0");
  m = message("belt_poisson_yz = 0.45", "belt_poisson_yz = 7.0");
  EXPECT_MENTIONS(m, "belt_poisson_yz");
  EXPECT_MENTIONS(m, "√(E_i/E_j)");
  m = message("belt_poisson_xy = 0.3\nbelt_poisson_xz = 0.45\nbelt_poisson_yz = 0.45",
              "belt_poisson_xy = 1.4\nbelt_poisson_xz = 0.45\nbelt_poisson_yz = 6.0");  // each bound met, the set not
  EXPECT_MENTIONS(m, "belt_poisson_xy");
  EXPECT_MENTIONS(m, "positive definite");
  m = message("tread_loss_factor = 0.1", "tread_loss_factor = 0.5");
  EXPECT_MENTIONS(m, "tread_loss_factor: must be < 0.33");
  m = message("side_condition = \"simply_supported\"", "side_condition = \"clamped\"");
  EXPECT_MENTIONS(m, "side_condition");
  EXPECT_MENTIONS(m, "\"sliding\"");
  // Sliding edges need a foundation (both keys changed).
  good_path_text_swap = true;
  m = message("foundation_stiffness = 1.5e6", "foundation_stiffness = 0.0");
  good_path_text_swap = false;
  EXPECT_MENTIONS(m, "foundation_stiffness");
  EXPECT_MENTIONS(m, "sliding");
  m = message("lateral_modes = 25", "lateral_modes = 0");
  EXPECT_MENTIONS(m, "lateral_modes");
  m = message("model = \"two_layer\"", "model = \"plate\"");
  EXPECT_MENTIONS(m, "\"two_layer\"");
  // The good file reads.
  EXPECT_EQ(message("radius = 0.316", "radius = 0.316"), "no error");
}

}  // namespace
}  // namespace rollnoise
