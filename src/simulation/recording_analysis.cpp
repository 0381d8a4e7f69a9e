#include "simulation/recording_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "audio/wav_file.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "core/regular_file.hpp"
#include "core/uff58.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::vector<ReceiverSignal> read_wav_recordings(const std::string& file, double full_scale_pa, double& full_scale) {
  const WavData wav = read_wav(file);
  full_scale = full_scale_pa > 0.0 ? full_scale_pa : wav.full_scale_pa.value_or(0.0);
  if (!(full_scale > 0.0)) {
    throw InputError(file, "--full-scale",
                     "the WAV does not say which pressure its full scale is: give --full-scale PA (the pressure in Pa of "
                     "sample value 1.0)");
  }
  std::vector<ReceiverSignal> out;
  for (std::size_t c = 0; c < wav.channels.size(); ++c) {
    out.push_back({"ch" + std::to_string(c + 1), wav.channels[c] * full_scale, wav.sample_rate});
  }
  return out;
}

bool is_pressure(const UffAxis& axis) {
  // Specific data types 15 (pressure) and 21 (sound pressure), or a pascal unit label.
  return axis.specific_data_type == 15 || axis.specific_data_type == 21 || axis.units == "Pa" || axis.units == "pa" ||
         axis.units == "PA";
}

std::vector<ReceiverSignal> read_uff_recordings(const std::string& file) {
  std::vector<int> skipped;
  const std::vector<Uff58Record> records = read_uff58(file, &skipped);
  std::vector<ReceiverSignal> out;
  std::string others;
  for (const Uff58Record& r : records) {
    if (!r.is_time_record()) {
      others += (others.empty() ? "" : "; ") + describe_uff58(r);
      continue;
    }
    const std::string where = "dataset " + std::to_string(r.position) + " (line " + std::to_string(r.line) + ")";
    if (!is_pressure(r.numerator_axis)) {
      throw InputError(file, where,
                       "is a time record of " + r.numerator_axis.label + " in " + r.numerator_axis.units +
                           "; analyse computes sound pressure levels and needs pressure in Pa");
    }
    if (!r.even_spacing || !(r.abscissa_increment > 0.0)) {
      throw InputError(file, where, "time records must be evenly sampled");
    }
    if (r.ordinate.size() == 0) throw InputError(file, where, "is complex; a time record must be real");
    double fs = 1.0 / r.abscissa_increment;
    // Headers print the increment with six digits (1.52588e-05 s for 65536 Hz): take the
    // nearest whole rate in Hz when it is within that rounding.
    if (std::abs(fs - std::round(fs)) <= 1e-5 * fs) fs = std::round(fs);
    std::string name = r.response_entity.empty() ? "node" + std::to_string(r.response_node) : r.response_entity;
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on ":" + std::string.
    name += ':';
    name += std::to_string(r.response_direction);
    out.push_back({name, r.ordinate, fs});
  }
  if (out.empty()) {
    throw InputError(file, "",
                     records.empty() ? "holds no dataset 58 (function data)"
                                     : "holds no time record (dataset 58, function type 1); found: " + others);
  }
  return out;
}

RecordingAnalysis analyse(std::vector<ReceiverSignal> signals, const std::string& input, double full_scale,
                          std::chrono::steady_clock::time_point started) {
  RecordingAnalysis analysis;
  analysis.report = sound_report(signals, input);
  analysis.signals = std::move(signals);
  nlohmann::json& summary = analysis.summary;
  summary["input"] = input;
  if (full_scale > 0.0) summary["full_scale_pa"] = full_scale;
  summary["levels"] = analysis.report.levels;
  summary["rollnoise_version"] = ROLLNOISE_VERSION;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return analysis;
}

}  // namespace

std::vector<ReceiverSignal> read_recording(const std::string& file, double full_scale_pa, double& full_scale_used) {
  require_regular_file(file);
  full_scale_used = 0.0;
  const std::string ext = lowercase_extension(file);
  return ext == ".uff" || ext == ".unv" ? read_uff_recordings(file) : read_wav_recordings(file, full_scale_pa, full_scale_used);
}

RecordingAnalysis analyse_recording(const std::string& file, double full_scale_pa) {
  const auto started = std::chrono::steady_clock::now();
  double full_scale = 0.0;
  std::vector<ReceiverSignal> signals = read_recording(file, full_scale_pa, full_scale);
  return analyse(std::move(signals), file, full_scale, started);
}

RecordingAnalysis analyse_signals(std::vector<ReceiverSignal> signals, const std::string& input) {
  const auto started = std::chrono::steady_clock::now();
  for (const ReceiverSignal& s : signals) {
    if (!(s.sample_rate > 0.0) || !std::isfinite(s.sample_rate))
      throw InputError(input, "sample_rate", "must be a positive number of Hz");
    if (!s.pressure.allFinite()) throw InputError(input, s.name, "holds a value that is not a finite number");
  }
  return analyse(std::move(signals), input, 0.0, started);
}

void write_recording_analysis(const fs::path& out, const RecordingAnalysis& analysis) {
  StagedOutputDirectory staged(out);
  write_sound_report(staged.staging(), analysis.signals, analysis.report);
  write_text_file(staged.staging() / "summary.json", analysis.summary.dump(2) + "\n");
  staged.commit();
}

}  // namespace rollnoise
