#include "greens/kropp_plate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollnoise {
namespace {


void require(bool ok, const char* name, const char* condition) {
  if (!ok) throw std::invalid_argument(std::string("plate: ") + name + " must be " + condition);
}

void require_positive(double v, const char* name) {
  require(std::isfinite(v) && v > 0.0, name, "finite and > 0");
}

void require_non_negative(double v, const char* name) {
  require(std::isfinite(v) && v >= 0.0, name, "finite and >= 0");
}

}  // namespace

KroppPlate::KroppPlate(const PlateParameters& parameters) : p_(parameters) {
  require_positive(p_.radius, "radius");
  require_positive(p_.width, "width");
  require_positive(p_.mass_per_area, "mass_per_area");
  require_non_negative(p_.tension_x, "tension_x");
  require_non_negative(p_.tension_y, "tension_y");
  require_non_negative(p_.bending_x, "bending_x");
  require_non_negative(p_.bending_y, "bending_y");
  require_non_negative(p_.bending_xy, "bending_xy");
  require_non_negative(p_.foundation_stiffness, "foundation_stiffness");
  // K_0n = By k_n⁴ + Ty k_n² + s_f is the smallest stiffness of lateral order n; every other
  // term only adds. So every K_mn > 0 exactly when one of these three is > 0.
  require(p_.foundation_stiffness > 0.0 || p_.tension_y > 0.0 || p_.bending_y > 0.0,
          "foundation_stiffness",
          "> 0 unless tension_y or bending_y is > 0 (otherwise the plate has a rigid-body mode)");
  // η = 0 is allowed: the rolling tyre's steady state needs no decay (it is found from the
  // compliance summed over all lags in closed form), and an undamped belt is the reference
  // for zero rolling resistance.
  require_non_negative(p_.loss_factor, "loss_factor");
  require(p_.circumferential_modes >= 0, "circumferential_modes", ">= 0");
  require(p_.lateral_modes >= 1, "lateral_modes", ">= 1");

  length_ = 2.0 * std::numbers::pi * p_.radius;
  modal_mass_ = p_.mass_per_area * length_ * p_.width / 2.0;
  zeta_ = p_.loss_factor / 2.0;
  underdamped_ = zeta_ < 1.0;

  const std::size_t columns = static_cast<std::size_t>(p_.circumferential_modes) + 1;
  const std::size_t count = columns * static_cast<std::size_t>(p_.lateral_modes);
  omega2_.resize(count);
  inv_omega2_.resize(count);
  damping_.resize(count);
  decay_.resize(count);
  omega_d_.resize(count);
  slowest_decay_ = std::numeric_limits<double>::infinity();
  fastest_ = 0.0;
  const double damped = std::sqrt(std::max(0.0, 1.0 - zeta_ * zeta_));
  for (int n = 1; n <= p_.lateral_modes; ++n) {
    for (int m = 0; m <= p_.circumferential_modes; ++m) {
      const std::size_t i = static_cast<std::size_t>(n - 1) * columns + static_cast<std::size_t>(m);
      const double w2 = modal_stiffness(m, n) / p_.mass_per_area;
      const double w = std::sqrt(w2);
      omega2_[i] = w2;
      inv_omega2_[i] = 1.0 / w2;
      damping_[i] = p_.loss_factor * w;
      decay_[i] = zeta_ * w;
      omega_d_[i] = w * damped;
      const SdofOscillator o = mode_oscillator(m, n);
      slowest_decay_ = std::min(slowest_decay_, o.slowest_decay_rate());
      fastest_ = std::max(fastest_, o.fastest_rate());
    }
  }
}

double KroppPlate::circumference() const noexcept { return length_; }

double KroppPlate::modal_mass() const noexcept { return modal_mass_; }

double KroppPlate::wavenumber_x(int m) const noexcept {
  return 2.0 * std::numbers::pi * static_cast<double>(m) / length_;
}

