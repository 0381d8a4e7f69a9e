#include "greens/tanh_sqrt_function.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace rollnoise {
namespace {

using cd = std::complex<double>;
using std::numbers::pi;

// Complex arithmetic without the slow IEEE recovery paths of the library (__divdc3, csqrt,
// cexp): every value here stays far inside the range of doubles (|μ| ≲ 1e20).
cd divide(cd z, cd w) { return z * std::conj(w) / std::norm(w); }

// The principal square root (Re ≥ 0).
cd principal_sqrt(cd z) {
  const double x = z.real(), y = z.imag();
  if (x == 0.0 && y == 0.0) return 0.0;
  const double t = std::sqrt(0.5 * (std::sqrt(x * x + y * y) + std::abs(x)));
  return x >= 0.0 ? cd(t, y / (2.0 * t)) : cd(std::abs(y) / (2.0 * t), std::copysign(t, y));
}

double magnitude(cd z) { return std::sqrt(std::norm(z)); }

// The Cauchy integral by the trapezoidal rule on a circle of radius ρ about the centre c of the
// points: its error falls as (s/ρ)^N + (ρ/r)^N, s the points' spread about c and r the distance
// from c to the nearest pole. Points within r/16 use ρ = r/4 and 28 nodes: both ratios are at
// most 1/4, the error at most 4^-28 ≈ 1.4e-17. The rounding of the sum grows like
// (r/ρ)^(n−1)·ε for n points: at most 16ε. Points farther apart take the difference quotient,
// whose cancellation is then at most about 2r/s·ε ≤ 32ε.
constexpr double close_fraction = 1.0 / 16.0;
constexpr int contour_nodes = 28;

const std::array<cd, contour_nodes>& unit_roots() {
  static const std::array<cd, contour_nodes> roots = [] {
    std::array<cd, contour_nodes> w{};
    for (int k = 0; k < contour_nodes; ++k) w[static_cast<std::size_t>(k)] = std::polar(1.0, 2.0 * pi * k / contour_nodes);
    return w;
  }();
  return roots;
}

// f[z_0, …, z_{n−1}] = (1/2πi)∮ f(z)/Π(z − z_j) dz, for points within r/16 of `centre`.
template <std::size_t n>
cd contour_divided(const std::array<cd, n>& z, cd centre, double r) {
  const double radius = 0.25 * r;
  cd sum = 0.0;
  for (const cd w : unit_roots()) {
    const cd point = centre + radius * w;
    cd denominator = 1.0;
    for (const cd zj : z) denominator *= point - zj;
    sum += divide(tanh_sqrt(point) * (radius * w), denominator);
  }
  return sum / static_cast<double>(contour_nodes);
}

// Points within 1e-8·r of their centre c (a repeated root split by round-off) need only the
// derivatives there: f[a, b] = f'(c) + O(s²/r²), f[a, b, d] = f''(c)/2 + O(s²/r²) about the
// centroid, both below 1e-16 relative.
constexpr double confluent_fraction = 1e-8;

// tanh(s)/s = Σ a_j μ^j (a_j = 2^{2n}(2^{2n} − 1) B_{2n}/(2n)!, n = j + 1), convergent for
// |μ| < π²/4; for |μ| < 1/4 the terms fall by 0.1 each, and 22 of them reach 1e-20.
constexpr std::array<double, 22> series = {
    1.0, -0.33333333333333331, 0.13333333333333333, -0.053968253968253971, 0.021869488536155203,
    -0.0088632355299021973, 0.0035921280365724811, -0.0014558343870513183, 0.00059002744094558595,
    -0.00023912911424355248, 9.6915379569294509e-05, -3.9278323883316833e-05, 1.5918905069328964e-05,
    -6.4516892156554306e-06, 2.6147711512907546e-06, -1.0597268320104654e-06, 4.2949110782738057e-07,
    -1.7406618963571648e-07, 7.0546369464009681e-08, -2.859136662305254e-08, 1.1587644432798853e-08,
    -4.6962953982309016e-09};

// f'(μ) and f''(μ)/2.
struct Derivatives {
  cd first;
  cd half_second;
};

Derivatives derivatives(cd mu) {
  if (std::abs(mu) < 0.25) {
    cd first = 0.0, half_second = 0.0;
    for (std::size_t j = series.size() - 1; j >= 1; --j) first = first * mu + static_cast<double>(j) * series[j];
    for (std::size_t j = series.size() - 1; j >= 2; --j) {
      half_second = half_second * mu + 0.5 * static_cast<double>(j * (j - 1)) * series[j];
    }
    return {first, half_second};
  }
  // With s = √μ, T = tanh s, S = sech² s = 4e^{−2s}/(1 + e^{−2s})² (no cancellation as T → 1):
  //   f'  = (sS − T)/(2s³),   f'' = (3T − 3sS − 2s²TS)/(4s⁵).
  // Their numerators cancel like s³ and s⁵ for small s: relative error ≤ 16ε at |μ| = 1/4.
  const cd s = std::sqrt(mu);
  const cd e = std::exp(-2.0 * s);
  const cd t = (1.0 - e) / (1.0 + e);
  const cd sech2 = 4.0 * e / ((1.0 + e) * (1.0 + e));
  const cd s2 = s * s;
  return {(s * sech2 - t) / (2.0 * s2 * s), (3.0 * t - 3.0 * s * sech2 - 2.0 * s2 * t * sech2) / (8.0 * s2 * s2 * s)};
}

}  // namespace

