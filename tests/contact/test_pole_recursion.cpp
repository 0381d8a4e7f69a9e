// The poles' recursion of the modal history engine (pole_recursion.hpp): its one pass against
// the complex arithmetic written out, and its AVX path against its scalar one, bit for bit.
#include <complex>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "contact/pole_recursion.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

// Modes with 0 to 7 poles (odd counts leave the AVX path a single pole at the end), decays
// inside the unit circle, random inputs and forces.
struct RandomPoles {
  std::vector<std::size_t> first{0};
  std::vector<Complex> decay, input;
  explicit RandomPoles(std::mt19937_64& rng, std::size_t modes) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> count(0, 7);
    for (std::size_t r = 0; r < modes; ++r) {
      for (int s = count(rng); s > 0; --s) {
        decay.push_back(std::polar(0.5 + 0.49 * u(rng), 3.0 * u(rng)));
        input.emplace_back(u(rng), u(rng));
      }
      first.push_back(decay.size());
    }
  }
};

TEST(PoleRecursion, OnePassEqualsTheRecursionWrittenOut) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t modes = 40;
  const RandomPoles p(rng, modes);
  PoleRecursion recursion(p.first, p.decay, p.input);
  recursion.use_avx(false);
  std::vector<Complex> y(p.decay.size(), 0.0), force(modes), coming(modes);
  for (int step = 0; step < 5; ++step) {
    for (Complex& f : force) f = {u(rng), u(rng)};
    recursion.advance(force.data(), coming.data());
    for (std::size_t r = 0; r < modes; ++r) {
      double sum_re = 0.0, sum_im = 0.0;
      for (std::size_t s = p.first[r]; s < p.first[r + 1]; ++s) {
        const double ar = p.decay[s].real(), ai = p.decay[s].imag(), yr = y[s].real(), yi = y[s].imag();
        const double pr = ar * yr - ai * yi, pi = ar * yi + ai * yr;
        const double br = p.input[s].real(), bi = p.input[s].imag(), fr = force[r].real(), fi = force[r].imag();
        y[s] = {pr + br * fr - bi * fi, pi + br * fi + bi * fr};
        sum_re += ar * y[s].real() - ai * y[s].imag();
        sum_im += ar * y[s].imag() + ai * y[s].real();
      }
      EXPECT_EQ(coming[r], Complex(sum_re, sum_im)) << "mode " << r;
    }
    for (std::size_t s = 0; s < y.size(); ++s) EXPECT_EQ(recursion.states()[s], y[s]) << "pole " << s;
    // Σ a·y from the states as they are is what the pass left.
    std::vector<Complex> predicted(modes);
    recursion.predict(predicted.data());
    EXPECT_EQ(predicted, coming);
  }
}

TEST(PoleRecursion, AvxPathGivesTheScalarBits) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t modes = 57;
  const RandomPoles p(rng, modes);
  PoleRecursion scalar(p.first, p.decay, p.input), vector(p.first, p.decay, p.input);
  scalar.use_avx(false);
  if (!vector.use_avx(true)) GTEST_SKIP() << "no AVX on this processor";
  std::vector<Complex> force(modes), coming_scalar(modes), coming_vector(modes);
  for (int step = 0; step < 20; ++step) {
    for (Complex& f : force) f = {u(rng), u(rng)};
    // Every other step without the prediction, as the response stage's engine advances.
    const bool predict = step % 2 == 0;
    scalar.advance(force.data(), predict ? coming_scalar.data() : nullptr);
    vector.advance(force.data(), predict ? coming_vector.data() : nullptr);
    ASSERT_EQ(scalar.states(), vector.states()) << "step " << step;
    if (predict) {
      ASSERT_EQ(coming_scalar, coming_vector) << "step " << step;
    }
  }
}

TEST(PoleRecursion, RejectsInconsistentPoles) {
  EXPECT_THROW(PoleRecursion({0, 2}, {0.5, 0.5}, {1.0}), std::invalid_argument);
  EXPECT_THROW(PoleRecursion({0, 3}, {0.5, 0.5}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(PoleRecursion({0, 2, 1}, {0.5, 0.5}, {1.0, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace rollnoise
