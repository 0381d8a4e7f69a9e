#include "audio/wav_file.hpp"

#include <sndfile.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* file) const noexcept { sf_close(file); }
};
using SndfileHandle = std::unique_ptr<SNDFILE, SndfileCloser>;

constexpr sf_count_t block_frames = 16384;

}  // namespace

std::string full_scale_comment(double full_scale_pa) {
  return "full scale = " + format_number(full_scale_pa) + " Pa (rollnoise)";
}

std::optional<double> full_scale_from_comment(std::string_view comment) {
  constexpr std::string_view marker = "full scale";
  const std::size_t at = comment.find(marker);
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view rest = comment.substr(at + marker.size());
  const auto skip_blanks = [&rest] {
    while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  };
  skip_blanks();
  if (rest.empty() || rest.front() != '=') return std::nullopt;
  rest.remove_prefix(1);
  skip_blanks();
  double value = 0.0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
  if (ec != std::errc() || !std::isfinite(value) || !(value > 0.0)) return std::nullopt;
  rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
  skip_blanks();
  if (rest.substr(0, 2) != "Pa") return std::nullopt;
  return value;
}

double round_full_scale(double peak_pa, double headroom_db) {
  if (!(peak_pa > 0.0) || !std::isfinite(peak_pa)) return 1.0;
  const double target = peak_pa * std::pow(10.0, std::max(headroom_db, 0.0) / 20.0);
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (const double step : {1.0, 2.0, 5.0, 10.0})
    if (step * decade >= target) return step * decade;
  return 10.0 * decade;
}

WavWriteReport write_wav(const std::filesystem::path& path, const Eigen::VectorXd& pressure_pa,
                         double sample_rate, const WavWriteOptions& options) {
  return write_wav(path, std::vector<Eigen::VectorXd>{pressure_pa}, sample_rate, options);
}

WavWriteReport write_wav(const std::filesystem::path& path,
                         const std::vector<Eigen::VectorXd>& channels_pa, double sample_rate,
                         const WavWriteOptions& options) {
  const std::string name = path.string();
  const auto fail = [&name](const std::string& problem) -> std::runtime_error {
    return std::runtime_error("cannot write WAV file " + name + ": " + problem);
  };
  if (channels_pa.empty()) throw fail("no channels");
  if (channels_pa.size() > 1024) throw fail("more than 1024 channels");
  const Eigen::Index frames = channels_pa.front().size();
  if (frames == 0) throw fail("no samples");
  for (const auto& channel : channels_pa)
    if (channel.size() != frames) throw fail("channels of different lengths");
  if (!(sample_rate >= 1.0) || sample_rate > 1e7 || sample_rate != std::round(sample_rate))
    throw fail("sample rate " + format_number(sample_rate) + " Hz is not a whole positive number");
  const double full_scale = options.full_scale_pa;
  if (!(full_scale > 0.0) || !std::isfinite(full_scale))
    throw fail("full scale " + format_number(full_scale) + " Pa is not a positive number");

  // Check everything before the file is created.
  WavWriteReport report;
  for (const auto& channel : channels_pa) {
    for (Eigen::Index i = 0; i < frames; ++i) {
      if (i % block_frames == 0) options.cancel.throw_if_cancelled();
      const double sample = channel[i] / full_scale;
      if (!std::isfinite(sample) || std::abs(sample) > 3.0e38)
        throw fail("sample " + std::to_string(i) + " is not a finite number");
      const double magnitude = std::abs(sample);
      report.peak = std::max(report.peak, magnitude);
      if (magnitude > 1.0) ++report.samples_over_full_scale;
    }
  }
  if (report.samples_over_full_scale > 0 && options.clipping == WavClipping::refuse)
    throw fail(std::to_string(report.samples_over_full_scale) +
               " samples exceed the full scale of " + format_number(full_scale) + " Pa (peak " +
               format_number(report.peak * full_scale) + " Pa); choose a larger full scale");

  const int channels = static_cast<int>(channels_pa.size());
  SF_INFO info{};
  info.samplerate = static_cast<int>(sample_rate);
  info.channels = channels;
  info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  if (!sf_format_check(&info)) throw fail("libsndfile rejects the format");
  SndfileHandle file(sf_open(name.c_str(), SFM_WRITE, &info));
  if (!file) throw fail(sf_strerror(nullptr));

  try {
    // Strings go in before the audio data, as libsndfile requires for some containers.
    const std::string comment = full_scale_comment(full_scale);
    if (sf_set_string(file.get(), SF_STR_COMMENT, comment.c_str()) != 0)
      throw fail(std::string("cannot set the comment: ") + sf_strerror(file.get()));
    sf_set_string(file.get(), SF_STR_SOFTWARE, "rollnoise");
    if (!options.title.empty()) sf_set_string(file.get(), SF_STR_TITLE, options.title.c_str());

    std::vector<float> buffer(static_cast<std::size_t>(block_frames) * channels_pa.size());
    for (Eigen::Index start = 0; start < frames; start += block_frames) {
      options.cancel.throw_if_cancelled();
      const Eigen::Index count = std::min<Eigen::Index>(block_frames, frames - start);
      for (Eigen::Index i = 0; i < count; ++i)
        for (std::size_t c = 0; c < channels_pa.size(); ++c)
          buffer[static_cast<std::size_t>(i) * channels_pa.size() + c] =
              static_cast<float>(channels_pa[c][start + i] / full_scale);
      if (sf_writef_float(file.get(), buffer.data(), count) != count)
        throw fail(sf_strerror(file.get()));
    }
    SNDFILE* raw = file.release();
    if (sf_close(raw) != 0) throw fail("closing the file failed");
  } catch (...) {
    // No half-written file is left behind.
    file.reset();
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    throw;
  }
  return report;
}

