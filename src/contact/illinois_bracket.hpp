#pragma once
// A bracket [lo, hi] on the root of an increasing function f (f(lo) ≤ 0 ≤ f(hi)), narrowed by
// regula falsi with the Illinois modification (Dowell & Jarratt, BIT 11 (1971) 168–174): when the
// same end moves twice running, the value kept at the other end is halved, so that an end that
// stays does not stall the iteration. Used for the indentation that carries a load, ΣF(d) = W.
#include <cmath>
#include <stdexcept>
#include <string>

namespace rollnoise {

struct IllinoisBracket {
  double lo = 0.0, f_lo = 0.0, hi = 0.0, f_hi = 0.0;
  int side = 0;  // which end moved last: −1 lo, +1 hi, 0 neither yet

  // The secant of the ends (with their values as kept).
  double regula_falsi() const { return (lo * f_hi - hi * f_lo) / (f_hi - f_lo); }

  // f(d) = f, with d inside the bracket, replaces the end on its side.
  void narrow(double d, double f) {
    if (f < 0.0) {
      lo = d;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = d;
      f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
};

// The first bracket of the indentation that carries the load: from the first touch (where
// f(touch) = f_touch < 0) down to touch + first_depth, the depth doubled until f ≥ 0. A depth
// beyond max_depth, or not finite, is a runtime_error with `failure`.
template <class F>
IllinoisBracket bracket_by_doubling(double touch, double f_touch, double first_depth, double max_depth,
                                    const std::string& failure, F&& f) {
  IllinoisBracket bracket{touch, f_touch, touch + first_depth, 0.0};
  bracket.f_hi = f(bracket.hi);
  while (bracket.f_hi < 0.0) {
    bracket.lo = bracket.hi;
    bracket.f_lo = bracket.f_hi;
    bracket.hi = touch + 2.0 * (bracket.hi - touch);
    if (!std::isfinite(bracket.hi) || bracket.hi - touch > max_depth) throw std::runtime_error(failure);
    bracket.f_hi = f(bracket.hi);
  }
  return bracket;
}

}  // namespace rollnoise
