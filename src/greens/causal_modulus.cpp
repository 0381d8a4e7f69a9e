#include "greens/causal_modulus.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollnoise {
namespace {

constexpr double tau_long = 1.0 / (2.0 * std::numbers::pi * CausalModulus::band_low);    // τ2
constexpr double tau_short = 1.0 / (2.0 * std::numbers::pi * CausalModulus::band_high);  // τ1

// L(ω) = ln(1 + iωτ2) − ln(1 + iωτ1). For Im ω ≤ 0 both arguments have a real part ≥ 1, so the
// principal logarithms are continuous and their difference is the logarithm of the ratio.
std::complex<double> relaxation_log(std::complex<double> omega) {
  const std::complex<double> i(0.0, 1.0);
  return std::log(1.0 + i * omega * tau_long) - std::log(1.0 + i * omega * tau_short);
}

std::complex<double> reference_log() {
  return relaxation_log(2.0 * std::numbers::pi * CausalModulus::reference_frequency);
}

}  // namespace

double CausalModulus::largest_loss_factor() {
  const std::complex<double> l = reference_log();
  return l.imag() / l.real();
}

CausalModulus::CausalModulus(double loss_factor) : eta_(loss_factor) {
  if (!std::isfinite(loss_factor) || loss_factor < 0.0) {
    throw std::invalid_argument("loss factor must be finite and >= 0");
  }
  const std::complex<double> l = reference_log();
  const double denominator = l.imag() - eta_ * l.real();
  if (!(denominator > 0.0)) {
    throw std::invalid_argument("loss factor " + std::to_string(loss_factor) + " must be < " +
                                std::to_string(largest_loss_factor()) +
                                ": a causal modulus with nearly constant loss from 10 Hz to 100 kHz cannot carry more "
                                "(its static modulus would not be positive)");
  }
  // ψ(ω_ref) = ψ0(1 + c·L_ref) = 1 + iη (see the header).
  c_ = eta_ / denominator;
  psi0_ = 1.0 / (1.0 + c_ * l.real());
}

std::complex<double> CausalModulus::factor(std::complex<double> omega) const {
  if (c_ == 0.0) return {1.0, 0.0};
  if (omega == 0.0) return {psi0_, 0.0};
  return psi0_ * (1.0 + c_ * relaxation_log(omega));
}

double CausalModulus::high_frequency_factor() const noexcept {
  return psi0_ * (1.0 + c_ * std::log(tau_long / tau_short));
}

double CausalModulus::loss_factor_at(double omega) const {
  const std::complex<double> psi = factor(omega);
  return psi.imag() / psi.real();
}

}  // namespace rollnoise
