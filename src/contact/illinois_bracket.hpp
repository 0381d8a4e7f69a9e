#pragma once
// A bracket [lo, hi] on the root of an increasing function f (f(lo) ≤ 0 ≤ f(hi)), narrowed by
// regula falsi with the Illinois modification (Dowell & Jarratt, BIT 11 (1971) 168–174): when the
// same end moves twice running, the value kept at the other end is halved, so that an end that
// stays does not stall the iteration. Used for the indentation that carries a load, ΣF(d) = W.
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

}  // namespace rollnoise