double KroppPlate::wavenumber_y(int n) const noexcept {
  return std::numbers::pi * static_cast<double>(n) / p_.width;
}

double KroppPlate::modal_stiffness(int m, int n) const noexcept {
  const double kx2 = wavenumber_x(m) * wavenumber_x(m);
  const double ky2 = wavenumber_y(n) * wavenumber_y(n);
  return p_.bending_x * kx2 * kx2 + 2.0 * p_.bending_xy * kx2 * ky2 + p_.bending_y * ky2 * ky2 +
         p_.tension_x * kx2 + p_.tension_y * ky2 + p_.foundation_stiffness;
}

double KroppPlate::natural_frequency(int m, int n) const noexcept {
  return std::sqrt(modal_stiffness(m, n) / p_.mass_per_area);
}

double KroppPlate::damping_ratio() const noexcept { return zeta_; }

SdofOscillator KroppPlate::mode_oscillator(int m, int n) const {
  const double w = natural_frequency(m, n);
  return SdofOscillator{1.0, p_.loss_factor * w, w * w};
}

double KroppPlate::lateral_shape(int l, double y) const { return std::sin(wavenumber_y(l + 1) * y); }

PoleResidueResponse KroppPlate::mode_response(int m, int l, double /*cell_length*/, double /*cell_width*/) const {
  PoleResidueResponse poles = oscillator_poles(mode_oscillator(m, l + 1));
  for (auto& residue : poles.residues) residue /= modal_mass_;
  return poles;
}

double KroppPlate::check_lateral(double y, const char* name) const {
  // Grid positions computed as (j + ½)·Δy may overshoot b by a rounding error: allow that.
  const double slack = 1e-9 * p_.width;
  if (!(y >= -slack && y <= p_.width + slack)) {
    throw std::invalid_argument(std::string("plate: ") + name + " = " + std::to_string(y) +
                                " m lies outside the width [0, " + std::to_string(p_.width) + "]");
  }
  return std::clamp(y, 0.0, p_.width);
}

double KroppPlate::modal_sum(double dx, double y, double y0, const double* factors) const {
  if (!std::isfinite(dx)) throw std::invalid_argument("plate: dx must be finite");
  const double ya = check_lateral(y, "y");
  const double yb = check_lateral(y0, "y0");
  // Reduce to one turn first: cos(k_m·dx) then keeps its digits for any number of turns.
  const double x = std::remainder(dx, length_);
  const std::size_t columns = static_cast<std::size_t>(p_.circumferential_modes) + 1;
  std::vector<double> c(columns);
  c[0] = 1.0;
  for (std::size_t m = 1; m < columns; ++m) c[m] = 2.0 * std::cos(wavenumber_x(static_cast<int>(m)) * x);
  double sum = 0.0;
  for (int n = 1; n <= p_.lateral_modes; ++n) {
    const double k = wavenumber_y(n);
    const double lateral = std::sin(k * ya) * std::sin(k * yb);
    if (lateral == 0.0) continue;
    const double* f = factors + static_cast<std::size_t>(n - 1) * columns;
    double inner = 0.0;
    for (std::size_t m = 0; m < columns; ++m) inner += c[m] * f[m];
    sum += lateral * inner;
  }
  return sum / modal_mass_;
}

std::vector<double> KroppPlate::time_factors(bool integral, double a, double b) const {
  struct {
    std::vector<double> f;
  } cache;  // the factor of each mode
  cache.f.resize(omega2_.size());
  for (std::size_t i = 0; i < omega2_.size(); ++i) {
    if (underdamped_) {
      const double alpha = decay_[i];
      const double wd = omega_d_[i];
      if (!integral) {
        // h = e^{−αt} sin(ω_d t)/ω_d for a unit mass.
        cache.f[i] = std::exp(-alpha * a) * std::sin(wd * a) / wd;
      } else {
        // ∫_a^b h = (E(a) − E(b))/ω² with E(t) = e^{−αt}(cos ω_d t + (α/ω_d) sin ω_d t),
        // E(0) = 1, E(∞) = 0. The difference form avoids 1 − E cancelling for long lags.
        const auto shape = [&](double t) {
          if (t == 0.0) return 1.0;
          if (std::isinf(t)) return 0.0;
          return std::exp(-alpha * t) * (std::cos(wd * t) + alpha / wd * std::sin(wd * t));
        };
        cache.f[i] = (shape(a) - shape(b)) * inv_omega2_[i];
      }
    } else {
      const SdofOscillator o{1.0, damping_[i], omega2_[i]};
      cache.f[i] = integral ? o.step_response(b) - o.step_response(a) : o.impulse_response(a);
    }
  }
  return cache.f;
}

