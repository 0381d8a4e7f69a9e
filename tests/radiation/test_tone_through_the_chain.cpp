// Issue 10 §3: the band up to 5 kHz. A tone injected at 4 kHz into the tread's velocity must come
// out in the 4 kHz third-octave band at the right level, through every step that `simulate`
// takes after the response stage (tools/rollnoise/tyre_sound.cpp): the radiation stage (its band
// limits, the anchors and the interpolation between them, the transform and its padding), the
// resampling to the audio rate, the looping to 5 s and the IEC 61260-1 band filters. The level
// expected is the same equivalent-source model's, so the check is of the chain, not of the mesh
// (the mesh's own accuracy at 5 kHz is checked in test_tyre_radiation.cpp):
//  - a tone on an anchor (4 kHz, at the 30 km/h rate): the model solved directly at the tone;
//  - a tone between anchors (4050 Hz, at the 80 km/h rate): the anchors' transfers interpolated
//    as the stage does (TransferTable). How far that interpolation is from a direct solve at
//    4050 Hz is recorded, not asserted: on this coarse mesh −3.2 … +0.8 dB (measured), and up
//    to 2 dB for single tones on the run's mesh (docs/validation.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "acoustics/sound_levels.hpp"
#include "audio/resampler.hpp"
#include "audio/seamless_loop.hpp"
#include "radiation/transfer_table.hpp"
#include "radiation/tyre_radiation.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// The velocity sample rates of the 205/55 R16 (512 cells around, dx = 3.878 mm) with the
// sub-steps that the 5 kHz band needs: 80 km/h with p = 2, 30 km/h with p = 6.
struct RateCase {
  const char* name;
  double sample_rate;
  double tone_hz;
  bool on_anchor;
};

