#include "radiation/reflected_field_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "radiation/impedance_plane_green.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr int kMaxOrder = 6;
// The nodes' line integrals to 1e-10 of the image's field: far below the interpolation's 1e-5,
// and fewer Gauss–Kronrod panels than impedance_plane_green's 1e-13.
constexpr double kNodeTolerance = 1e-10;

// Lagrange weights on the nodes 0, 1, …, order − 1 at t, with their first and second derivatives.
struct Weights {
  std::array<double, kMaxOrder> w{}, d1{}, d2{};
};

// Π_{n≠m}(m − n) for the nodes 0 … order − 1.
constexpr std::array<double, kMaxOrder> denominators(int order) {
  std::array<double, kMaxOrder> out{};
  for (int m = 0; m < order; ++m) {
    double d = 1.0;
    for (int n = 0; n < order; ++n)
      if (n != m) d *= m - n;
    out[static_cast<std::size_t>(m)] = d;
  }
  return out;
}
constexpr std::array<double, kMaxOrder> kDenominators4 = denominators(4), kDenominators6 = denominators(6);

// Π_{n≠m}(t − n) as the product of the factors before m and those after, each carried with its
// first and second derivatives (the product rule), then divided by Π_{n≠m}(m − n).
inline Weights lagrange(double t, int order, int derivatives) {
  struct Jet {
    double p = 1.0, d1 = 0.0, d2 = 0.0;
    void times(double f) {
      d2 = d2 * f + 2.0 * d1;
      d1 = d1 * f + p;
      p *= f;
    }
  };
  std::array<Jet, kMaxOrder> before{}, after{};
  for (int m = 1; m < order; ++m) {
    before[static_cast<std::size_t>(m)] = before[static_cast<std::size_t>(m - 1)];
    before[static_cast<std::size_t>(m)].times(t - (m - 1));
  }
  for (int m = order - 2; m >= 0; --m) {
    after[static_cast<std::size_t>(m)] = after[static_cast<std::size_t>(m + 1)];
    after[static_cast<std::size_t>(m)].times(t - (m + 1));
  }
  const std::array<double, kMaxOrder>& denominator = order == 4 ? kDenominators4 : kDenominators6;
  Weights out;
  for (int m = 0; m < order; ++m) {
    const auto q = static_cast<std::size_t>(m);
    const Jet& a = before[q];
    const Jet& b = after[q];
    const double inverse = 1.0 / denominator[q];
    out.w[q] = a.p * b.p * inverse;
    if (derivatives > 0) out.d1[q] = (a.d1 * b.p + a.p * b.d1) * inverse;
    if (derivatives > 1) out.d2[q] = (a.d2 * b.p + 2.0 * a.d1 * b.d1 + a.p * b.d2) * inverse;
  }
  return out;
}

}  // namespace

double ReflectedFieldTable::spacing_for(double k, std::complex<double> admittance, double r_max, double z_max) {
  const double far = std::hypot(r_max, z_max);
  const double angle = std::max(std::abs(admittance), 1.0 / std::sqrt(std::max(1.0, k * far)));
  // Measured (tests/radiation/test_half_space_green.cpp): with 0.3 of that scale, at most
  // 0.06 rad, and quintic stencils, C within 1.3e-5 of the image's field, its first
  // derivatives within 3e-5 and its second within 1.1e-4 (relative to the image's, k + 1/R₂
  // a derivative) over the tyre's region from 20 Hz to 5.6 kHz.
  return std::clamp(0.3 * angle, 0.005, 0.06);
}

