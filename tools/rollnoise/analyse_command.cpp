#include "analyse_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "audio/wav_file.hpp"
#include "core/error.hpp"
#include "core/output_directory.hpp"
#include "core/uff58.hpp"
#include "simulation/sound_report.hpp"
#include "number_checks.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

namespace {

struct Recording {
  std::string receiver;
  Eigen::VectorXd pressure;  // Pa
  double sample_rate = 0.0;  // Hz
};

std::string lowercase_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::vector<Recording> read_wav_recordings(const AnalyseOptions& options, double& full_scale) {
  const WavData wav = read_wav(options.file);
  full_scale = options.full_scale > 0.0 ? options.full_scale : wav.full_scale_pa.value_or(0.0);
  if (!(full_scale > 0.0)) {
    throw InputError(options.file, "--full-scale",
                     "the WAV does not say which pressure its full scale is: give --full-scale PA (the pressure in Pa of "
                     "sample value 1.0)");
  }
  std::vector<Recording> out;
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

std::vector<Recording> read_uff_recordings(const AnalyseOptions& options) {
  std::vector<int> skipped;
  const std::vector<Uff58Record> records = read_uff58(options.file, &skipped);
  std::vector<Recording> out;
  std::string others;
  for (const Uff58Record& r : records) {
    if (!r.is_time_record()) {
      others += (others.empty() ? "" : "; ") + describe_uff58(r);
      continue;
    }
    const std::string where = "dataset " + std::to_string(r.position) + " (line " + std::to_string(r.line) + ")";
    if (!is_pressure(r.numerator_axis)) {
      throw InputError(options.file, where,
                       "is a time record of " + r.numerator_axis.label + " in " + r.numerator_axis.units +
                           "; analyse computes sound pressure levels and needs pressure in Pa");
    }
    if (!r.even_spacing || !(r.abscissa_increment > 0.0)) {
      throw InputError(options.file, where, "time records must be evenly sampled");
    }
    if (r.ordinate.size() == 0) throw InputError(options.file, where, "is complex; a time record must be real");
    double fs = 1.0 / r.abscissa_increment;
    // Headers print the increment with six digits (1.52588e-05 s for 65536 Hz): take the
    // nearest whole rate in Hz when it is within that rounding.
    if (std::abs(fs - std::round(fs)) <= 1e-5 * fs) fs = std::round(fs);
    std::string name = r.response_entity.empty() ? "node" + std::to_string(r.response_node) : r.response_entity;
    name += ":" + std::to_string(r.response_direction);
    out.push_back({name, r.ordinate, fs});
  }
  if (out.empty()) {
    throw InputError(options.file, "",
                     records.empty() ? "holds no dataset 58 (function data)"
                                     : "holds no time record (dataset 58, function type 1); found: " + others);
  }
  return out;
}

}  // namespace

CLI::App* add_analyse_command(CLI::App& app, AnalyseOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "analyse",
      "Spectra and levels of a recording: third-octave band levels (IEC 61260-1 filters), A-weighting\n"
      "(IEC 61672-1), Leq, LAeq and LAFmax. Writes spectrum.csv, summary.json and spectrum.png.");
  cmd->add_option("file", options.file, "A WAV file (each channel a receiver ch1, ch2, ...) or a UFF file with "
                                        "dataset 58/58b time records of sound pressure in Pa")
      ->required();
  cmd->add_option("--full-scale", options.full_scale,
                  "Pressure in Pa of a WAV sample value of 1.0 (default: from the WAV's comment, as rollnoise writes it)")
      ->check(positive_number());
  cmd->add_option("--out", options.out, "Output folder (default out/<file name>); written atomically");
  cmd->footer("Example:\n  rollnoise analyse recording.wav --full-scale 20 --out out/recording");
  return cmd;
}

int run_analyse(const AnalyseOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const fs::path input(options.file);
  std::error_code ec;
  if (!fs::is_regular_file(input, ec)) throw InputError(options.file, "", "file not found (or not a regular file)");
  double full_scale = 0.0;
  const std::string ext = lowercase_extension(input);
  const std::vector<Recording> recordings =
      ext == ".uff" || ext == ".unv" ? read_uff_recordings(options) : read_wav_recordings(options, full_scale);

  const fs::path out = options.out.empty() ? fs::path("out") / input.stem() : fs::path(options.out);
  StagedOutputDirectory staged(out);
  std::vector<ReceiverSignal> signals;
  for (const Recording& r : recordings) signals.push_back({r.receiver, r.pressure, r.sample_rate});
  const nlohmann::json levels = write_sound_report(staged.staging(), signals, options.file);
  nlohmann::json summary;
  summary["input"] = options.file;
  if (full_scale > 0.0) summary["full_scale_pa"] = full_scale;
  summary["levels"] = levels;
  summary["rollnoise_version"] = ROLLNOISE_VERSION;
  summary["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_text_file(staged.staging() / "summary.json", summary.dump(2) + "\n");
  staged.commit();
  std::printf("rollnoise: wrote %s (spectrum.csv, summary.json, spectrum.png)\n", out.string().c_str());
  return 0;
}

}  // namespace rollnoise
