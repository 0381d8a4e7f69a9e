#include "greens/oscillator_recursion.hpp"

#include <complex>

namespace rollnoise {

OscillatorRecursion make_oscillator_recursion(const SdofOscillator& o, double dt) {
  const double h = o.impulse_response(dt);
  const double dh = o.impulse_response_rate(dt);
  OscillatorRecursion r;
  // Free response from (x0, v0): x = x0·(m ḣ + r h) + v0·m h, v = −x0·k h + v0·m ḣ.
  r.transition << o.mass * dh + o.damping * h, o.mass * h,  //
      -o.stiffness * h, o.mass * dh;
  r.input << o.step_response(dt), h;
  return r;
}

TravellingRecursion make_travelling_recursion(const SdofOscillator& o, double dt, double omega) {
  const OscillatorRecursion still = make_oscillator_recursion(o, dt);
  const std::complex<double> rho = std::polar(1.0, omega * dt);
  const std::complex<double> integral = o.phase_integral(omega, 0.0, dt);
  TravellingRecursion r;
  r.transition = rho * still.transition.cast<std::complex<double>>();
  r.input << integral, rho * o.impulse_response(dt) - std::complex<double>(0.0, omega) * integral;
  return r;
}

}  // namespace rollnoise