double KroppPlate::green(double dx, double y, double y0, double t) const {
  if (std::isnan(t)) throw std::invalid_argument("plate: t must not be NaN");
  if (!(t > 0.0) || std::isinf(t)) {
    if (!std::isfinite(dx)) throw std::invalid_argument("plate: dx must be finite");
    check_lateral(y, "y");
    check_lateral(y0, "y0");
    return 0.0;
  }
  return modal_sum(dx, y, y0, time_factors(false, t, t).data());
}

void KroppPlate::green_along(std::span<const double> dx, double y, double y0, double t, std::span<double> out) const {
  if (dx.size() != out.size()) throw std::invalid_argument("plate: green_along needs one output per dx");
  if (!(t > 0.0) || std::isinf(t)) {
    for (std::size_t i = 0; i < dx.size(); ++i) out[i] = green(dx[i], y, y0, t);
    return;
  }
  const std::vector<double> factors = time_factors(false, t, t);
  for (std::size_t i = 0; i < dx.size(); ++i) out[i] = modal_sum(dx[i], y, y0, factors.data());
}

double KroppPlate::static_compliance(double dx, double y, double y0) const {
  return modal_sum(dx, y, y0, inv_omega2_.data());
}

double KroppPlate::green_integral(double dx, double y, double y0, double t0, double t1) const {
  if (std::isnan(t0) || std::isnan(t1)) throw std::invalid_argument("plate: times must not be NaN");
  const double a = std::max(t0, 0.0);
  const double b = std::max(t1, 0.0);
  if (a == 0.0 && std::isinf(b)) return static_compliance(dx, y, y0);
  if (a == b) {
    if (!std::isfinite(dx)) throw std::invalid_argument("plate: dx must be finite");
    check_lateral(y, "y");
    check_lateral(y0, "y0");
    return 0.0;
  }
  // Negative for t1 < t0, as ∫_{t0}^{t1}.
  return modal_sum(dx, y, y0, time_factors(true, a, b).data());
}

std::complex<double> KroppPlate::receptance(double dx, double y, double y0, double omega) const {
  if (!std::isfinite(omega)) throw std::invalid_argument("plate: omega must be finite");
  // 1/(ω_mn² − ω² + iω·η·ω_mn): the Fourier transform of the viscous modal response; the real
  // and imaginary parts are two real modal sums.
  thread_local std::vector<double> re, im;
  re.resize(omega2_.size());
  im.resize(omega2_.size());
  const double w2 = omega * omega;
  for (std::size_t i = 0; i < omega2_.size(); ++i) {
    const double A = omega2_[i] - w2;
    const double B = omega * damping_[i];
    const double inv = 1.0 / (A * A + B * B);
    re[i] = A * inv;
    im[i] = -B * inv;
  }
  return {modal_sum(dx, y, y0, re.data()), modal_sum(dx, y, y0, im.data())};
}

std::complex<double> KroppPlate::mobility(double dx, double y, double y0, double omega) const {
  return std::complex<double>(0.0, omega) * receptance(dx, y, y0, omega);
}

double KroppPlate::slowest_decay_rate() const { return slowest_decay_; }

double KroppPlate::fastest_rate() const { return fastest_; }

}  // namespace rollnoise