ReflectedFieldTable::ReflectedFieldTable(double k, std::complex<double> admittance, double r_max, double z_min, double z_max,
                                         double spacing, int order)
    : k_(k), h_(spacing), order_(order) {
  if (!(k > 0.0) || !std::isfinite(k) || !(r_max >= 0.0) || !(z_min > 0.0) || !(z_max >= z_min) || !std::isfinite(r_max) ||
      !std::isfinite(z_max) || !(spacing > 0.0) || !(order == 4 || order == 6) || !std::isfinite(std::abs(admittance)) ||
      admittance == 0.0 || admittance.real() < 0.0)
    throw std::invalid_argument(
        "reflected field table: k > 0, 0 < z_min <= z_max, r_max >= 0, spacing > 0, order 4 or 6 and a finite non-zero "
        "admittance with Re β >= 0 needed");
  // The log-polar rectangle round the box: R₂ from z_min to the far corner, ψ from the far low
  // corner's elevation to the vertical.
  const double xi_lo = std::log(z_min), xi_hi = std::log(std::hypot(r_max, z_max));
  const double psi_lo = std::atan2(z_min, r_max), psi_hi = 0.5 * std::numbers::pi;
  // Nodes beyond the region by half a stencil, so that its stencils are centred; below ψ_lo only
  // while Z stays positive. ψ = π/2 lies half-way between two nodes, with as many nodes past it
  // as before it within a stencil: F is even about π/2, so the interpolant of its node values on
  // a stencil straddling π/2 is exactly even there, ∂F/∂ψ vanishes at r = 0 and ∂C/∂r / r stays
  // accurate as r → 0 (the combined sources' Hessian needs it).
  const double margin = 0.5 * order * h_;
  xi0_ = xi_lo - margin;
  nxi_ = std::max(static_cast<int>(std::ceil((xi_hi + margin - xi0_) / h_)) + 1, order_);
  psi0_ = std::max(psi_lo - margin, 0.5 * psi_lo);
  const int below = std::max(static_cast<int>(std::ceil((psi_hi - psi0_) / h_ + 0.5)), order_ / 2);
  hpsi_ = (psi_hi - psi0_) / (below - 0.5);
  npsi_ = below + order_ / 2;
  xi_max_ = xi_hi;
  psi_max_ = psi_hi;
  values_.resize(static_cast<std::size_t>(nxi_) * static_cast<std::size_t>(npsi_));
  for (int i = 0; i < nxi_; ++i) {
    const double radius = std::exp(xi0_ + i * h_);
    const Complex image = std::polar(1.0 / (4.0 * std::numbers::pi * radius), -k * radius);
    Complex* row = &values_[static_cast<std::size_t>(i) * static_cast<std::size_t>(npsi_)];
    for (int j = 0; j < below; ++j) {
      const double psi = psi0_ + j * hpsi_;
      row[j] = impedance_plane_correction(k, radius * std::cos(psi), radius * std::sin(psi), admittance, kNodeTolerance) / image;
    }
    // Past ψ = π/2 (r < 0) the mirror images, to the bit: C is even in r.
    for (int j = below; j < npsi_; ++j) row[j] = row[2 * below - 1 - j];
  }
  // The region proper, for covers(): [xi_lo, xi_hi] × [psi_lo, π/2], and the box inside it.
  xi0_region_ = xi_lo;
  psi0_region_ = psi_lo;
  r_max_ = r_max;
  z_min_ = z_min;
  z_max_ = z_max;
}

std::size_t ReflectedFieldTable::estimated_nodes(double k, std::complex<double> admittance, double r_max, double z_min,
                                                 double z_max, int order) {
  const double h = spacing_for(k, admittance, r_max, z_max);
  const double xi = std::log(std::hypot(r_max, z_max) / z_min), psi = 0.5 * std::numbers::pi - std::atan2(z_min, r_max);
  return static_cast<std::size_t>((xi / h + order + 1) * (psi / h + order + 1));
}

bool ReflectedFieldTable::covers(double r, double z) const noexcept {
  // The box first (no logarithms): it lies inside the log-polar region.
  if (r >= 0.0 && r <= r_max_ && z >= z_min_ && z <= z_max_) return true;
  if (!(z > 0.0) || !(r >= 0.0)) return false;
  const double xi = 0.5 * std::log(r * r + z * z);
  const double psi = std::atan2(z, r);
  const double slack = 1e-12;
  return xi >= xi0_region_ - slack && xi <= xi_max_ + slack && psi >= psi0_region_ - slack && psi <= psi_max_ + slack;
}

