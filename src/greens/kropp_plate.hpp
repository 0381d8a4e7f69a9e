#pragma once
// Kropp's tyre belt model (MODEL.md §4): a tensioned orthotropic Kirchhoff plate on an elastic
// foundation, periodic around the circumference (length L = 2πR) and simply supported at the
// sides y = 0 and y = b:
//
//   Bx w,xxxx + 2Bxy w,xxyy + By w,yyyy − Tx w,xx − Ty w,yy + s_f w + m'' ẅ = p
//
// Modes φ_mn = e^{i k_m x} sin(k_n y), k_m = 2πm/L (m = −M … M), k_n = nπ/b (n = 1 … N), with
// modal stiffness K_mn = Bx k_m⁴ + 2Bxy k_m²k_n² + By k_n⁴ + Tx k_m² + Ty k_n² + s_f and
// ω_mn² = K_mn/m''. Orthogonality: ∫∫ φ_mn φ*_mn dx dy = L·b/2.
//
// Damping: every mode is a viscously damped oscillator with ζ = η/2. This is causal and exact
// in the time domain, and at each resonance it gives the same peak as the loss factor η
// (the hysteretic 1/(K(1 + iη) − m''ω²) and the viscous form agree at ω = ω_mn); away from
// resonance viscous damping grows ∝ ω instead of staying constant. The receptance below is the
// Fourier transform of this same time-domain model, so calibration and simulation agree.
//
// Green's function, material frame, impulse at (x0, y0), response at (x, y):
//   g(t) = Σ_n Σ_m  sin(k_n y) sin(k_n y0) e^{i k_m (x − x0)} h_mn(t) / (m'' L b / 2)
// with h_mn the unit-mass oscillator impulse response; it depends on x − x0 only (rotation
// invariance) and is symmetric in the two points (reciprocity).
#include <complex>
#include <span>
#include <vector>

#include "greens/modal_tyre.hpp"
#include "greens/sdof_oscillator.hpp"

namespace rollnoise {

struct PlateParameters {
  double radius = 0.0;                // R, m (L = 2πR)
  double width = 0.0;                 // b, m
  double mass_per_area = 0.0;         // m'', kg/m²
  double tension_x = 0.0;             // Tx, N/m (circumferential)
  double tension_y = 0.0;             // Ty, N/m (lateral)
  double bending_x = 0.0;             // Bx, N·m
  double bending_y = 0.0;             // By, N·m
  double bending_xy = 0.0;            // Bxy, N·m
  double foundation_stiffness = 0.0;  // s_f, N/m³ (per unit area)
  double loss_factor = 0.0;           // η (ζ = η/2 per mode)
  int circumferential_modes = 0;      // M: orders m = −M … M
  int lateral_modes = 0;              // N: n = 1 … N
};

class KroppPlate final : public ModalTyre {
 public:
  // Validates the parameters (std::invalid_argument naming the parameter).
  explicit KroppPlate(const PlateParameters& parameters);

  const PlateParameters& parameters() const noexcept { return p_; }
  double circumference() const noexcept override;  // L = 2πR
  double modal_mass() const noexcept;     // m''·L·b/2, kg
  double wavenumber_x(int m) const noexcept;
  double wavenumber_y(int n) const noexcept;
  double modal_stiffness(int m, int n) const noexcept;  // K_mn, N/m³
  double natural_frequency(int m, int n) const noexcept;  // ω_mn, rad/s
  double damping_ratio() const noexcept;                   // ζ = η/2

  // g(t), m/(N·s), for dx = x − x0 (any real), lateral positions y, y0 in [0, b].
  double green(double dx, double y, double y0, double t) const;
  // g(t) at many dx at once (out[i] for dx[i]): the per-mode time factors are computed once.
  void green_along(std::span<const double> dx, double y, double y0, double t, std::span<double> out) const;
  // ∫_{t0}^{t1} g dt, m/N (t1 may be +infinity: the static compliance).
  double green_integral(double dx, double y, double y0, double t0, double t1) const;
  // α(ω) = ∫ g e^{−iωt} dt, m/N.
  std::complex<double> receptance(double dx, double y, double y0, double omega) const;
  // Mobility Y = iω·α, m/(N·s).
  std::complex<double> mobility(double dx, double y, double y0, double omega) const;

  // The slowest modal decay rate ζ·min ω_mn (1/s) and the fastest ω_mn (rad/s).
  double slowest_decay_rate() const;
  double fastest_rate() const;

  // The static compliance ∫_0^∞ g dt = Σ φ φ*/(K_mn·L·b/2), m/N (green_integral(…, 0, ∞)).
  double static_compliance(double dx, double y, double y0) const;
  // The modal form for recursions: g = Σ_n Σ_{m=0}^{M} w_m cos(k_m dx) sin(k_n y) sin(k_n y0)
  // h_mn(t) / modal_mass() with w_0 = 1, w_m = 2, and h_mn the impulse response of
  // mode_oscillator(m, n) = {mass 1, damping 2ζω_mn = η·ω_mn, stiffness ω_mn²}.
  SdofOscillator mode_oscillator(int m, int n) const;

  // ModalTyre (modal_tyre.hpp), exactly: mode (m, l) is mode_oscillator(m, l + 1) as a
  // conjugate pair of poles, divided by the modal mass; lateral shape l is sin(k_{l+1} y). Point
  // responses: the plate is thin, its point response finite, so cell sizes are ignored.
  std::string name() const override { return "plate"; }
  double width() const override { return p_.width; }
  int orders() const override { return p_.circumferential_modes; }
  int lateral_modes() const override { return p_.lateral_modes; }
  double lateral_shape(int l, double y) const override;
  PoleResidueResponse mode_response(int m, int l, double cell_length, double cell_width) const override;
  bool includes_tread() const override { return false; }

 private:
  // Σ_n s_n Σ_m c_m·f_mn with c_m = w_m cos(k_m dx)/modal_mass, s_n = sin(k_n y) sin(k_n y0)
  // and a per-mode time factor f (h_mn(t), ∫h_mn or 1/ω_mn²).
  double modal_sum(double dx, double y, double y0, const double* factors) const;
  // The per-mode time factors of g(t) (integral = false) or of ∫_a^b g (integral = true).
  std::vector<double> time_factors(bool integral, double a, double b) const;
  double check_lateral(double y, const char* name) const;

  PlateParameters p_;
  double length_ = 0.0;       // L = 2πR
  double modal_mass_ = 0.0;   // m''·L·b/2
  double zeta_ = 0.0;         // η/2
  bool underdamped_ = true;   // ζ < 1: every mode oscillates
  double slowest_decay_ = 0.0;
  double fastest_ = 0.0;
  // Per mode, index (n − 1)·(M + 1) + m for m = 0 … M, n = 1 … N.
  std::vector<double> omega2_;      // ω_mn²
  std::vector<double> inv_omega2_;  // 1/ω_mn²
  std::vector<double> damping_;     // r = η·ω_mn (unit mass)
  std::vector<double> decay_;       // a = ζ·ω_mn
  std::vector<double> omega_d_;     // ω_mn·√(1 − ζ²) (under-damped only)
};

}  // namespace rollnoise