cd tanh_sqrt(cd mu) {
  if (std::abs(mu) < 1e-3) {
    // tanh(s)/s = 1 − s²/3 + 2s⁴/15 − 17s⁶/315 + 62s⁸/2835 − …; the next term is below 1e-17.
    return 1.0 + mu * (-1.0 / 3.0 + mu * (2.0 / 15.0 + mu * (-17.0 / 315.0 + mu * (62.0 / 2835.0))));
  }
  // Principal root: Re s ≥ 0, so e^{−2s} never overflows; f is even in s, so the branch is
  // immaterial.
  const cd s = principal_sqrt(mu);
  const cd e = std::polar(std::exp(-2.0 * s.real()), -2.0 * s.imag());
  return divide(1.0 - e, (1.0 + e) * s);
}

double tanh_sqrt_pole_distance(cd mu) {
  const auto pole = [](double j) { return -(pi * (j + 0.5)) * (pi * (j + 0.5)); };
  const double x = mu.real();
  double best = magnitude(mu - pole(0.0));
  if (x < pole(0.0)) {
    const double t = std::sqrt(-x) / pi - 0.5;
    for (const double j : {std::floor(t), std::ceil(t)}) best = std::min(best, magnitude(mu - pole(std::max(j, 0.0))));
  }
  return best;
}

namespace {

// f[a, b] given f(a) and f(b) (used only when the points lie apart).
cd divided(cd a, cd b, cd fa, cd fb) {
  const cd centre = 0.5 * (a + b);
  const double spread = 0.5 * magnitude(a - b);
  const double r = tanh_sqrt_pole_distance(centre);
  if (spread <= confluent_fraction * r) return derivatives(centre).first;
  if (spread <= close_fraction * r) return contour_divided<2>({a, b}, centre, r);
  return divide(fa - fb, a - b);
}

// f[a, b, c] given the pairs' divided differences (used only when the points lie apart).
cd divided(cd a, cd b, cd c, cd fab, cd fbc, cd fac) {
  const cd centre = (a + b + c) / 3.0;
  const double spread = std::max({magnitude(a - centre), magnitude(b - centre), magnitude(c - centre)});
  const double r = tanh_sqrt_pole_distance(centre);
  if (spread <= confluent_fraction * r) return derivatives(centre).half_second;
  if (spread <= close_fraction * r) return contour_divided<3>({a, b, c}, centre, r);
  // The recursion divides by the widest pair: put it first and last.
  const double ab = magnitude(a - b), bc = magnitude(b - c), ac = magnitude(a - c);
  if (ab >= ac && ab >= bc) return divide(fac - fbc, a - b);  // z = (a, c, b)
  if (bc >= ac && bc >= ab) return divide(fab - fac, b - c);  // z = (b, a, c)
  return divide(fab - fbc, a - c);                            // z = (a, b, c)
}

}  // namespace

cd tanh_sqrt_divided(cd a, cd b) {
  const cd centre = 0.5 * (a + b);
  const double spread = 0.5 * magnitude(a - b);
  if (spread <= close_fraction * tanh_sqrt_pole_distance(centre)) return divided(a, b, 0.0, 0.0);
  return divided(a, b, tanh_sqrt(a), tanh_sqrt(b));
}

cd tanh_sqrt_divided(cd a, cd b, cd c) {
  return divided(a, b, c, tanh_sqrt_divided(a, b), tanh_sqrt_divided(b, c), tanh_sqrt_divided(a, c));
}

Eigen::Matrix3cd tanh_sqrt(const Eigen::Matrix3cd& m) {
  const Eigen::ComplexSchur<Eigen::Matrix3cd> schur(m);
  const Eigen::Matrix3cd& t = schur.matrixT();
  // Each value of f and each divided difference once: the three-point one reuses the pairs'.
  const cd t0 = t(0, 0), t1 = t(1, 1), t2 = t(2, 2);
  const cd f0 = tanh_sqrt(t0), f1 = tanh_sqrt(t1), f2 = tanh_sqrt(t2);
  const cd f01 = divided(t0, t1, f0, f1), f12 = divided(t1, t2, f1, f2), f02 = divided(t0, t2, f0, f2);
  Eigen::Matrix3cd f = Eigen::Matrix3cd::Zero();
  f(0, 0) = f0;
  f(1, 1) = f1;
  f(2, 2) = f2;
  f(0, 1) = t(0, 1) * f01;
  f(1, 2) = t(1, 2) * f12;
  f(0, 2) = t(0, 2) * f02 + t(0, 1) * t(1, 2) * divided(t0, t1, t2, f01, f12, f02);
  const Eigen::Matrix3cd& u = schur.matrixU();
  return u * f * u.adjoint();
}

Eigen::Matrix3cd tanh_sqrt(const Eigen::Matrix3cd& m, cd mu1, cd mu2) {
  const cd slope = tanh_sqrt_divided(mu1, mu2);
  Eigen::Matrix3cd f = slope * m;
  f.diagonal().array() += tanh_sqrt(mu1) - slope * mu1;
  return f;
}

}  // namespace rollnoise
