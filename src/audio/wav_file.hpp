#pragma once
// Level-calibrated WAV files.
//
// Written files are 32-bit IEEE float WAV: sample = p / full_scale, so a sample value of 1.0
// is `full_scale_pa` pascals. Float rather than 24-bit integer PCM because
// - the level survives the round trip exactly (24-bit mantissa at every level: relative error
//   below 6e-8, i.e. < 1e-6 dB), with no dither noise to add and no quantisation of quiet
//   passages, whatever full scale the caller picks;
// - nothing is lost if a caller accepts samples above full scale (WavClipping::report): the
//   file keeps them, only a player would clip;
// - libsndfile, sox, Audacity, Python (soundfile, scipy) and every DAW read it.
// The full scale is written into the WAV comment (LIST/INFO ICMT) as
// "full scale = 12.3 Pa (rollnoise)", with the number printed so that it reads back exactly.
//
// Reading takes any file libsndfile can read (WAV, FLAC, AIFF, ...; integer or float samples)
// and returns the sample values scaled so that integer full scale is 1.0.
#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/cancellation.hpp"

namespace rollnoise {

enum class WavClipping {
  refuse,  // any |p| > full scale: std::runtime_error, nothing written
  report,  // write anyway (the float file keeps values above 1.0) and count them
};

struct WavWriteOptions {
  double full_scale_pa = 1.0;  // pressure in Pa of sample value 1.0; positive, finite
  WavClipping clipping = WavClipping::refuse;
  std::string title;  // optional SF_STR_TITLE, such as the receiver name
  // Polled every block of samples (an hour of sound is 170 million): when cancelled, write_wav
  // throws Interrupted and removes the file it had started.
  CancellationToken cancel;
};

struct WavWriteReport {
  double peak = 0.0;                        // largest |sample| written (1.0 = full scale)
  std::size_t samples_over_full_scale = 0;  // only non-zero with WavClipping::report
};

// Writes one file with one channel per vector (all of the same length) of pressures in Pa.
// `sample_rate` in Hz must be a positive whole number. Writes to `path` directly (callers
// stage directories for atomic output). Errors: std::runtime_error naming the file;
// Interrupted on options.cancel (no file left either way).
WavWriteReport write_wav(const std::filesystem::path& path,
                         const std::vector<Eigen::VectorXd>& channels_pa, double sample_rate,
                         const WavWriteOptions& options);
WavWriteReport write_wav(const std::filesystem::path& path, const Eigen::VectorXd& pressure_pa,
                         double sample_rate, const WavWriteOptions& options);

struct WavData {
  std::vector<Eigen::VectorXd> channels;  // sample values (integer full scale = 1.0)
  double sample_rate = 0.0;               // Hz
  std::string comment;                    // SF_STR_COMMENT, empty if none
  std::optional<double> full_scale_pa;    // from the comment, when it carries one

  std::size_t frames() const {
    return channels.empty() ? 0 : static_cast<std::size_t>(channels.front().size());
  }
};

// Reads any libsndfile-readable file. Errors (cannot open, not audio, no samples, non-finite
// samples): InputError naming the file.
WavData read_wav(const std::filesystem::path& path);

// "full scale = 12.3 Pa (rollnoise)".
std::string full_scale_comment(double full_scale_pa);
// The full scale in a comment written by full_scale_comment() (or any text containing
// "full scale = <number> Pa"); nullopt when there is none or it is not a positive number.
std::optional<double> full_scale_from_comment(std::string_view comment);

// A round full scale (1, 2 or 5 times a power of ten, in Pa) at least `headroom_db` above
// `peak_pa`, so the written samples stay below 1.0. For peak_pa <= 0 (silence): 1 Pa.
double round_full_scale(double peak_pa, double headroom_db = 1.0);

}  // namespace rollnoise