template <int P>
ReflectedField ReflectedFieldTable::evaluate(double r, double z, int derivatives) const {
  const double r2sq = r * r + z * z;
  const double radius = std::sqrt(r2sq);
  const double xi = std::log(radius);
  const double psi = std::atan2(z, r);
  const auto stencil = [&](double u, int n, int& start) {
    start = std::clamp(static_cast<int>(std::floor(u)) - (P / 2 - 1), 0, n - P);
    return lagrange(u - start, P, derivatives);
  };
  int i0 = 0, j0 = 0;
  const Weights a = stencil((xi - xi0_) / h_, nxi_, i0);
  const Weights b = stencil((psi - psi0_) / hpsi_, npsi_, j0);
  // F and its derivatives in (ξ, ψ).
  Complex f = 0.0, fx = 0.0, fp = 0.0, fxx = 0.0, fxp = 0.0, fpp = 0.0;
  for (int m = 0; m < P; ++m) {
    const Complex* row = &values_[static_cast<std::size_t>(i0 + m) * static_cast<std::size_t>(npsi_) + static_cast<std::size_t>(j0)];
    Complex v = 0.0, vp = 0.0, vpp = 0.0;
    for (int n = 0; n < P; ++n) v += b.w[static_cast<std::size_t>(n)] * row[n];
    if (derivatives > 0)
      for (int n = 0; n < P; ++n) vp += b.d1[static_cast<std::size_t>(n)] * row[n];
    if (derivatives > 1)
      for (int n = 0; n < P; ++n) vpp += b.d2[static_cast<std::size_t>(n)] * row[n];
    const auto p = static_cast<std::size_t>(m);
    f += a.w[p] * v;
    fx += a.d1[p] * v;
    fp += a.w[p] * vp;
    fxx += a.d2[p] * v;
    fxp += a.d1[p] * vp;
    fpp += a.w[p] * vpp;
  }
  fx /= h_;
  fp /= hpsi_;
  fxx /= h_ * h_;
  fxp /= h_ * hpsi_;
  fpp /= hpsi_ * hpsi_;
  // C = F·E, E(ξ) = e^{−ikR}/(4πR), R = e^ξ: E′ = E(−ikR − 1), E″ = E((−ikR − 1)² − ikR).
  const Complex e = std::polar(1.0 / (4.0 * std::numbers::pi * radius), -k_ * radius);
  ReflectedField out{};
  out.value = f * e;
  if (derivatives == 0) return out;
  const Complex g1(-1.0, -k_ * radius);
  const Complex e1 = e * g1;
  const Complex e2 = e * (g1 * g1 - Complex(0.0, k_ * radius));
  const Complex hx = fx * e + f * e1, hp = fp * e;
  const Complex hxx = fxx * e + 2.0 * fx * e1 + f * e2, hxp = fxp * e + fp * e1, hpp = fpp * e;
  // The log-polar map ln(r + iZ) = ξ + iψ: ξ_r = r/R², ξ_Z = Z/R², ψ_r = −Z/R², ψ_Z = r/R²;
  // ξ_rr = −ξ_ZZ = ψ_rZ = (Z² − r²)/R⁴, ξ_rZ = −ψ_rr = ψ_ZZ = −2rZ/R⁴.
  const double xr = r / r2sq, xz = z / r2sq, pr = -z / r2sq, pz = r / r2sq;
  out.dr = hx * xr + hp * pr;
  out.dz = hx * xz + hp * pz;
  if (derivatives == 1) {
    out.dr_over_r = r > 0.0 ? out.dr / r : Complex(0.0);
    return out;
  }
  const double r4 = r2sq * r2sq;
  const double a1 = (z * z - r * r) / r4, a2 = -2.0 * r * z / r4;
  out.drr = hxx * xr * xr + 2.0 * hxp * xr * pr + hpp * pr * pr + hx * a1 - hp * a2;
  out.drz = hxx * xr * xz + hxp * (xr * pz + xz * pr) + hpp * pr * pz + hx * a2 + hp * a1;
  out.dzz = hxx * xz * xz + 2.0 * hxp * xz * pz + hpp * pz * pz - hx * a1 + hp * a2;
  // ∂C/∂r / r: H_ψ vanishes like r at r = 0 (above), so the quotient is regular; at r = 0
  // itself it is ∂²C/∂r².
  out.dr_over_r = r > 0.0 ? out.dr / r : out.drr;
  return out;
}

ReflectedField ReflectedFieldTable::operator()(double r, double z, int derivatives) const {
  return order_ == 4 ? evaluate<4>(r, z, derivatives) : evaluate<6>(r, z, derivatives);
}

}  // namespace rollnoise
