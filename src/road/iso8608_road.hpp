#pragma once
// A road profile of an ISO 8608 unevenness class (MODEL.md §7): a stationary Gaussian profile
// with the displacement spectral density of ISO 8608:2016 (Mechanical vibration — Road surface
// profiles — Reporting of measured data),
//     G_d(n) = G_d(n0) (n / n0)^(-w),   n0 = 0.1 cycles/m,
// one-sided (m^2 per cycle/m, i.e. m^3), over the standard's classification range of spatial
// frequency n from 0.011 to 2.83 cycles/m (octave bands centred 0.0156 to 2 cycles/m; about
// 0.35 m to 90 m wavelength), zero outside it. [road] type = "iso8608". (The standard's notes
// put the lower limit of on-road measurements at about 0.01 cycles/m and recommend 10 cycles/m
// as the upper limit for vehicle vibration; shorter wavelengths, up to texture, are not part of
// the class and not generated here (the texture road covers them; the two cannot yet be summed).)
//
// Keys. `class` = "A" .. "H": G_d(n0) the class's geometric mean (A 16e-6, B 64e-6, C 256e-6,
// D 1024e-6, E 4096e-6, F 16384e-6, G 65536e-6, H 262144e-6 m^3), w = 2; or `gd_n0` (m^3, > 0)
// with `waviness` (w, default 2) instead. `seed` (default 1), `length` (m, default 100),
// `sample_spacing` (m, default 0.04; at most 1 / (2 × 2.83) ≈ 0.177 m, the Nyquist limit of the
// range), `lead_in` (m, default 10: a raised-cosine ramp from r(0) = 0, gentle next to the
// unevenness wavelengths).
//
// Synthesis: random phases, complex normal amplitudes of the absolute spectrum
// (spectral_synthesis.hpp), not rescaled, over a periodic grid of at least 8 longest wavelengths
// (727 m) and the covered length plus two longest wavelengths. The profile covers
// [0, max(length, x_max)] and is fixed by its keys: runs within `length` see the same road.
//
// In 2-D (a tyre with lateral lines) the same profile lies on every line, r(x, y) = r(x): at
// wavelengths of 0.35 m and more, the variation across a tyre's width (0.1–0.3 m) is negligible
// next to that along the road (ISO 8608 itself describes a track by one profile).
#include <cstdint>
#include <memory>
#include <optional>

#include "road/sampled_road.hpp"

namespace rollnoise {

class ConfigTable;

struct Iso8608RoadSpec {
  double gd_n0 = 0.0;     // m^3, > 0
  double waviness = 2.0;  // w
  std::optional<double> sample_spacing;  // m
  double lead_in = 10.0;  // m, >= 0
  std::uint64_t seed = 1;
  double length = 100.0;  // m
  double x_max = 0.0;     // the run's largest x (m)

  static constexpr double n0 = 0.1;        // cycles/m
  static constexpr double n_low = 0.011;   // cycles/m
  static constexpr double n_high = 2.83;   // cycles/m
};

// Reads the keys of a [road] table of type "iso8608" into `spec`.
void read_iso8608_keys(const ConfigTable& road, Iso8608RoadSpec& spec);

// Generates the profile; bad parameters are InputErrors naming the bare key.
std::unique_ptr<SampledProfile> make_iso8608_profile(const Iso8608RoadSpec& spec);

}  // namespace rollnoise