WavData read_wav(const std::filesystem::path& path) {
  const std::string name = path.string();
  SF_INFO info{};
  SndfileHandle file(sf_open(name.c_str(), SFM_READ, &info));
  if (!file)
    throw InputError(name, "",
                     std::string("cannot read it as a sound file (WAV or another format "
                                 "libsndfile reads): ") +
                         sf_strerror(nullptr));
  if (info.channels < 1 || info.channels > 1024)
    throw InputError(name, "", "has " + std::to_string(info.channels) + " channels");
  if (info.samplerate < 1)
    throw InputError(name, "", "sample rate " + std::to_string(info.samplerate) + " Hz");
  // Integer samples scale to [-1, 1) (libsndfile's default normalisation).
  sf_command(file.get(), SFC_SET_NORM_DOUBLE, nullptr, SF_TRUE);

  const auto channels = static_cast<std::size_t>(info.channels);
  std::vector<std::vector<double>> data(channels);
  std::vector<double> buffer(static_cast<std::size_t>(block_frames) * channels);
  std::size_t frame = 0;
  for (;;) {
    const sf_count_t got = sf_readf_double(file.get(), buffer.data(), block_frames);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i, ++frame) {
      for (std::size_t c = 0; c < channels; ++c) {
        const double value = buffer[static_cast<std::size_t>(i) * channels + c];
        if (!std::isfinite(value))
          throw InputError(name,
                           "channel " + std::to_string(c + 1) + ", frame " + std::to_string(frame),
                           "sample is not a finite number");
        data[c].push_back(value);
      }
    }
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR)
    throw InputError(name, "", std::string("reading failed: ") + sf_strerror(file.get()));
  if (frame == 0) throw InputError(name, "", "holds no samples");

  WavData result;
  result.sample_rate = static_cast<double>(info.samplerate);
  if (const char* comment = sf_get_string(file.get(), SF_STR_COMMENT)) result.comment = comment;
  result.full_scale_pa = full_scale_from_comment(result.comment);
  result.channels.reserve(channels);
  for (auto& column : data)
    result.channels.emplace_back(
        Eigen::Map<const Eigen::VectorXd>(column.data(), static_cast<Eigen::Index>(column.size())));
  return result;
}

}  // namespace rollnoise
