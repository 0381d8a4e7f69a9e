// Pass-by auralisation against references computed here independently of pass_by(): emission
// times by fixed-point iteration of t_e = t − r(t_e)/c (pass_by solves them in closed form),
// the analytic Doppler factor 1/(1 − M cos θ), spherical spreading 1/r, and the image-source
// interference |1/r1 + R e^{−ikΔr}/r2|. Checked: the whole waveform of a tone (the
// interpolation error), the received frequency approaching and receding, the level along the
// pass, the ground dip at the closest approach, the low-frequency normalisation and the time
// alignment, and argument checking.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "audio/pass_by.hpp"
#include "radiation/impedance_plane_green.hpp"

namespace rollnoise {
namespace {

using std::numbers::pi;

constexpr double fs = 48000.0;
// 0.1 s sources: every multiple of 10 Hz is a whole number of cycles, so the looped source is
// exactly the endless tone and the references need no loop of their own.
constexpr Eigen::Index source_length = 4800;

Eigen::VectorXd tone(double frequency, double amplitude, double phase = 0.0) {
  Eigen::VectorXd x(source_length);
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x[i] = amplitude * std::sin(2.0 * pi * frequency * static_cast<double>(i) / fs + phase);
  return x;
}

double db(double ratio) { return 20.0 * std::log10(ratio); }

// The two path lengths abeam and the normalisation 1/(1/r1_0 + R/r2_0).
struct Abeam {
  double r1, r2, norm;
};
Abeam abeam(const PassBySettings& s) {
  const double d = s.receiver_distance;
  const double above = s.receiver_height - s.source_height;
  const double below = s.receiver_height + s.source_height;
  const double r1 = std::sqrt(d * d + above * above);
  const double r2 = std::sqrt(d * d + below * below);
  return {r1, r2, 1.0 / (1.0 / r1 + s.ground_reflection / r2)};
}

// The emission behind what the receiver hears at time t along one path (direct or image):
// emission time, distance then, and cos θ between the velocity (+x) and the direction from
// the source to the receiver. Fixed-point iteration of t_e = t − r(t_e)/c, a contraction by
// M |cos θ| <= 0.3 per step, run to convergence.
struct Emission {
  double time, distance, cos_theta;
};
Emission emission(double t, const PassBySettings& s, bool image) {
  const double dz = image ? s.receiver_height + s.source_height
                          : s.receiver_height - s.source_height;
  const double lateral_sq = s.receiver_distance * s.receiver_distance + dz * dz;
  const auto distance = [&](double te) {
    const double x = s.speed * (te - 0.5 * s.duration);
    return std::sqrt(x * x + lateral_sq);
  };
  double te = t;
  for (int i = 0; i < 200; ++i) {
    const double next = t - distance(te) / s.sound_speed;
    const bool converged = std::abs(next - te) < 1e-15;
    te = next;
    if (converged) break;
  }
  const double x = s.speed * (te - 0.5 * s.duration);
  const double r = distance(te);
  return {te, r, -x / r};
}

// The exact received pressure at time t for a source tone a·sin(2π f t + phase): each path
// carries the tone as emitted at t_e, with the header's time alignment (the source is read at
// t_e + r1_0/c), divided by the distance at emission; the tone first taken through the
// header's equaliser E(f) = (1/r1_0 + R/r2_0)/(1/r1_0 + R e^{−ikΔr}/r2_0) (amplitude |E|, phase
// arg E), which divides out the interference at the closest approach.
double tone_pass_by(double t, double f, double a, double phase, const PassBySettings& s) {
  const Abeam ab = abeam(s);
  const double shift = ab.r1 / s.sound_speed;
  const double k = 2.0 * pi * f / s.sound_speed;
  const std::complex<double> e =
      (1.0 / ab.r1 + s.ground_reflection / ab.r2) /
      (1.0 / ab.r1 + s.ground_reflection * std::polar(1.0, -k * (ab.r2 - ab.r1)) / ab.r2);
  const double amplitude = a * std::abs(e), start = phase + std::arg(e);
  const Emission direct = emission(t, s, false);
  double p = std::sin(2.0 * pi * f * (direct.time + shift) + start) / direct.distance;
  if (s.ground_reflection > 0.0) {
    const Emission image = emission(t, s, true);
    p += s.ground_reflection * std::sin(2.0 * pi * f * (image.time + shift) + start) / image.distance;
  }
  return ab.norm * amplitude * p;
}

// The whole cycles of y between its first and last rising zero crossings inside [t0, t1]
// (crossing times by linear interpolation): their mean frequency, their amplitude (√2 × RMS)
// and their middle time.
struct Cycles {
  double frequency, amplitude, middle;
};
Cycles whole_cycles(const Eigen::VectorXd& y, double t0, double t1) {
  const auto i0 = static_cast<Eigen::Index>(std::ceil(t0 * fs));
  const auto i1 = static_cast<Eigen::Index>(std::floor(t1 * fs));
  double first = -1.0, last = -1.0;
  int crossings = 0;
  for (Eigen::Index i = i0 + 1; i <= i1; ++i) {
    if (y[i - 1] < 0.0 && y[i] >= 0.0) {
      const double t = static_cast<double>(i - 1) + y[i - 1] / (y[i - 1] - y[i]);
      if (first < 0.0) first = t;
      last = t;
      ++crossings;
    }
  }
  // y² over the whole cycles by the trapezoidal rule, with the partial first and last
  // intervals (y is ~0 at the crossings, so their ends contribute ~nothing).
  const auto a = static_cast<Eigen::Index>(std::ceil(first));
  const auto b = static_cast<Eigen::Index>(std::floor(last));
  double energy = 0.5 * y[a] * y[a] * (static_cast<double>(a) - first) +
                  0.5 * y[b] * y[b] * (last - static_cast<double>(b));
  for (Eigen::Index i = a; i < b; ++i) energy += 0.5 * (y[i] * y[i] + y[i + 1] * y[i + 1]);
  return {(crossings - 1) * fs / (last - first), std::sqrt(2.0 * energy / (last - first)),
          0.5 * (first + last) / fs};
}

// Amplitude of the f component over samples [i0, i0 + n) by projection on sin and cos (exact
// for a steady tone with a whole number of cycles in the window).
double tone_amplitude(const Eigen::VectorXd& y, double f, Eigen::Index i0, Eigen::Index n) {
  double s = 0.0, c = 0.0;
  for (Eigen::Index i = i0; i < i0 + n; ++i) {
    const double phase = 2.0 * pi * f * static_cast<double>(i) / fs;
    s += y[i] * std::sin(phase);
    c += y[i] * std::cos(phase);
  }
  return 2.0 * std::hypot(s, c) / static_cast<double>(n);
}

// ------------------------------------------------------------------------------------------

TEST(PassBy, ToneMatchesTheExactRetardedField) {
  // The whole output of a looped tone against the exact field, sample by sample. The only
  // approximation in pass_by is the interpolation of the source between samples, so this
  // measures it: 6-point Lagrange errs by at most 5e-3 (2π f/fs)^6 relative per path (2.4e-8
  // at 1 kHz, 1.7e-5 at 3 kHz, 1.0e-3 at 6 kHz), and the paths' gains add up to at most 1
  // (abeam). Tolerances: twice those bounds (plus 1e-9 for rounding in the references).
  struct Case {
    double f, speed, bound;
  };
  for (const Case& c : {Case{1000.0, 30.0, 2.4e-8}, Case{3000.0, 30.0, 1.75e-5},
                        Case{3000.0, 0.29 * 343.2, 1.75e-5}, Case{6000.0, 30.0, 1.04e-3}}) {
    PassBySettings s;
    s.speed = c.speed;
    s.duration = 1.0;
    const double amplitude = 2.0;
    const Eigen::VectorXd y = pass_by(tone(c.f, amplitude, 0.7), fs, s);
    ASSERT_EQ(y.size(), 48000);
    double error = 0.0;
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      const double t = static_cast<double>(i) / fs;
      error = std::max(error, std::abs(y[i] - tone_pass_by(t, c.f, amplitude, 0.7, s)));
    }
    error /= amplitude;
    std::printf("  %4.0f Hz at %5.1f m/s: max error %.2e of the source amplitude (%.1f dB)\n",
                c.f, c.speed, error, db(error));
    EXPECT_LT(error, 2.0 * c.bound + 1e-9) << c.f << " Hz, " << c.speed << " m/s";
  }
}

TEST(PassBy, DopplerShiftApproachingAndReceding) {
  // 1 kHz at 30 m/s (M = 0.087) without the ground: the received frequency over 50 ms windows
  // centred 1.9 s before and after the closest approach (the tyre ~57 m away) against
  // f0 / (1 − M cos θ) at the emission time of the window's middle. The zero-crossing
  // frequency is the window's mean; the frequency changes by < 0.1 Hz per 0.1 s there, almost
  // linearly, so the mean is the middle's value to ~1e-5 Hz. Linear interpolation of the
  // crossings of a sine errs by < (ωh)³/24 rad ≈ 1.2e-4 rad (1.8e-8 s) per crossing, so over
  // 50 ms the frequency is resolved to ~1e-3 Hz. Tolerance 0.01 Hz: the ~90 Hz shift to 1e-4,
  // and tight enough to fail if θ were taken where the tyre is when heard (0.14 Hz off).
  // (The shift is +95 Hz approaching, −80 Hz receding.)
  PassBySettings s;
  s.speed = 30.0;
  s.ground_reflection = 0.0;
  const double f0 = 1000.0, mach = s.speed / s.sound_speed;
  const Eigen::VectorXd y = pass_by(tone(f0, 1.0), fs, s);
  for (const double centre : {0.6, 4.4}) {
    const Cycles cycles = whole_cycles(y, centre - 0.025, centre + 0.025);
    const Emission e = emission(cycles.middle, s, false);
    const double expected = f0 / (1.0 - mach * e.cos_theta);
    std::printf("  t = %.2f s (cos θ = %+.4f): %.4f Hz, Doppler formula %.4f Hz, error %.1e Hz\n",
                cycles.middle, e.cos_theta, cycles.frequency, expected,
                cycles.frequency - expected);
    EXPECT_NEAR(cycles.frequency, expected, 0.01) << "t = " << centre;
    EXPECT_GT(std::abs(expected - f0), 70.0) << "the test must see a large shift";
  }
}

TEST(PassBy, LevelFollowsTheDistanceAtEmission) {
  // Without the ground the amplitude is A r1_0 / r(t_e). Measured as √2 × RMS over the whole
  // cycles in 20 ms windows: the amplitude changes almost linearly over a window, which moves
  // the RMS by < 1e-5 dB; near the closest approach r is quadratic in time, +0.002 dB at most.
  // Tolerance 0.01 dB; using the distance when heard instead of when emitted is 0.7 dB off at
  // t = 0.5 s and 1.5 s.
  PassBySettings s;
  s.speed = 30.0;
  s.ground_reflection = 0.0;
  const double amplitude = 1.5;
  const Eigen::VectorXd y = pass_by(tone(1000.0, amplitude), fs, s);
  const double closest = 0.5 * s.duration + abeam(s).r1 / s.sound_speed;
  for (const double t : {0.5, 1.5, closest, 3.5, 4.5}) {
    const Cycles cycles = whole_cycles(y, t - 0.01, t + 0.01);
    const Emission e = emission(cycles.middle, s, false);
    const double expected = amplitude * abeam(s).r1 / e.distance;
    const double error_db = db(cycles.amplitude / expected);
    std::printf("  t = %.3f s, r = %6.2f m: level %+7.3f dB re abeam, error %+.1e dB\n",
                cycles.middle, e.distance, db(cycles.amplitude / amplitude), error_db);
    EXPECT_LT(std::abs(error_db), 0.01) << "t = " << t;
  }
}

TEST(PassBy, GroundReflectionInterferenceComesBackAtTheClosestApproachAndMovesAway) {
  // Source 1 m up, receiver 1.2 m up at 7.5 m: Δr = r2 − r1 = 0.313 m, first dip at
  // c/(2Δr) = 548 Hz. The input is what the stationary microphone hears, its own dip included,
  // so at the closest approach the pass-by gives it back (0 dB), in the dip as elsewhere; 5 m
  // further on, the two paths' interference has moved: the level relative to the closest
  // approach is the image-source formula |1/r1 + R e^{−iφ}/r2| there over the same abeam, φ the
  // phase between the paths' emission times (kΔr, stretched by the motion: at 0.25 m/s and
  // 5 m, 2e-3 rad, which moves the 800 Hz level by 0.018 dB). At 0.25 m/s the geometry hardly
  // changes over the 0.1 s window (at 5 m, Δr by 2e-4 m). Tolerance 0.005 dB away from the dip;
  // 0.02 dB at 550 Hz, where the dip's sharpness magnifies what is left.
  struct Case {
    double f, reflection, tolerance_db;
  };
  for (const Case& c : {Case{100.0, 1.0, 0.005}, Case{550.0, 1.0, 0.02}, Case{800.0, 1.0, 0.005},
                        Case{1100.0, 1.0, 0.005}, Case{550.0, 0.5, 0.005}}) {
    PassBySettings s;
    s.speed = 0.25;
    s.duration = 45.0;
    s.source_height = 1.0;
    s.receiver_height = 1.2;
    s.ground_reflection = c.reflection;
    const double amplitude = 1.0;
    const Eigen::VectorXd y = pass_by(tone(c.f, amplitude, 0.3), fs, s);
    // The two paths at time t, each the tone as emitted then over the distance then (the
    // emission times carry the path difference, stretched by the motion).
    const auto paths = [&](double t) {
      const Emission direct = emission(t, s, false), image = emission(t, s, true);
      return std::abs(std::polar(1.0 / direct.distance, 2.0 * pi * c.f * direct.time) +
                      c.reflection * std::polar(1.0 / image.distance, 2.0 * pi * c.f * image.time));
    };
    const double closest = 0.5 * s.duration + abeam(s).r1 / s.sound_speed;
    for (const double x : {0.0, 5.0}) {
      const double r1 = std::hypot(std::hypot(s.receiver_distance, x), s.receiver_height - s.source_height);
      const double heard = 0.5 * s.duration + x / s.speed + r1 / s.sound_speed;
      const double measured = whole_cycles(y, heard - 0.05, heard + 0.05).amplitude;
      const double expected = amplitude * paths(heard) / paths(closest);
      const double error_db = db(measured / expected);
      std::printf("  %4.0f Hz, R = %.1f, x_e = %.0f m: level %+8.3f dB (image-source formula re abeam %+8.3f dB), "
                  "error %+.1e dB\n",
                  c.f, c.reflection, x, db(measured / amplitude), db(expected / amplitude), error_db);
      EXPECT_LT(std::abs(error_db), c.tolerance_db) << c.f << " Hz, R = " << c.reflection << ", x_e = " << x;
    }
  }
}

// Q = 1 + C/E of the impedance plane at horizontal distance rho, for the settings' heights; the
// line integral to 1e-10 of the image's field, as the pass-by of a run takes it.
PassBySettings::ReflectionFactor exact_factor(const PassBySettings& s, std::complex<double> beta) {
  return [height = s.receiver_height + s.source_height, c = s.sound_speed, beta](double hz, double rho) {
    const double k = 2.0 * pi * hz / c;
    const double r2 = std::hypot(rho, height);
    const std::complex<double> image = std::polar(1.0 / (4.0 * pi * r2), -k * r2);
    return 1.0 + impedance_plane_correction(k, rho, height, beta, 1e-10) / image;
  };
}

TEST(PassBy, AbsorbingRoadAtTheClosestApproachGivesBackTheStationarySignal) {
  // Over an impedance plane the stationary microphone's signal already holds the road's ground
  // effect: heard abeam (1 m/s, as above) the pass-by must give it back, 0 dB, and not apply the
  // ground effect again. That second application is printed beside: |G|/(1/r1 + 1/r2) of the
  // exact field (impedance_plane_green), the level the pass-by had before the interference
  // abeam was divided out. The ISO geometry (source 2 cm, 7.5 m, 1.2 m) and porous asphalt's
  // sizes of admittance; 0.005 dB, as above.
  struct Case {
    std::complex<double> beta;
    double f;
  };
  for (const Case& c : {Case{{0.3, -0.4}, 250.0}, Case{{0.02, 0.06}, 1000.0}, Case{{0.8, 0.1}, 2000.0}}) {
    PassBySettings s;
    s.speed = 1.0;
    s.duration = 2.0;
    s.ground_reflection_factor = exact_factor(s, c.beta);
    const Eigen::VectorXd y = pass_by(tone(c.f, 1.0, 0.3), fs, s);
    const Abeam ab = abeam(s);
    const double k = 2.0 * pi * c.f / s.sound_speed;
    const double twice =
        4.0 * pi * std::abs(impedance_plane_green(k, s.receiver_distance, s.receiver_height, s.source_height, c.beta)) /
        (1.0 / ab.r1 + 1.0 / ab.r2);
    const auto centre = static_cast<Eigen::Index>(std::llround((0.5 * s.duration + ab.r1 / s.sound_speed) * fs));
    const double measured = tone_amplitude(y, c.f, centre - 2400, 4800);
    std::printf("  %4.0f Hz, β (%.2f, %.2f): level %+8.3f dB re the stationary signal (ground effect applied twice: %+8.3f dB)\n",
                c.f, c.beta.real(), c.beta.imag(), db(measured), db(twice));
    EXPECT_LT(std::abs(db(measured)), 0.005) << c.f << " Hz, β " << c.beta;
  }
}

TEST(PassBy, AbsorbingRoadAlongThePassIsTheExactFieldAtEachDistance) {
  // As the tyre moves away the image path's factor follows its position at emission: a tone's
  // level, measured over whole cycles 20 ms long around the moment the sound emitted at x_e
  // arrives, relative to the stationary signal, must be the exact field of a point source there
  // (impedance_plane_green, independent of the filter) at the frequency received along the
  // image path (the Doppler factor 1/(1 − M cos θ₂)), over the exact field abeam. At 2 m/s over 30 s, and at 25 m/s
  // (90 km/h) over 2.6 s, the tyre emits from up to 30 m either side of the closest approach:
  // at x_e = 0 to 28 m the incidence is 9.2° to 2.4° above grazing. Tolerance 0.02 dB: a road's
  // level is quoted to 0.1 dB, and the filter's series holds Q to 1e-4 (measured 2026-11-28:
  // within 0.002 dB at 2 m/s, 0.01 dB at 25 m/s, where the geometry moves within the window).
  // Printed beside: the closest approach's factor kept for the whole pass-by,
  // as the pass-by did before (2.2–9.8 dB off at 28 m), and at 25 m/s the exact field at the
  // emitted frequency (what leaving out the Doppler factor of Q would give).
  struct Case {
    std::complex<double> beta;
    double f, speed, duration;
  };
  for (const Case& c : {Case{{0.3, -0.4}, 250.0, 2.0, 30.0}, Case{{0.02, 0.06}, 1000.0, 2.0, 30.0},
                        Case{{0.8, 0.1}, 2000.0, 2.0, 30.0}, Case{{0.3, -0.4}, 1000.0, 25.0, 2.6}}) {
    PassBySettings s;
    s.speed = c.speed;
    s.duration = c.duration;
    s.ground_reflection_factor = exact_factor(s, c.beta);
    const Eigen::VectorXd y = pass_by(tone(c.f, 1.0, 0.3), fs, s);
    const Abeam ab = abeam(s);
    const std::complex<double> q_closest = exact_factor(s, c.beta)(c.f, s.receiver_distance);
    const double image_height = s.receiver_height + s.source_height;
    for (const double x : {-28.0, -12.1, 0.0, 5.3, 12.1, 20.5, 28.0}) {
      const double rho = std::hypot(s.receiver_distance, x);
      const double r1 = std::hypot(rho, s.receiver_height - s.source_height);
      const double r2 = std::hypot(rho, image_height);
      const double heard = 0.5 * s.duration + x / s.speed + r1 / s.sound_speed;
      const double mach = s.speed / s.sound_speed;
      const double received = c.f / (1.0 - mach * (-x / r2));
      const double expected =
          std::abs(impedance_plane_green(2.0 * pi * received / s.sound_speed, rho, s.receiver_height, s.source_height, c.beta)) /
          std::abs(impedance_plane_green(2.0 * pi * c.f / s.sound_speed, s.receiver_distance, s.receiver_height,
                                         s.source_height, c.beta));
      const double k = 2.0 * pi * c.f / s.sound_speed;
      const std::complex<double> abeam_paths = std::polar(1.0 / ab.r1, -k * ab.r1) + q_closest * std::polar(1.0 / ab.r2, -k * ab.r2);
      const double emitted = std::abs(impedance_plane_green(k, rho, s.receiver_height, s.source_height, c.beta)) /
                             std::abs(impedance_plane_green(k, s.receiver_distance, s.receiver_height, s.source_height, c.beta));
      const double frozen =
          std::abs(std::polar(1.0 / r1, -k * r1) + q_closest * std::polar(1.0 / r2, -k * r2)) / std::abs(abeam_paths);
      const Cycles cycles = whole_cycles(y, heard - 0.01, heard + 0.01);
      std::printf("  %4.0f Hz, %4.1f m/s, x_e %+5.1f m: level %+8.3f dB, exact field %+8.3f dB (closest approach's "
                  "factor %+8.3f, emitted frequency %+8.3f)\n",
                  c.f, c.speed, x, db(cycles.amplitude), db(expected), db(frozen), db(emitted));
      EXPECT_LT(std::abs(db(cycles.amplitude / expected)), 0.02) << c.f << " Hz, " << c.speed << " m/s at x_e " << x << " m";
    }
  }
}

TEST(PassBy, LowFrequencyLevelAbeamIsTheSourceLevel) {
  // Default SPB geometry (source 0.02 m up): Δr = 6.3 mm, so at 50 and 100 Hz the two paths
  // are within 0.012 rad and the level abeam is the source's to 1.4e-4 dB, whatever R; the
  // 1/r change across the 0.1 s window at 1 m/s takes off another 6e-5 dB. Tolerance 0.002 dB
  // (leaving out the image's weight in q would be 6 dB off for R = 1).
  for (const double reflection : {1.0, 0.3, 0.0}) {
    for (const double f : {50.0, 100.0}) {
      PassBySettings s;
      s.speed = 1.0;
      s.duration = 2.0;
      s.ground_reflection = reflection;
      const double amplitude = 0.8;
      const Eigen::VectorXd y = pass_by(tone(f, amplitude, 1.1), fs, s);
      const auto centre = static_cast<Eigen::Index>(
          std::llround((0.5 * s.duration + abeam(s).r1 / s.sound_speed) * fs));
      const double error_db = db(tone_amplitude(y, f, centre - 2400, 4800) / amplitude);
      std::printf("  %3.0f Hz, R = %.1f: level abeam re the source %+.1e dB\n", f, reflection,
                  error_db);
      EXPECT_LT(std::abs(error_db), 0.002) << f << " Hz, R = " << reflection;
    }
  }
  // Time alignment: abeam and without the ground, the source comes back sample for sample.
  // Within ±1 ms at 1 m/s the distance changes by 7e-8 m: a delay of 2e-10 s, 1.2e-6 of the
  // amplitude at 1 kHz; the interpolation adds 2.4e-8. Tolerance 5e-6 (a one-sample shift
  // would be 0.13, and ±5 ms would already see the delay change, 3e-5).
  PassBySettings s;
  s.speed = 1.0;
  s.duration = 2.0;
  s.ground_reflection = 0.0;
  const Eigen::VectorXd x = tone(1000.0, 1.0, 0.2);
  const Eigen::VectorXd y = pass_by(x, fs, s);
  const auto centre =
      static_cast<Eigen::Index>(std::llround((1.0 + abeam(s).r1 / s.sound_speed) * fs));
  double error = 0.0;
  for (Eigen::Index i = centre - 48; i <= centre + 48; ++i)
    error = std::max(error, std::abs(y[i] - x[i % x.size()]));
  std::printf("  abeam, R = 0: max deviation from the source %.1e\n", error);
  EXPECT_LT(error, 5e-6);
}

TEST(PassBy, ShortSourcesLoopAndTheResultIsDeterministic) {
  // A constant source of 1, 2 or 3 samples (the periodic index wraps several times within
  // the interpolator's 6 points): the output is exactly the spreading of the two paths,
  // norm · (1/r1(t_e1) + R/r2(t_e2)).
  PassBySettings s;
  s.speed = 25.0;
  s.duration = 0.5;
  s.ground_reflection = 0.8;
  const Abeam ab = abeam(s);
  for (const Eigen::Index n : {Eigen::Index{1}, Eigen::Index{2}, Eigen::Index{3}}) {
    const Eigen::VectorXd y = pass_by(Eigen::VectorXd::Constant(n, 0.25), fs, s);
    ASSERT_EQ(y.size(), 24000);
    for (const Eigen::Index i : {Eigen::Index{0}, Eigen::Index{9000}, Eigen::Index{12345},
                                 Eigen::Index{23999}}) {
      const double t = static_cast<double>(i) / fs;
      const double expected = 0.25 * ab.norm *
                              (1.0 / emission(t, s, false).distance +
                               s.ground_reflection / emission(t, s, true).distance);
      EXPECT_NEAR(y[i], expected, 1e-12) << "n = " << n << ", i = " << i;
    }
  }
  EXPECT_EQ(pass_by(tone(440.0, 1.0), fs, s), pass_by(tone(440.0, 1.0), fs, s));
  s.duration = 0.1 / fs * 7.0;  // 0.7 samples: rounds to one
  EXPECT_EQ(pass_by(tone(440.0, 1.0), fs, s).size(), 1);
}

TEST(PassBy, BadArgumentsThrowNamingTheParameter) {
  const Eigen::VectorXd x = tone(440.0, 1.0);
  const auto expect_rejected = [](const Eigen::VectorXd& source, double rate,
                                  const PassBySettings& settings, const std::string& name) {
    try {
      pass_by(source, rate, settings);
      ADD_FAILURE() << "no exception for " << name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PassBySettings good;
  good.speed = 20.0;
  good.duration = 0.01;
  EXPECT_EQ(pass_by(x, fs, good).size(), 480);

  expect_rejected(Eigen::VectorXd(), fs, good, "source");
  Eigen::VectorXd bad = x;
  bad[17] = nan;
  expect_rejected(bad, fs, good, "source");
  for (const double rate : {0.0, -48000.0, nan, inf}) expect_rejected(x, rate, good, "sample_rate");

  const auto with = [&](auto change) {
    PassBySettings s = good;
    change(s);
    return s;
  };
  for (const double v : {0.0, -5.0, nan, inf, 0.3 * 343.2, 200.0})
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.speed = v; }), "speed");
  for (const double v : {0.0, -7.5, nan, inf})
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.receiver_distance = v; }),
                    "receiver_distance");
  for (const double v : {-0.1, nan, inf}) {
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.receiver_height = v; }),
                    "receiver_height");
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.source_height = v; }),
                    "source_height");
  }
  for (const double v : {0.0, -1.0, nan, inf, 1e-6, 1e9})
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.duration = v; }), "duration");
  for (const double v : {0.0, -343.2, nan, inf})
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.sound_speed = v; }), "sound_speed");
  for (const double v : {-0.1, 1.1, nan})
    expect_rejected(x, fs, with([&](PassBySettings& s) { s.ground_reflection = v; }),
                    "ground_reflection");
  // The limits themselves are accepted.
  EXPECT_NO_THROW(pass_by(x, fs, with([](PassBySettings& s) {
                            s.ground_reflection = 0.0;
                            s.source_height = 0.0;
                            s.receiver_height = 0.0;
                            s.speed = 0.2999 * s.sound_speed;
                          })));
  EXPECT_NO_THROW(pass_by(x, fs, with([](PassBySettings& s) { s.ground_reflection = 1.0; })));
}

// A cancelled token (the test's own flag, set before the call: no timing) stops the pass-by
// with Interrupted; one not cancelled changes nothing.
TEST(PassBy, StopsWhenCancelled) {
  std::atomic<int> flag{0};
  PassBySettings s;
  s.speed = 30.0;
  s.duration = 2.0;
  const Eigen::VectorXd source = tone(1000.0, 1.0, 0.7);
  const Eigen::VectorXd expected = pass_by(source, fs, s);
  s.cancel = CancellationToken(flag);
  EXPECT_EQ(pass_by(source, fs, s), expected);
  flag = SIGINT;
  EXPECT_THROW(pass_by(source, fs, s), Interrupted);
}

}  // namespace
}  // namespace rollnoise
