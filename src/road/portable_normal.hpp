#pragma once
// Portable uniform and standard normal numbers from std::mt19937_64, shared by the random roads and
// surfaces. Written out rather than std::uniform_real_distribution / std::normal_distribution,
// whose algorithms the standard leaves to the implementation: the same seed must give the same
// road on every platform and standard library.
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

namespace rollnoise::portable {

// Uniform on (0, 1] from the top 53 bits, so that log() never sees 0.
inline double uniform_open_closed(std::mt19937_64& engine) {
  return (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53;
}

// Uniform on [0, 1) from the top 53 bits.
inline double uniform_closed_open(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Box-Muller: two independent standard normals from two uniforms (two engine draws).
inline std::pair<double, double> standard_normal_pair(std::mt19937_64& engine) {
  const double u1 = uniform_open_closed(engine);
  const double u2 = static_cast<double>(engine() >> 11) * 0x1.0p-53;  // [0, 1)
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

// A phase uniform on [0, 2π) as (cos, sin), from the same two engine draws as
// standard_normal_pair (whose direction it is), so that a generator can switch between complex
// normal and fixed-modulus amplitudes without changing the draws that follow.
inline std::pair<double, double> random_phasor(std::mt19937_64& engine) {
  (void)engine();  // the radius's draw of standard_normal_pair
  const double angle = 2.0 * std::numbers::pi * (static_cast<double>(engine() >> 11) * 0x1.0p-53);
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace rollnoise::portable
