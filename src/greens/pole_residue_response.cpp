#include "greens/pole_residue_response.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "greens/sdof_oscillator.hpp"

namespace rollnoise {

namespace {
constexpr std::complex<double> kI(0.0, 1.0);

// (e^{q t1} − e^{q t0})/q, also for |q·(t1 − t0)| small (where the difference cancels).
std::complex<double> exponential_integral(std::complex<double> q, double t0, double t1) {
  const std::complex<double> z = q * (t1 - t0);
  std::complex<double> ratio;  // (e^z − 1)/z
  if (std::abs(z) < 1e-4) {
    ratio = 1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0));
  } else {
    ratio = (std::exp(z) - 1.0) / z;  // relative error ≈ ε/|z| ≤ 1e-12
  }
  return std::exp(q * t0) * ratio * (t1 - t0);
}
}  // namespace

std::complex<double> PoleResidueResponse::receptance(double omega) const {
  // ρ/(iω − p) = ρ·conj(d)/|d|², d = iω − p, in reals: std::complex's division guards against
  // overflow and infinities (__divdc3) at many times the cost; d = 0 only for a pole on the
  // imaginary axis at ω, where the response is infinite either way.
  double re = direct, im = 0.0;
  for (std::size_t r = 0; r < poles.size(); ++r) {
    const double dr = -poles[r].real(), di = omega - poles[r].imag();
    const double scale = 1.0 / (dr * dr + di * di);
    const double rr = residues[r].real(), ri = residues[r].imag();
    re += (rr * dr + ri * di) * scale;
    im += (ri * dr - rr * di) * scale;
  }
  return {re, im};
}

double PoleResidueResponse::impulse_response(double t) const {
  if (t < 0.0) return 0.0;
  std::complex<double> sum = 0.0;
  for (std::size_t r = 0; r < poles.size(); ++r) sum += residues[r] * std::exp(poles[r] * t);
  return sum.real();
}

std::complex<double> PoleResidueResponse::phase_integral(double omega, double t0, double t1) const {
  if (!(t0 >= 0.0 && t1 >= t0)) throw std::invalid_argument("phase_integral: need 0 <= t0 <= t1");
  std::complex<double> sum = t0 == 0.0 && t1 > 0.0 ? std::complex<double>(direct) : 0.0;
  for (std::size_t r = 0; r < poles.size(); ++r)
    sum += residues[r] * exponential_integral(poles[r] + kI * omega, t0, t1);
  return sum;
}

void PoleResidueResponse::validate() const {
  if (poles.size() != residues.size()) throw std::invalid_argument("pole-residue response: poles and residues differ in number");
  if (!std::isfinite(direct)) throw std::invalid_argument("pole-residue response: the direct term is not finite");
  for (std::size_t r = 0; r < poles.size(); ++r) {
    const auto p = poles[r];
    if (!std::isfinite(p.real()) || !std::isfinite(p.imag()) || !std::isfinite(residues[r].real()) ||
        !std::isfinite(residues[r].imag()))
      throw std::invalid_argument("pole-residue response: pole or residue " + std::to_string(r) + " is not finite");
    if (!(p.real() < 0.0)) throw std::invalid_argument("pole-residue response: pole " + std::to_string(r) + " is not stable");
    const double tol = 1e-9 * std::abs(p);
    if (std::abs(p.imag()) <= tol) {
      if (std::abs(residues[r].imag()) > 1e-9 * std::abs(residues[r]))
        throw std::invalid_argument("pole-residue response: real pole " + std::to_string(r) + " has a complex residue");
      continue;
    }
    bool paired = false;
    for (std::size_t s = 0; s < poles.size() && !paired; ++s)
      paired = s != r && std::abs(poles[s] - std::conj(p)) <= tol &&
               std::abs(residues[s] - std::conj(residues[r])) <= 1e-9 * std::abs(residues[r]);
    if (!paired) throw std::invalid_argument("pole-residue response: pole " + std::to_string(r) + " has no conjugate partner");
  }
}

PoleResidueResponse oscillator_poles(const SdofOscillator& o) {
  const double a = o.damping / (2.0 * o.mass);
  const double w2 = o.stiffness / o.mass;
  PoleResidueResponse out;
  if (a * a < w2) {
    const double wd = std::sqrt(w2 - a * a);
    out.poles = {{-a, wd}, {-a, -wd}};
    const std::complex<double> rho = -kI / (2.0 * o.mass * wd);
    out.residues = {rho, std::conj(rho)};
  } else {
    const double beta = std::max(std::sqrt(a * a - w2), 1e-6 * a);
    out.poles = {{-a + beta, 0.0}, {-a - beta, 0.0}};
    const double rho = 1.0 / (2.0 * o.mass * beta);
    out.residues = {rho, -rho};
  }
  return out;
}

}  // namespace rollnoise