TEST(ToneThroughTheChain, FourKilohertzToneLandsInThe4kHzBandAtItsLevel) {
  const double dx = 2.0 * kPi * 0.316 / 512.0;
  for (const RateCase rate : {RateCase{"80 km/h, p = 2, 4050 Hz", 2.0 * 22.222 / dx, 4050.0, false},
                              RateCase{"30 km/h, p = 6, 4000 Hz", 6.0 * 8.3333 / dx, 4000.0, true}}) {
    SCOPED_TRACE(rate.name);
    const double fs = rate.sample_rate;
    // A coarse mesh keeps the 59 anchor solves fast; the reference below uses the same mesh.
    TyreRadiationSettings settings;
    settings.mesh.around = 64;
    settings.mesh.across = 6;
    settings.mesh.sidewall_rings = 8;
    settings.max_frequency_hz = 5623.4;  // the upper edge of the 5 kHz band, the run's default
    settings.anchor_spacing_hz = 100.0;
    settings.points_per_wavelength = 0.0;  // this mesh for every anchor (the chain, not the mesh, is under test)
    Eigen::Matrix3Xd receivers(3, 3);
    receivers << 0.2, -0.2, 0.0,  // cpx_front, cpx_rear, spb (tyre width 0.18 m)
        0.29, 0.29, 7.5,          //
        0.1, 0.1, 1.2;
    const TyreRadiation radiation(settings, receivers);
    const TyreSurfaceMesh& mesh = radiation.mesh();
    ASSERT_GE(radiation.anchors(fs).back(), 5623.0);

    // 0.2 s of a tone with a whole number of cycles (so the loop to 5 s is seamless): the
    // tread's velocity that of a monopole 1 cm inside the tread near the contact, the sidewalls
    // at rest (as in a run).
    const auto samples = static_cast<Eigen::Index>(std::llround(0.2 * fs));
    const double duration = static_cast<double>(samples) / fs;
    const double f0 = std::round(rate.tone_hz * duration) / duration;
    const double omega = 2 * kPi * f0;
    const double k = omega / settings.medium.sound_speed;
    const Eigen::Vector3d source(0.03, 0.0, 0.012);
    const Complex q(2e-5, 1e-5);
    Eigen::VectorXcd amplitude(mesh.tread_points);
    for (Eigen::Index m = 0; m < amplitude.size(); ++m)
      amplitude(m) = -q * mesh.normals.col(m).cast<Complex>().dot(helmholtz_green_gradient(mesh.points.col(m), source, k, true));
    Eigen::MatrixXd velocity(samples, mesh.tread_points);
    for (Eigen::Index n = 0; n < samples; ++n)
      velocity.row(n) = (amplitude * std::polar(1.0, omega * static_cast<double>(n) / fs)).real().transpose();

    const RadiatedSound sound = radiation.radiate(velocity, fs);
    // The references: the same model solved at f0 itself, and interpolated from the anchors
    // around f0 as the stage does.
    const EquivalentSources model = make_tyre_model(mesh, settings.medium, f0 > kCombinedSourcesAboveHz);
    const Eigen::VectorXcd direct = model.transfer(omega, receivers, settings.regularisation).leftCols(mesh.tread_points) * amplitude;
    const double below = 100.0 * std::floor(f0 / 100.0);
    const TransferTable table(model, receivers, {below, below + 100.0},
                              Eigen::Vector3d(0.0, 0.0, settings.mesh.radius + settings.mesh.clearance),
                              settings.medium.sound_speed, settings.regularisation);
    const Eigen::VectorXcd interpolated = table.at(f0).leftCols(mesh.tread_points) * amplitude;
    const Eigen::VectorXcd& exact = rate.on_anchor ? direct : interpolated;

    // As tyre_sound.cpp: the bands up to the one the radiated band reaches, at 48 kHz, looped to 5 s.
    const double highest_band = sound.highest_hz / std::pow(2.0, 1.0 / 6.0);
    for (Eigen::Index r = 0; r < receivers.cols(); ++r) {
      const Eigen::VectorXd audio = loop_to_duration(resample(sound.pressure.col(r), fs, 48000.0), 48000.0, 5.0);
      BandSpectrumOptions options;
      options.f_high = std::min({10000.0, 48000.0 / 4.5, highest_band});
      options.settle_time = std::min(0.5, 0.1 * static_cast<double>(audio.size()) / 48000.0);
      const BandSpectrum spectrum = band_spectrum(std::span<const double>(audio.data(), static_cast<std::size_t>(audio.size())), 48000.0, options);
      ASSERT_EQ(spectrum.labels.back(), "5000") << "the 5 kHz band is reported";
      std::size_t at = 0;
      while (at < spectrum.labels.size() && spectrum.labels[at] != "4000") ++at;
      ASSERT_LT(at, spectrum.labels.size());
      const double expected_db = 20.0 * std::log10(std::abs(exact(r)) / std::sqrt(2.0) / 20e-6);
      const double error_db = spectrum.lp_db[at] - expected_db;
      // Measured: within 0.02 dB between anchors, 0.14 dB on the anchor (the band filter's
      // response at f0, the resampler's passband, the record's ends): 0.2 dB is 2.3 % in pressure.
      EXPECT_NEAR(error_db, 0.0, 0.2) << "receiver " << r;
      const double interpolation_db = 20.0 * std::log10(std::abs(interpolated(r)) / std::abs(direct(r)));
      // Nothing leaks into or is misplaced to other bands: the neighbours are the band filters'
      // skirts (order 3: 15–20 dB one band away), the rest far below.
      EXPECT_LE(spectrum.lp_db[at - 1], spectrum.lp_db[at] - 10.0) << "3.15 kHz band, receiver " << r;
      EXPECT_LE(spectrum.lp_db[at + 1], spectrum.lp_db[at] - 10.0) << "5 kHz band, receiver " << r;
      for (std::size_t b = 0; b + 2 <= at; ++b) EXPECT_LE(spectrum.lp_db[b], spectrum.lp_db[at] - 30.0) << spectrum.labels[b];
      const std::string key = std::string(rate.on_anchor ? "on_anchor" : "between_anchors") + "_r" + std::to_string(r);
      RecordProperty(key + "_error_dB", std::to_string(error_db));
      RecordProperty(key + "_interpolation_vs_direct_dB", std::to_string(interpolation_db));
      std::printf("%s, receiver %ld: 4 kHz band %.3f dB, expected %.3f dB, error %+.3f dB (interpolated - direct "
                  "%+.2f dB); 3.15 kHz band %.1f dB, 5 kHz band %.1f dB\n",
                  rate.name, static_cast<long>(r), spectrum.lp_db[at], expected_db, error_db, interpolation_db,
                  spectrum.lp_db[at - 1], spectrum.lp_db[at + 1]);
    }
  }
}

}  // namespace
}  // namespace rollnoise
