#pragma once
// The poles' one-state recursions of every mode of a rolling tyre (rolling_modes.hpp),
//   y_s ← a_s·y_s + b_s·f_r   for each pole s of mode r,
// in one pass over the poles that also leaves, per mode, what the states will give at the end of
// the coming step before its force is known, Σ_s a_s·y_s (the history engine's u⁰).
//
// Why one pass: the two-layer tyre has 164 650 poles (about 26 per mode) against the plate's
// few, and its history engine streamed them twice a step (Σ a·y for u⁰, stored, then read back
// to add b·f), 10 MB a step. Recomputing a·y in the advance is cheaper than storing and reading
// it: the pass reads a, b and y and writes y, nothing else.
//
// Bits: every value gets the operations of the plain complex arithmetic in the same order
// (a·y as (a_r y_r − a_i y_i, a_r y_i + a_i y_r), then (a·y)_r + b_r f_r − b_i f_i and
// (a·y)_i + b_r f_i + b_i f_r, no fused multiply-add), and each mode's sum runs over its poles
// in order from zero. The AVX path, two poles to a register, gives the same bits as the scalar
// one.
#include <complex>
#include <cstddef>
#include <vector>

namespace rollnoise {

class PoleRecursion {
 public:
  // Poles of mode r at first_pole[r] … first_pole[r + 1] − 1 (first_pole has modes + 1 entries);
  // decay a and input b per pole. The states start at zero.
  PoleRecursion(std::vector<std::size_t> first_pole, std::vector<std::complex<double>> decay,
                std::vector<std::complex<double>> input);

  std::size_t modes() const noexcept { return first_pole_.size() - 1; }
  std::size_t poles() const noexcept { return states_.size(); }
  std::size_t first_pole(std::size_t r) const noexcept { return first_pole_[r]; }
  const std::vector<std::complex<double>>& states() const noexcept { return states_; }
  std::vector<std::complex<double>>& states() noexcept { return states_; }
  const std::vector<std::complex<double>>& decay() const noexcept { return decay_; }
  const std::vector<std::complex<double>>& input() const noexcept { return input_; }

  // y ← a·y + b·f_r (`force`: one value per mode); with `coming` (one per mode), also
  // coming[r] = Σ a·y over the new states.
  void advance(const std::complex<double>* force, std::complex<double>* coming);
  // coming[r] = Σ a·y over the states as they are.
  void predict(std::complex<double>* coming) const;

  // Whether the pass takes two poles at a time (AVX, where the processor has it: the default) or
  // one; both give the same bits. Returns whether AVX is now used.
  bool use_avx(bool on) noexcept;

 private:
  std::vector<std::size_t> first_pole_;
  std::vector<std::complex<double>> decay_, input_, states_;
  bool avx_ = false;
};

}  // namespace rollnoise
